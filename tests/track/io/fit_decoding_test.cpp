// FIT decoding on synthetic files (fit_test_writer.hpp): byte orders, headers, compressed
// timestamps, developer fields, invalid values, field sizes, chained files.
#include <gtest/gtest.h>

#include <cmath>

#include "fit_test_support.hpp"
#include "track/io/fit_decoder.hpp"

namespace trailray::test::fit {
namespace {

TEST(FitDecoding, RecordFieldsAreScaledIntoThePoint) {
  auto r = read_fit_bytes(simple_activity(3));
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front().to_string();
  EXPECT_EQ(r.file.format, track::Format::Fit);
  auto pts = all_points(r.file);
  ASSERT_EQ(pts.size(), 3u);
  const auto& p = pts[2];
  EXPECT_NEAR(p.lat, 46.5002, 1e-7);
  EXPECT_NEAR(p.lon, 7.5, 1e-7);
  EXPECT_DOUBLE_EQ(p.ele, 1000.0);
  EXPECT_DOUBLE_EQ(p.time, kT0 + 2);
  EXPECT_EQ(p.heart_rate, 102.0f);
  EXPECT_EQ(p.cadence, 80.0f);
  EXPECT_FLOAT_EQ(p.speed, 3.5f);
  EXPECT_EQ(p.power, 200.0f);
  EXPECT_EQ(p.temperature, -5.0f);
}

TEST(FitDecoding, BothByteOrdersAndHeaderSizesReadTheSame) {
  auto little = read_fit_bytes(simple_activity(5, false, true));
  auto big = read_fit_bytes(simple_activity(5, true, false));
  ASSERT_TRUE(little.ok() && big.ok());
  EXPECT_TRUE(big.warnings.empty());
  auto a = all_points(little.file), b = all_points(big.file);
  ASSERT_EQ(a.size(), 5u);
  ASSERT_EQ(b.size(), 5u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].lat, b[i].lat);
    EXPECT_EQ(a[i].lon, b[i].lon);
    EXPECT_EQ(a[i].ele, b[i].ele);
    EXPECT_EQ(a[i].time, b[i].time);
    EXPECT_EQ(a[i].heart_rate, b[i].heart_rate);
    EXPECT_EQ(a[i].temperature, b[i].temperature);
  }
  // Negative coordinates survive both orders (sign extension).
  Writer w;
  w.define(0, kRecordMsg, kRecordFields, {}, 1);
  RecordValues south;
  south.lat = -33.9;
  south.lon = -70.6;
  w.data(0, record(south));
  auto pts = all_points(read_fit_bytes(w.file()).file);
  ASSERT_EQ(pts.size(), 1u);
  EXPECT_NEAR(pts[0].lat, -33.9, 1e-7);
  EXPECT_NEAR(pts[0].lon, -70.6, 1e-7);
}

TEST(FitDecoding, CompressedTimestampsFollowTheLastFullOne) {
  Writer w;
  w.define(0, kRecordMsg, kRecordFields);
  // position and altitude only, for the compressed-header messages (local types 0-3)
  w.define(1, kRecordMsg, {{0, 4, kSint32}, {1, 4, kSint32}, {2, 2, kUint16}});
  RecordValues r;
  r.time = kT0;  // its low five bits decide where the offsets roll over
  w.data(0, record(r));
  const std::uint32_t base = fit_time(kT0);
  const std::uint32_t low = base & 0x1F;
  const std::vector<std::uint32_t> offsets = {(low + 3) & 0x1F, (low + 20) & 0x1F, (low + 40) & 0x1F};
  for (std::uint32_t off : offsets)
    w.compressed(1, static_cast<std::uint8_t>(off), {semicircles(46.6), semicircles(7.6), 7500});
  auto res = read_fit_bytes(w.file());
  ASSERT_TRUE(res.ok());
  auto pts = all_points(res.file);
  ASSERT_EQ(pts.size(), 4u);
  EXPECT_DOUBLE_EQ(pts[1].time, kT0 + 3);
  EXPECT_DOUBLE_EQ(pts[2].time, kT0 + 20);
  EXPECT_DOUBLE_EQ(pts[3].time, kT0 + 40);
  EXPECT_DOUBLE_EQ(pts[3].ele, 1000.0);

  track::WarningCollector warnings("x");
  track::fit::DecodeStats stats;
  (void)track::fit::decode(w.file(), warnings, stats, [](const track::fit::Message&) {});
  EXPECT_EQ(stats.compressed_headers, 3u);
}

