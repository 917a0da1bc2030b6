// How FIT messages map onto the track model: sessions, laps, timer pauses, courses and course
// points, file_id, device-relative timestamps.
#include <gtest/gtest.h>

#include <cmath>

#include "fit_test_support.hpp"

namespace trailray::test::fit {
namespace {

const std::vector<FieldSpec> kEventFields = {{253, 4, kUint32}, {0, 1, kEnum}, {1, 1, kEnum}};
const std::vector<FieldSpec> kSessionFields = {{253, 4, kUint32}, {2, 4, kUint32}, {5, 1, kEnum}};

void add_records(Writer& w, double t0, int n, double lat0) {
  for (int i = 0; i < n; ++i) {
    RecordValues r;
    r.time = t0 + i;
    r.lat = lat0 + 0.0001 * i;
    w.data(0, record(r));
  }
}

TEST(FitModel, LapsKeepOneSegmentTimerStopsSplitIt) {
  Writer w;
  w.define(0, kRecordMsg, kRecordFields);
  w.define(1, kEventMsg, kEventFields);
  w.define(2, kLapMsg, {{253, 4, kUint32}, {2, 4, kUint32}});
  add_records(w, kT0, 3, 46.5);
  w.data(2, {std::uint64_t{fit_time(kT0 + 2)}, std::uint64_t{fit_time(kT0)}});  // lap button
  add_records(w, kT0 + 3, 3, 46.5003);
  w.data(1, {std::uint64_t{fit_time(kT0 + 6)}, 0, 4});    // timer stop_all
  w.data(1, {std::uint64_t{fit_time(kT0 + 600)}, 0, 0});  // timer start
  add_records(w, kT0 + 600, 2, 46.6);
  w.data(2, {std::uint64_t{fit_time(kT0 + 601)}, std::uint64_t{fit_time(kT0 + 3)}});
  auto r = read_fit_bytes(w.file());
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.tracks.size(), 1u);
  const auto& segs = r.file.tracks[0].segments;
  ASSERT_EQ(segs.size(), 2u);
  EXPECT_EQ(segs[0].points.size(), 6u);  // across the lap boundary
  EXPECT_EQ(segs[1].points.size(), 2u);
  EXPECT_DOUBLE_EQ(segs[1].points[0].time, kT0 + 600);
  EXPECT_EQ(metadata_field(r.file, "laps"), "2");
}

TEST(FitModel, EachSessionIsATrackWithItsSport) {
  Writer w;
  w.define(0, kRecordMsg, kRecordFields);
  w.define(3, kSessionMsg, kSessionFields);
  add_records(w, kT0, 4, 46.5);                                                           // swim (say)
  add_records(w, kT0 + 100, 5, 46.6);                                                     // bike
  w.data(3, {std::uint64_t{fit_time(kT0 + 99)}, std::uint64_t{fit_time(kT0 + 100)}, 2});  // cycling
  w.data(3, {std::uint64_t{fit_time(kT0 + 4)}, std::uint64_t{fit_time(kT0)}, 5});         // swimming
  auto r = read_fit_bytes(w.file());
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.tracks.size(), 2u);
  EXPECT_EQ(r.file.tracks[0].type, "swimming");
  EXPECT_EQ(r.file.tracks[0].point_count(), 4u);
  EXPECT_EQ(r.file.tracks[1].type, "cycling");
  EXPECT_EQ(r.file.tracks[1].point_count(), 5u);
  EXPECT_EQ(r.file.metadata.activity_type, "cycling");  // the first session message
}

TEST(FitModel, FileIdGoesIntoTheMetadata) {
  Writer w;
  w.define(1, kFileIdMsg,
           {{0, 1, kEnum}, {1, 2, kUint16}, {2, 2, kUint16}, {3, 4, kUint32z}, {4, 4, kUint32}, {8, 12, kString}});
  w.data(1, {4, 1, 2697, 3900000001u, std::uint64_t{fit_time(kT0 - 5)}, "Edge 530"});
  w.define(0, kRecordMsg, kRecordFields);
  add_records(w, kT0, 2, 46.5);
  auto r = read_fit_bytes(w.file());
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.file.metadata.creator, "Edge 530");
  EXPECT_DOUBLE_EQ(r.file.metadata.time, kT0 - 5);
  EXPECT_EQ(metadata_field(r.file, "file_type"), "activity");
  EXPECT_EQ(metadata_field(r.file, "manufacturer"), "garmin");
  EXPECT_EQ(metadata_field(r.file, "product"), "2697");
  EXPECT_EQ(metadata_field(r.file, "serial_number"), "3900000001");
}

