#include "track/statistics.hpp"

#include <gtest/gtest.h>
#include <GeographicLib/Geodesic.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "geo/geodesic.hpp"
#include "track/clean.hpp"
#include "track/track_builders.hpp"

namespace trailray::track {
namespace {

using test::kLat0;
using test::kLon0;
using test::north;
using test::one_segment;

Statistics stats(const Track& t, const StatisticsOptions& o = {}) { return track_statistics(t, compute_metrics(t), o); }

// No field NaN or infinite.
void expect_finite(const Statistics& s) {
  EXPECT_TRUE(std::isfinite(s.distance_2d_m));
  EXPECT_TRUE(std::isfinite(s.distance_3d_m));
  for (const auto& v :
       {s.duration_s, s.elapsed_s, s.moving_time_s, s.elevation_gain_m, s.elevation_loss_m, s.min_elevation_m,
        s.max_elevation_m, s.max_speed_kmh, s.avg_speed_kmh, s.max_climb_ms, s.max_sink_ms}) {
    if (v) {
      EXPECT_TRUE(std::isfinite(*v));
    }
  }
  if (s.bbox) {
    EXPECT_FALSE(s.bbox->empty());
    EXPECT_TRUE(std::isfinite(s.bbox->min_lat) && std::isfinite(s.bbox->max_lat) && std::isfinite(s.bbox->min_lon) &&
                std::isfinite(s.bbox->max_lon));
  }
}

TEST(Statistics, ConstantSpeedAlongAMeridian) {
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 10; ++i) pts.push_back(north(100.0 * i, 500.0, 1000.0 + 10.0 * i));
  const Statistics s = stats(one_segment(pts));
  expect_finite(s);
  EXPECT_EQ(s.points, 11u);
  EXPECT_EQ(s.segments, 1u);
  EXPECT_NEAR(s.distance_2d_m, 1000.0, 1e-6);
  EXPECT_NEAR(s.distance_3d_m, 1000.0, 1e-6);
  EXPECT_EQ(s.duration_s, 100.0);
  EXPECT_EQ(s.elapsed_s, 100.0);
  EXPECT_EQ(s.moving_time_s, 100.0);
  ASSERT_TRUE(s.avg_speed_kmh && s.max_speed_kmh);
  EXPECT_NEAR(*s.avg_speed_kmh, 36.0, 1e-6);
  EXPECT_NEAR(*s.max_speed_kmh, 36.0, 1e-6);
  EXPECT_EQ(s.elevation_gain_m, 0.0);
  EXPECT_EQ(s.elevation_loss_m, 0.0);
  EXPECT_EQ(s.min_elevation_m, 500.0);
  EXPECT_EQ(s.max_elevation_m, 500.0);
  ASSERT_TRUE(s.bbox);
  EXPECT_DOUBLE_EQ(s.bbox->min_lat, kLat0);
  EXPECT_DOUBLE_EQ(s.bbox->max_lat, pts.back().lat);
  EXPECT_DOUBLE_EQ(s.bbox->min_lon, kLon0);
}

TEST(Statistics, GapBetweenSegmentsIsNotMeasured) {
  Track t;
  Segment a, b, empty;
  for (int i = 0; i <= 5; ++i) a.points.push_back(north(100.0 * i, kMissing, 10.0 * i));
  for (int i = 0; i <= 5; ++i) b.points.push_back(north(20000.0 + 100.0 * i, kMissing, 3600.0 + 10.0 * i));
  t.segments = {a, empty, b};
  const Statistics s = stats(t);
  expect_finite(s);
  EXPECT_EQ(s.segments, 3u);  // the empty one counts
  EXPECT_EQ(s.points, 12u);
  EXPECT_NEAR(s.distance_2d_m, 1000.0, 1e-6);
  EXPECT_EQ(s.duration_s, 100.0);  // 50 + 50, not the hour between
  EXPECT_EQ(s.elapsed_s, 3650.0);
  EXPECT_EQ(s.moving_time_s, 100.0);
  EXPECT_NEAR(*s.avg_speed_kmh, 36.0, 1e-6);
}

TEST(Statistics, DurationUsesTheFirstAndLastTimedPointsOfEachSegment) {
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 6; ++i) pts.push_back(north(10.0 * i, kMissing, 100.0 + i));
  pts.front().time = kMissing;
  pts.back().time = kMissing;
  const Statistics s = stats(one_segment(pts));
  EXPECT_EQ(s.duration_s, 4.0);  // 101 .. 105
  EXPECT_EQ(s.elapsed_s, 4.0);
}