TEST(FitDecoding, DeveloperFieldsAreSkippedAndCounted) {
  Writer w;
  // developer fields: 3 bytes and 5 bytes, between the record's own fields and the next message
  w.define(0, kRecordMsg, kRecordFields, {{0, 3, 0}, {1, 5, 0}});
  for (int i = 0; i < 4; ++i) {
    RecordValues r;
    r.time = kT0 + i;
    r.hr = 90 + i;
    w.data(0, record(r), std::string("\x40\x41\x42\x43\x44\x45\x46\x47", 8));
  }
  auto res = read_fit_bytes(w.file());
  ASSERT_TRUE(res.ok());
  EXPECT_TRUE(res.warnings.empty());
  auto pts = all_points(res.file);
  ASSERT_EQ(pts.size(), 4u);
  EXPECT_EQ(pts[3].heart_rate, 93.0f);
  EXPECT_DOUBLE_EQ(pts[3].time, kT0 + 3);
  EXPECT_EQ(metadata_field(res.file, "developer_fields_skipped"), "8");
}

TEST(FitDecoding, InvalidValuesAreAbsent) {
  Writer w;
  w.define(0, kRecordMsg, kRecordFields);
  // every optional field at its base type's invalid value
  w.data(0,
         {std::uint64_t{fit_time(kT0)}, semicircles(46.5), semicircles(7.5), 0xFFFF, 0xFF, 0xFF, 0xFFFF, 0xFFFF, 0x7F});
  // no position at all: the record is dropped and counted
  w.data(0, {std::uint64_t{fit_time(kT0 + 1)}, 0x7FFFFFFF, 0x7FFFFFFF, 7500, 130, 0xFF, 0xFFFF, 0xFFFF, 0x7F});
  // only one coordinate: dropped too
  w.data(0, {std::uint64_t{fit_time(kT0 + 2)}, semicircles(46.5), 0x7FFFFFFF, 7500, 130, 0xFF, 0xFFFF, 0xFFFF, 0x7F});
  // no timestamp: kept without a time
  w.data(0, {0xFFFFFFFF, semicircles(46.6), semicircles(7.6), 7500, 0xFF, 0xFF, 0xFFFF, 0xFFFF, 0x7F});
  auto res = read_fit_bytes(w.file());
  ASSERT_TRUE(res.ok());
  auto pts = all_points(res.file);
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_FALSE(pts[0].has_ele());
  EXPECT_TRUE(std::isnan(pts[0].heart_rate));
  EXPECT_TRUE(std::isnan(pts[0].cadence));
  EXPECT_TRUE(std::isnan(pts[0].speed));
  EXPECT_TRUE(std::isnan(pts[0].power));
  EXPECT_TRUE(std::isnan(pts[0].temperature));
  EXPECT_TRUE(pts[0].has_time());
  EXPECT_FALSE(pts[1].has_time());
  EXPECT_DOUBLE_EQ(pts[1].ele, 1000.0);
  EXPECT_EQ(metadata_field(res.file, "records_without_position"), "2");
}

TEST(FitDecoding, EnhancedAltitudeAndSpeedWinOverTheShortOnes) {
  Writer w;
  w.define(0, kRecordMsg,
           {{253, 4, kUint32},
            {0, 4, kSint32},
            {1, 4, kSint32},
            {2, 2, kUint16},
            {78, 4, kUint32},
            {6, 2, kUint16},
            {73, 4, kUint32}});
  // altitude 100 m in the short field, 9000 m in the enhanced one (beyond uint16's 12,607 m
  // would be the usual reason); speed 1 m/s short, 70 m/s enhanced.
  w.data(0, {std::uint64_t{fit_time(kT0)}, semicircles(1), semicircles(2), 3000, (9000 + 500) * 5, 1000, 70000});
  // enhanced fields invalid: the short ones count
  w.data(0, {std::uint64_t{fit_time(kT0 + 1)}, semicircles(1), semicircles(2), 3000, 0xFFFFFFFF, 1000, 0xFFFFFFFF});
  auto pts = all_points(read_fit_bytes(w.file()).file);
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_DOUBLE_EQ(pts[0].ele, 9000.0);
  EXPECT_FLOAT_EQ(pts[0].speed, 70.0f);
  EXPECT_DOUBLE_EQ(pts[1].ele, 100.0);
  EXPECT_FLOAT_EQ(pts[1].speed, 1.0f);
}

