// Damaged FIT files: cut at every offset, flipped bytes, broken CRCs, lost framing. Never a
// crash; the complete records before the damage stay; warnings and errors name the file and
// the byte offset.
#include <gtest/gtest.h>

#include "fit_test_support.hpp"

namespace trailray::test::fit {
namespace {

constexpr std::size_t kHeader = 14;

std::size_t record_size() {
  std::size_t n = 1;  // record header
  for (const FieldSpec& f : kRecordFields) n += f.size;
  return n;
}

bool mentions(const std::vector<track::Diagnostic>& ds, const std::string& text) {
  for (const auto& d : ds)
    if (d.message.find(text) != std::string::npos) return true;
  return false;
}

TEST(FitDamage, ACutFileKeepsEveryCompleteRecord) {
  const int n = 6;
  const std::string whole = simple_activity(n);
  const std::size_t definition = 6 + 3 * kRecordFields.size();
  for (std::size_t len = 0; len < whole.size(); ++len) {
    SCOPED_TRACE("cut at " + std::to_string(len));
    auto r = read_fit_bytes(whole.substr(0, len));
    if (len < kHeader) {
      ASSERT_FALSE(r.ok());  // not even a header
      continue;
    }
    ASSERT_TRUE(r.ok()) << r.error->to_string();
    const std::size_t body = len - kHeader;
    const std::size_t complete = body < definition ? 0 : std::min<std::size_t>(n, (body - definition) / record_size());
    EXPECT_EQ(all_points(r.file).size(), complete);
    ASSERT_FALSE(r.warnings.empty());
    EXPECT_TRUE(mentions(r.warnings, "cut")) << r.warnings.front().message;
    EXPECT_EQ(r.warnings.front().file, "test.fit");
    EXPECT_GE(r.warnings.front().position.byte_offset, 0);
    // --strict: the same cut is an error
    auto strict = read_fit_bytes(whole.substr(0, len), true);
    ASSERT_FALSE(strict.ok());
    EXPECT_NE(strict.error->message.find("(--strict)"), std::string::npos);
  }
}

TEST(FitDamage, AFlippedFileCrcIsAWarningAndTheDataStays) {
  std::string bytes = simple_activity(4);
  bytes[bytes.size() - 1] = static_cast<char>(bytes[bytes.size() - 1] ^ 0x5A);
  auto r = read_fit_bytes(bytes);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(all_points(r.file).size(), 4u);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].message.find("CRC"), std::string::npos);
  EXPECT_EQ(r.warnings[0].position.byte_offset, static_cast<std::int64_t>(bytes.size() - 2));
  EXPECT_FALSE(read_fit_bytes(bytes, true).ok());

  // a flipped data byte (the 2nd record's heart rate): read as written, the CRC tells
  std::string data_flip = simple_activity(4);
  const std::size_t hr = kHeader + 6 + 3 * kRecordFields.size() + record_size() + 1 + 4 + 4 + 4 + 2;
  data_flip[hr] = static_cast<char>(50);
  auto d = read_fit_bytes(data_flip);
  ASSERT_TRUE(d.ok());
  ASSERT_EQ(all_points(d.file).size(), 4u);
  EXPECT_EQ(all_points(d.file)[1].heart_rate, 50.0f);
  EXPECT_TRUE(mentions(d.warnings, "CRC"));
}

TEST(FitDamage, AFlippedHeaderCrcIsAWarning) {
  std::string bytes = simple_activity(2);
  bytes[12] = static_cast<char>(bytes[12] ^ 1);
  auto r = read_fit_bytes(bytes);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(all_points(r.file).size(), 2u);
  EXPECT_TRUE(mentions(r.warnings, "header CRC"));
  // a header CRC of 0 means "not computed": no warning
  bytes[12] = bytes[13] = 0;
  EXPECT_FALSE(mentions(read_fit_bytes(bytes).warnings, "header CRC"));
}