TEST(Statistics, DurationAbsentWithoutTwoTimedPointsInASegment) {
  Track t;
  t.segments.push_back(Segment{{north(0, kMissing, 10), north(100)}});
  t.segments.push_back(Segment{{north(200, kMissing, 20), north(300)}});
  const Statistics s = stats(t);
  expect_finite(s);
  EXPECT_FALSE(s.duration_s);
  EXPECT_FALSE(s.moving_time_s);
  EXPECT_FALSE(s.avg_speed_kmh);
  EXPECT_EQ(s.elapsed_s, 10.0);  // over the track: two timed points
  EXPECT_NEAR(s.distance_2d_m, 200.0, 1e-6);

  const Statistics untimed = stats(one_segment({north(0), north(100)}));
  EXPECT_FALSE(untimed.duration_s);
  EXPECT_FALSE(untimed.elapsed_s);
  EXPECT_FALSE(untimed.max_speed_kmh);
  EXPECT_FALSE(untimed.elevation_gain_m);
  EXPECT_FALSE(untimed.min_elevation_m);
  EXPECT_FALSE(untimed.max_climb_ms);
}

TEST(Statistics, RawTrackWithDuplicatesAndBackwardTimes) {
  // Raw statistics are compared with gpxpy: distance is every consecutive pair, duration is
  // last minus first timestamp of the segment, whatever happens in between.
  const std::vector<TrackPoint> pts{north(0, 100, 0),    north(100, 101, 10), north(100, 101, 10), north(150, 90, 10),
                                    north(200, 103, 20), north(250, 104, 15), north(240, 105, 30), north(300, 105, 30)};
  const Track t = one_segment(pts);
  const Statistics s = stats(t);
  expect_finite(s);
  EXPECT_NEAR(s.distance_2d_m, 320.0, 1e-6);
  EXPECT_EQ(s.duration_s, 30.0);
  ASSERT_TRUE(s.moving_time_s);
  EXPECT_GT(*s.moving_time_s, 0.0);
  EXPECT_LE(*s.moving_time_s, 30.0);  // a backward jump does not count the same seconds twice
  ASSERT_TRUE(s.max_speed_kmh);

  // And cleaning removes the offenders.
  CleanReport r;
  const Track cleaned = clean_track(t, CleanOptions{}, r);
  EXPECT_EQ(r.duplicate_points, 1u);     // (100, t=10) twice
  EXPECT_EQ(r.spread_time, 2u);          // 150 m and 300 m share their second with the point before
  EXPECT_EQ(r.non_increasing_time, 1u);  // t=15 after t=20
  expect_finite(stats(cleaned));
}

TEST(Statistics, BackwardTimeJumpCountsNoSecondTwice) {
  // 10 m/s throughout; the clock jumps back 5 s at point 3.
  const Track t = one_segment({north(0, kMissing, 0), north(100, kMissing, 10), north(200, kMissing, 20),
                               north(250, kMissing, 15), north(400, kMissing, 30)});
  const Statistics s = stats(t);
  expect_finite(s);
  EXPECT_EQ(s.duration_s, 30.0);
  EXPECT_EQ(s.moving_time_s, 30.0);
}

TEST(Statistics, EmptyTrackHasNoValues) {
  const Track t;
  const Statistics s = stats(t);
  EXPECT_EQ(s.points, 0u);
  EXPECT_EQ(s.segments, 0u);
  EXPECT_EQ(s.distance_2d_m, 0.0);
  EXPECT_EQ(s.distance_3d_m, 0.0);
  for (const auto& v :
       {s.duration_s, s.elapsed_s, s.moving_time_s, s.elevation_gain_m, s.elevation_loss_m, s.min_elevation_m,
        s.max_elevation_m, s.max_speed_kmh, s.avg_speed_kmh, s.max_climb_ms, s.max_sink_ms})
    EXPECT_FALSE(v);
  EXPECT_FALSE(s.bbox);

  Track only_empty;
  only_empty.segments.resize(2);
  EXPECT_EQ(stats(only_empty).segments, 2u);
  EXPECT_FALSE(stats(only_empty).bbox);
}

TEST(Statistics, OnePoint) {
  const Statistics s = stats(one_segment({north(0, 1234.5, 77)}));
  expect_finite(s);
  EXPECT_EQ(s.points, 1u);
  EXPECT_EQ(s.distance_2d_m, 0.0);
  EXPECT_FALSE(s.duration_s);
  EXPECT_FALSE(s.elapsed_s);
  EXPECT_FALSE(s.elevation_gain_m);
  EXPECT_EQ(s.min_elevation_m, 1234.5);
  EXPECT_EQ(s.max_elevation_m, 1234.5);
  EXPECT_FALSE(s.max_speed_kmh);
  ASSERT_TRUE(s.bbox);
  EXPECT_EQ(s.bbox->min_lat, s.bbox->max_lat);
}