TEST(FitModel, CoursePointsBecomeWaypoints) {
  Writer w;
  w.define(0, kCourseMsg, {{5, 16, kString}, {4, 1, kEnum}});
  w.data(0, {"Col du Test", 2});
  w.define(1, kCoursePointMsg,
           {{254, 2, kUint16}, {1, 4, kUint32}, {2, 4, kSint32}, {3, 4, kSint32}, {5, 1, kEnum}, {6, 10, kString}});
  w.data(1, {0, std::uint64_t{fit_time(kT0 + 60)}, semicircles(45.1), semicircles(6.2), 1, "Summit"});
  w.data(1, {1, 0xFFFFFFFF, semicircles(45.2), semicircles(6.3), 6, "Turn"});
  w.data(1, {2, 0xFFFFFFFF, 0x7FFFFFFF, 0x7FFFFFFF, 6, "Nowhere"});  // no position: dropped
  w.define(2, kRecordMsg, kRecordFields);
  RecordValues r0;
  w.data(2, record(r0));
  auto r = read_fit_bytes(w.file());
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.waypoints.size(), 2u);
  EXPECT_EQ(r.file.waypoints[0].name, "Summit");
  EXPECT_EQ(r.file.waypoints[0].symbol, "summit");
  EXPECT_NEAR(r.file.waypoints[0].point.lat, 45.1, 1e-7);
  EXPECT_DOUBLE_EQ(r.file.waypoints[0].point.time, kT0 + 60);
  EXPECT_EQ(r.file.waypoints[1].name, "Turn");
  EXPECT_EQ(r.file.waypoints[1].symbol, "left");
  EXPECT_FALSE(r.file.waypoints[1].point.has_time());
  ASSERT_EQ(r.file.tracks.size(), 1u);
  EXPECT_EQ(r.file.tracks[0].name, "Col du Test");
  EXPECT_EQ(r.file.tracks[0].type, "cycling");
  ASSERT_EQ(r.warnings.size(), 1u);  // the course point without a position
}

TEST(FitModel, DeviceRelativeTimesUseTheTimestampCorrelation) {
  Writer w;
  w.define(0, kRecordMsg, kRecordFields);
  RecordValues r;
  r.time = 631065600.0 + 5000;  // FIT time 5000: seconds since power-on
  w.data(0, record(r));
  // at system time 4000 the UTC time was kT0
  w.define(1, kTimestampCorrelationMsg, {{253, 4, kUint32}, {1, 4, kUint32}});
  w.data(1, {std::uint64_t{fit_time(kT0)}, 4000});
  auto res = read_fit_bytes(w.file());
  ASSERT_TRUE(res.ok());
  EXPECT_TRUE(res.warnings.empty());
  ASSERT_EQ(all_points(res.file).size(), 1u);
  EXPECT_DOUBLE_EQ(all_points(res.file)[0].time, kT0 + 1000);

  // device_settings' utc_offset when there is no correlation
  Writer s;
  s.define(1, kDeviceSettingsMsg, {{1, 4, kUint32}});
  s.data(1, {std::uint64_t{fit_time(kT0)} - 4000});
  s.define(0, kRecordMsg, kRecordFields);
  s.data(0, record(r));
  auto res2 = read_fit_bytes(s.file());
  ASSERT_EQ(all_points(res2.file).size(), 1u);
  EXPECT_DOUBLE_EQ(all_points(res2.file)[0].time, kT0 + 1000);

  // neither: kept as read, with a warning that the times are not UTC
  Writer n;
  n.define(0, kRecordMsg, kRecordFields);
  n.data(0, record(r));
  auto res3 = read_fit_bytes(n.file());
  ASSERT_TRUE(res3.ok());
  ASSERT_EQ(res3.warnings.size(), 1u);
  EXPECT_NE(res3.warnings[0].message.find("not UTC"), std::string::npos);
  EXPECT_DOUBLE_EQ(all_points(res3.file)[0].time, 631065600.0 + 5000);
}

}  // namespace
}  // namespace trailray::test::fit