TEST(FitDamage, ADataMessageWithoutDefinitionEndsTheFile) {
  Writer w;
  w.define(0, kRecordMsg, kRecordFields);
  w.data(0, record(RecordValues{}));
  const std::size_t bad = kHeader + w.size();
  w.raw(std::string(1, '\x05'));  // local type 5: never defined
  w.data(0, record(RecordValues{}));
  auto r = read_fit_bytes(w.file());
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(all_points(r.file).size(), 1u);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_EQ(r.warnings.front().position.byte_offset, static_cast<std::int64_t>(bad));
  EXPECT_TRUE(mentions(r.warnings, "no definition"));
}

TEST(FitDamage, AnArchitectureByteOtherThanZeroOrOneEndsTheFile) {
  Writer w;
  w.define(0, kRecordMsg, kRecordFields);
  w.data(0, record(RecordValues{}));
  const std::size_t bad = kHeader + w.size();
  w.define(1, kRecordMsg, kRecordFields, {}, 0xE5);
  w.data(1, record(RecordValues{}));
  auto r = read_fit_bytes(w.file());
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(all_points(r.file).size(), 1u);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].position.byte_offset, static_cast<std::int64_t>(bad + 2));
  EXPECT_NE(r.warnings[0].message.find("0xE5"), std::string::npos);
  EXPECT_NE(r.warnings[0].to_string().find("test.fit: byte "), std::string::npos);
}

TEST(FitDamage, AMessagePastTheAnnouncedDataSizeEndsThatFileOnly) {
  // The first file's header announces fewer bytes than its messages take: the message that
  // straddles the end is dropped, and the chained file after it is still read.
  Writer w;
  w.define(0, kRecordMsg, kRecordFields);
  w.data(0, record(RecordValues{}));
  w.data(0, record(RecordValues{}));
  std::string first = w.file();
  const std::uint32_t shorter = static_cast<std::uint32_t>(w.size() - 5);
  for (int i = 0; i < 4; ++i) first[4 + i] = static_cast<char>((shorter >> (8 * i)) & 0xFF);
  first[12] = first[13] = 0;  // header CRC: not computed
  // re-frame: data shorter by 5, then a CRC, then the next file
  std::string reframed = first.substr(0, kHeader + shorter);
  reframed += std::string(2, '\0');
  auto r = read_fit_bytes(reframed + simple_activity(3));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(all_points(r.file).size(), 1u + 3u);
  EXPECT_TRUE(mentions(r.warnings, "runs past the end of the FIT data"));
}

TEST(FitDamage, AnUnfinishedFileWithoutDataSizeIsReadToTheEnd) {
  std::string bytes = simple_activity(5);
  bytes.resize(bytes.size() - 2 - 10);  // no CRC, the last record cut
  for (int i = 4; i < 8; ++i) bytes[static_cast<std::size_t>(i)] = 0;
  bytes[12] = bytes[13] = 0;
  auto r = read_fit_bytes(bytes);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(all_points(r.file).size(), 4u);
  EXPECT_TRUE(mentions(r.warnings, "no data size"));
  EXPECT_TRUE(mentions(r.warnings, "cut"));
}

TEST(FitDamage, RandomByteFlipsNeverBreakTheContract) {
  const std::string whole = simple_activity(8);
  std::uint32_t seed = 12345;
  for (int round = 0; round < 3000; ++round) {
    std::string bytes = whole;
    for (int k = 0; k < 3; ++k) {
      seed = seed * 1103515245u + 12345u;
      const std::size_t at = (seed >> 8) % bytes.size();
      bytes[at] = static_cast<char>(seed >> 24);
    }
    auto r = read_fit_bytes(bytes);
    if (!r.ok()) {
      EXPECT_FALSE(r.error->message.empty());
      continue;
    }
    for (const auto& p : all_points(r.file)) ASSERT_TRUE(track::valid_coordinates(p.lat, p.lon));
  }
}

}  // namespace
}  // namespace trailray::test::fit
