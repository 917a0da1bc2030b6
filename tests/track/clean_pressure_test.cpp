// Cleaning carries the IGC pressure altitude: kept points keep theirs through the minimum
// distance, and smoothing averages it like the elevation, over the neighbours that have one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "track/clean.hpp"

namespace trailray::track {
namespace {

// n points 10 m apart heading north-east, one per second, with an altitude that climbs and
// wobbles (so smoothing changes it).
std::vector<TrackPoint> flight(std::size_t n, unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 3.0);
  std::vector<TrackPoint> pts(n);
  for (std::size_t i = 0; i < n; ++i) {
    TrackPoint& p = pts[i];
    p.lat = 46.6 + 0.00006 * static_cast<double>(i);
    p.lon = 7.8 + 0.00009 * static_cast<double>(i);
    p.time = 1.7e9 + static_cast<double>(i);
    p.ele = std::round(800.0 + 0.5 * static_cast<double>(i) + noise(rng));
    p.pressure_altitude = static_cast<float>(p.ele - 90.0);
  }
  return pts;
}

Segment clean(std::vector<TrackPoint> pts, const CleanOptions& o) {
  CleanReport report;
  return clean_segment(Segment{std::move(pts)}, o, report);
}

// Smoothed pressure altitude minus 90 m is the smoothed elevation: the same kernel, over the
// same points (up to float rounding of the stored value). Short segments use the truncated
// kernels of the ends only; long ones cross the smoother's blocks of 1024 points.
TEST(CleanPressure, SmoothedLikeTheElevation) {
  for (std::size_t n : {5u, 12u, 3000u}) {
    SCOPED_TRACE(n);
    CleanOptions o;
    o.min_distance_m = 0.0;
    const auto raw = flight(n);
    const Segment s = clean(raw, o);
    ASSERT_EQ(s.points.size(), n);
    std::size_t changed = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const TrackPoint& p = s.points[i];
      ASSERT_TRUE(p.has_pressure_altitude());
      EXPECT_NEAR(static_cast<double>(p.pressure_altitude), p.ele - 90.0, 1e-4 * std::abs(p.ele)) << i;
      if (std::abs(static_cast<double>(p.pressure_altitude) - static_cast<double>(raw[i].pressure_altitude)) > 0.01)
        ++changed;
    }
    EXPECT_GT(changed, n / 2);  // it was smoothed, not carried
    // The ends stay where they are, as elevations do.
    EXPECT_EQ(s.points.front().pressure_altitude, raw.front().pressure_altitude);
    EXPECT_EQ(s.points.back().pressure_altitude, raw.back().pressure_altitude);
  }
}

TEST(CleanPressure, AveragesOnlyOverNeighboursThatHaveOne) {
  // Pressure 1000 m on even points, none on odd ones: the even points stay at 1000 m (any
  // average of 1000s), the odd ones stay without; the elevation is unaffected.
  for (std::size_t n : {9u, 2500u}) {
    SCOPED_TRACE(n);
    auto pts = flight(n);
    for (std::size_t i = 0; i < n; ++i) pts[i].pressure_altitude = i % 2 == 0 ? 1000.0f : kMissingF;
    CleanOptions o;
    o.min_distance_m = 0.0;
    const Segment s = clean(pts, o);
    ASSERT_EQ(s.points.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      if (i % 2 == 0) {
        EXPECT_FLOAT_EQ(s.points[i].pressure_altitude, 1000.0f) << i;
      } else {
        EXPECT_FALSE(s.points[i].has_pressure_altitude()) << i;
      }
      EXPECT_TRUE(s.points[i].has_ele());
    }
  }
}

TEST(CleanPressure, AStepIsSmoothedAcross) {
  auto pts = flight(41);
  for (std::size_t i = 0; i < pts.size(); ++i) pts[i].pressure_altitude = i < 20 ? 1000.0f : 1100.0f;
  CleanOptions o;
  o.min_distance_m = 0.0;
  const Segment s = clean(pts, o);
  ASSERT_EQ(s.points.size(), 41u);
  EXPECT_FLOAT_EQ(s.points[10].pressure_altitude, 1000.0f);
  EXPECT_GT(s.points[19].pressure_altitude, 1000.0f);
  EXPECT_LT(s.points[20].pressure_altitude, 1100.0f);
  EXPECT_LT(s.points[19].pressure_altitude, s.points[20].pressure_altitude);
  EXPECT_FLOAT_EQ(s.points[30].pressure_altitude, 1100.0f);
}

TEST(CleanPressure, TracksWithoutItStayWithout) {
  auto pts = flight(2000);
  for (TrackPoint& p : pts) p.pressure_altitude = kMissingF;
  const Segment s = clean(pts, CleanOptions{});
  ASSERT_FALSE(s.points.empty());
  for (const TrackPoint& p : s.points) EXPECT_FALSE(p.has_pressure_altitude());
}

TEST(CleanPressure, KeptPointsKeepTheirsThroughTheMinimumDistanceAndTheOrderSteps) {
  // Each point repeated 1 m further on (dropped by a 3 m minimum distance) and one exact
  // duplicate (dropped): the kept points carry their own pressure altitude and heart rate.
  std::vector<TrackPoint> pts;
  for (std::size_t i = 0; i < 20; ++i) {
    TrackPoint p;
    p.lat = 46.6 + 0.0001 * static_cast<double>(i);  // about 11 m apart
    p.lon = 7.8;
    p.time = 1.7e9 + 2.0 * static_cast<double>(i);
    p.ele = 800.0 + static_cast<double>(i);
    p.pressure_altitude = 700.0f + static_cast<float>(i);
    p.heart_rate = 100.0f + static_cast<float>(i);
    pts.push_back(p);
    if (i == 5) pts.push_back(p);  // exact duplicate
    if (i + 1 < 20) {
      TrackPoint q = p;
      q.lat += 0.000009;  // 1 m on
      q.time += 1.0;
      q.pressure_altitude = -1.0f;  // would show if carried onto a kept point
      pts.push_back(q);
    }
  }
  CleanOptions o;
  o.smooth = false;
  o.min_distance_m = 3.0;
  CleanReport report;
  const Segment s = clean_segment(Segment{pts}, o, report);
  ASSERT_EQ(s.points.size(), 20u);
  EXPECT_EQ(report.too_close, 19u);
  EXPECT_EQ(report.duplicate_points, 1u);
  for (std::size_t i = 0; i < 20; ++i) {
    EXPECT_EQ(s.points[i].pressure_altitude, 700.0f + static_cast<float>(i));
    EXPECT_EQ(s.points[i].heart_rate, 100.0f + static_cast<float>(i));
  }
}

}  // namespace
}  // namespace trailray::track