TEST(Statistics, TwoIdenticalPoints) {
  const Track t = one_segment({north(0, 100, 50), north(0, 100, 50)});
  const Statistics s = stats(t);
  expect_finite(s);
  EXPECT_EQ(s.distance_2d_m, 0.0);
  EXPECT_EQ(s.distance_3d_m, 0.0);
  EXPECT_EQ(s.duration_s, 0.0);
  EXPECT_EQ(s.elapsed_s, 0.0);
  EXPECT_EQ(s.moving_time_s, 0.0);
  EXPECT_FALSE(s.avg_speed_kmh);  // no division by a zero moving time
  EXPECT_FALSE(s.max_speed_kmh);
  EXPECT_EQ(s.elevation_gain_m, 0.0);
  // Cleaned, the same.
  CleanReport r;
  const Track c = clean_track(t, CleanOptions{}, r);
  expect_finite(stats(c));
}

TEST(Statistics, ElevationNoiseBelowTheThresholdIsNoClimb) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> noise(-2.0, 2.0);  // peak to peak < 5 m
  std::vector<TrackPoint> pts;
  for (int i = 0; i < 500; ++i) pts.push_back(north(10.0 * i, 800.0 + noise(rng), double(i)));
  const Statistics s = stats(one_segment(pts));
  EXPECT_EQ(s.elevation_gain_m, 0.0);
  EXPECT_EQ(s.elevation_loss_m, 0.0);

  StatisticsOptions zero;
  zero.elevation_threshold_m = 0.0;  // without hysteresis every wiggle counts
  EXPECT_GT(*stats(one_segment(pts), zero).elevation_gain_m, 100.0);
}

TEST(Statistics, A100MetreClimbWithNoiseCountsAbout100) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> noise(-1.5, 1.5);
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 200; ++i) pts.push_back(north(10.0 * i, 1000.0 + 0.5 * i + noise(rng), double(i)));
  const Statistics s = stats(one_segment(pts));
  ASSERT_TRUE(s.elevation_gain_m);
  EXPECT_NEAR(*s.elevation_gain_m, 100.0, 3.0);
  EXPECT_EQ(s.elevation_loss_m, 0.0);
}

TEST(Statistics, ElevationHysteresisTurningPoints) {
  EXPECT_EQ(elevation_gain_loss({0, 4, 0, 4, 0}, 5).gain_m, 0.0);
  const GainLoss up_down = elevation_gain_loss({0, 6, 0}, 5);
  EXPECT_EQ(up_down.gain_m, 6.0);
  EXPECT_EQ(up_down.loss_m, 6.0);
  const GainLoss hill = elevation_gain_loss({100, 103, 150, 200, 197, 199, 120, 50, 53}, 5);
  EXPECT_EQ(hill.gain_m, 100.0);
  EXPECT_EQ(hill.loss_m, 150.0);
  // A drift down less than the threshold then up: counted from the low point.
  EXPECT_EQ(elevation_gain_loss({10, 7, 16}, 5).gain_m, 9.0);
  // Missing elevations are skipped.
  EXPECT_EQ(elevation_gain_loss({0, kMissing, 10}, 5).gain_m, 10.0);
  EXPECT_EQ(elevation_gain_loss({}, 5).gain_m, 0.0);
}

TEST(Statistics, ClimbAndDescentPerSegmentAndMaximumRates) {
  Track t;
  Segment up, down;
  // Climb 1 m/s for 100 s, then (another segment) sink 2 m/s for 50 s.
  for (int i = 0; i <= 10; ++i) up.points.push_back(north(100.0 * i, 1000.0 + 10.0 * i, 10.0 * i));
  for (int i = 0; i <= 5; ++i) down.points.push_back(north(1000.0 + 100.0 * i, 1100.0 - 20.0 * i, 200.0 + 10.0 * i));
  t.segments = {up, down};
  const Statistics s = stats(t);
  expect_finite(s);
  EXPECT_NEAR(*s.elevation_gain_m, 100.0, 1e-9);
  EXPECT_NEAR(*s.elevation_loss_m, 100.0, 1e-9);
  EXPECT_NEAR(*s.max_climb_ms, 1.0, 1e-9);
  EXPECT_NEAR(*s.max_sink_ms, 2.0, 1e-9);
  EXPECT_EQ(s.min_elevation_m, 1000.0);
  EXPECT_EQ(s.max_elevation_m, 1100.0);
  EXPECT_NEAR(s.distance_3d_m, 10 * std::hypot(100.0, 10.0) + 5 * std::hypot(100.0, 20.0), 1e-6);

  const Statistics only_up = segment_statistics(up, compute_metrics(t).segments[0]);
  EXPECT_EQ(only_up.segments, 1u);
  EXPECT_EQ(only_up.max_sink_ms, 0.0);  // it never descends
  EXPECT_EQ(only_up.elevation_loss_m, 0.0);
  EXPECT_EQ(only_up.duration_s, 100.0);
}