TEST(FitDecoding, FieldSizesThatDoNotFitTheirTypeAreSkippedNotMisread) {
  Writer w;
  // heart rate declared uint16 in 3 bytes, temperature sint32 in 1 byte, an unknown base type
  w.define(0, kRecordMsg,
           {{253, 4, kUint32}, {3, 3, kUint16}, {0, 4, kSint32}, {13, 1, kSint32}, {1, 4, kSint32}, {4, 2, 0x1F}});
  w.data(0, {std::uint64_t{fit_time(kT0)}, 0x010203, semicircles(10), 5, semicircles(20), 0x0101});
  auto res = read_fit_bytes(w.file());
  ASSERT_TRUE(res.ok());
  auto pts = all_points(res.file);
  ASSERT_EQ(pts.size(), 1u);
  EXPECT_NEAR(pts[0].lat, 10.0, 1e-7);  // the fields after the odd ones are read in place
  EXPECT_NEAR(pts[0].lon, 20.0, 1e-7);
  EXPECT_TRUE(std::isnan(pts[0].heart_rate));
  EXPECT_TRUE(std::isnan(pts[0].temperature));
  EXPECT_TRUE(std::isnan(pts[0].cadence));
  ASSERT_EQ(res.warnings.size(), 1u);
  EXPECT_NE(res.warnings[0].message.find("3 times"), std::string::npos) << res.warnings[0].message;
  EXPECT_GT(res.warnings[0].position.byte_offset, 14);
  EXPECT_FALSE(read_fit_bytes(w.file(), true).ok());  // --strict
}

TEST(FitDecoding, ArrayFieldsGiveTheirFirstElement) {
  Writer w;
  w.define(0, kRecordMsg, {{253, 4, kUint32}, {0, 4, kSint32}, {1, 4, kSint32}, {3, 2, kUint8}});
  w.data(0, {std::uint64_t{fit_time(kT0)}, semicircles(1), semicircles(2), std::string("\x8C\x01", 2)});
  auto pts = all_points(read_fit_bytes(w.file()).file);
  ASSERT_EQ(pts.size(), 1u);
  EXPECT_EQ(pts[0].heart_rate, 140.0f);
}

TEST(FitDecoding, ChainedFilesAreAllRead) {
  const std::string one = simple_activity(3), two = simple_activity(4, true);
  auto res = read_fit_bytes(one + two);
  ASSERT_TRUE(res.ok());
  EXPECT_TRUE(res.warnings.empty()) << res.warnings.front().to_string();
  ASSERT_EQ(res.file.tracks.size(), 1u);
  // separate recordings: a segment each
  ASSERT_EQ(res.file.tracks[0].segments.size(), 2u);
  EXPECT_EQ(res.file.tracks[0].segments[0].points.size(), 3u);
  EXPECT_EQ(res.file.tracks[0].segments[1].points.size(), 4u);
  EXPECT_EQ(metadata_field(res.file, "chained_fit_files"), "2");
  // bytes after the chain that are no FIT header: a warning naming their offset
  auto tail = read_fit_bytes(one + two + "junk at the end");
  ASSERT_TRUE(tail.ok());
  ASSERT_EQ(tail.warnings.size(), 1u);
  EXPECT_EQ(tail.warnings[0].position.byte_offset, static_cast<std::int64_t>(one.size() + two.size()));
  EXPECT_EQ(all_points(tail.file).size(), 7u);
}

TEST(FitDecoding, NotAFitFileIsAnErrorAtByteZero) {
  auto r = read_fit_bytes("<gpx></gpx> and more text");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->file, "test.fit");
  EXPECT_EQ(r.error->position.byte_offset, 0);
  EXPECT_NE(r.error->to_string().find("test.fit: byte 0:"), std::string::npos) << r.error->to_string();
  EXPECT_FALSE(read_fit_bytes("").ok());
}

TEST(FitDecoding, CrcMatchesTheProtocolCheckValue) {
  // CRC-16/ARC of "123456789" is 0xBB3D.
  EXPECT_EQ(track::fit::crc16("123456789"), 0xBB3D);
}

}  // namespace
}  // namespace trailray::test::fit