TEST(Statistics, MovingTimeExcludesAStopAndAPause) {
  // 1 Hz: 60 s at 5 m/s, 120 s standing still, 60 s at 5 m/s, then no points for 10 minutes
  // (a pause) and 60 s more at 5 m/s.
  std::vector<TrackPoint> pts;
  double s = 0, t = 0;
  for (int i = 0; i < 60; ++i, t += 1) pts.push_back(north(s += 5.0, kMissing, t));
  for (int i = 0; i < 120; ++i, t += 1) pts.push_back(north(s, kMissing, t));
  for (int i = 0; i < 60; ++i, t += 1) pts.push_back(north(s += 5.0, kMissing, t));
  t += 600;
  for (int i = 0; i < 60; ++i, t += 1) pts.push_back(north(s += 5.0, kMissing, t));
  const Statistics st = stats(one_segment(pts));
  expect_finite(st);
  ASSERT_TRUE(st.moving_time_s);
  // 178 s of motion; the windowed speed blurs each edge of the stop by a few seconds.
  EXPECT_GE(*st.moving_time_s, 178.0);
  EXPECT_LE(*st.moving_time_s, 195.0);
  EXPECT_EQ(st.duration_s, 899.0);  // t = 0 .. 899, the pause included: duration is not moving time
  EXPECT_NEAR(st.distance_2d_m, 895.0, 1e-6);
  ASSERT_TRUE(st.avg_speed_kmh);
  // The 5 m step across the 10-minute pause is not moving distance.
  EXPECT_NEAR(*st.avg_speed_kmh, (st.distance_2d_m - 5.0) / *st.moving_time_s * 3.6, 1e-6);
  EXPECT_GT(*st.avg_speed_kmh, 16.0);
  EXPECT_NEAR(*st.max_speed_kmh, 18.0, 1e-6);
}

TEST(Statistics, ASparseLoggerStillMoves) {
  // A fix every 20 minutes at 30 km/h (10 km apart), then a 3-hour stop in one place.
  std::vector<TrackPoint> pts;
  for (int i = 0; i < 10; ++i) pts.push_back(north(10000.0 * i, kMissing, 1200.0 * i));
  pts.push_back(north(90000.0 + 2.0, kMissing, 1200.0 * 9 + 3 * 3600.0));
  const Statistics st = stats(one_segment(pts));
  ASSERT_TRUE(st.moving_time_s);
  EXPECT_NEAR(*st.moving_time_s, 9 * 1200.0, 1e-6);
  ASSERT_TRUE(st.avg_speed_kmh);
  EXPECT_NEAR(*st.avg_speed_kmh, 30.0, 1e-6);
}

TEST(Statistics, SegmentStatisticsMatchATrackOfOneSegment) {
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 30; ++i) pts.push_back(north(37.0 * i, 700.0 + 3.0 * std::sin(i), 5.0 * i));
  const Track t = one_segment(pts);
  const TrackMetrics m = compute_metrics(t);
  const Statistics a = track_statistics(t, m);
  const Statistics b = segment_statistics(t.segments[0], m.segments[0]);
  EXPECT_EQ(a.distance_2d_m, b.distance_2d_m);
  EXPECT_EQ(a.duration_s, b.duration_s);
  EXPECT_EQ(a.moving_time_s, b.moving_time_s);
  EXPECT_EQ(a.elevation_gain_m, b.elevation_gain_m);
  EXPECT_EQ(a.max_speed_kmh, b.max_speed_kmh);
}

TEST(Statistics, MismatchedMetricsAreRecomputed) {
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 10; ++i) pts.push_back(north(100.0 * i, 500.0 + i, 10.0 * i));
  const Track t = one_segment(pts);
  const Statistics good = stats(t);
  const Statistics from_nothing = track_statistics(t, TrackMetrics{});
  EXPECT_DOUBLE_EQ(from_nothing.distance_2d_m, good.distance_2d_m);
  EXPECT_EQ(from_nothing.max_speed_kmh, good.max_speed_kmh);
  EXPECT_EQ(from_nothing.moving_time_s, good.moving_time_s);
}

TEST(Statistics, DistanceIsTheSumOfGeodesicSteps) {
  // A zig-zag over half a degree, compared with pairwise geodesics computed here.
  std::vector<TrackPoint> pts;
  double expected = 0;
  for (int i = 0; i <= 50; ++i) {
    TrackPoint p;
    p.lat = 46.0 + 0.01 * i;
    p.lon = 7.0 + (i % 2 ? 0.013 : 0.0);
    if (!pts.empty()) expected += geo::geodesic_distance_m(pts.back().lat, pts.back().lon, p.lat, p.lon);
    pts.push_back(p);
  }
  EXPECT_NEAR(stats(one_segment(pts)).distance_2d_m, expected, 1e-6);
}

}  // namespace
}  // namespace trailray::track
