// Cleaning carries the IGC pressure and GNSS altitudes: kept points keep theirs through the
// minimum distance, and smoothing averages each like the elevation, over the neighbours that have
// one. Every test runs for both channels (the parameter), with the other channel absent.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include "track/clean.hpp"

namespace trailray::track {
namespace {

using Channel = float TrackPoint::*;

class CleanIgcAltitude : public ::testing::TestWithParam<Channel> {
 protected:
  Channel f = GetParam();
  static bool has(const TrackPoint& p, Channel c) { return !std::isnan(p.*c); }
};

// n points 10 m apart heading north-east, one per second, with an altitude that climbs and
// wobbles (so smoothing changes it).
// The channel under test is 90 m below the elevation; the other one is absent.
std::vector<TrackPoint> flight(std::size_t n, Channel channel, unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 3.0);
  std::vector<TrackPoint> pts(n);
  for (std::size_t i = 0; i < n; ++i) {
    TrackPoint& p = pts[i];
    p.lat = 46.6 + 0.00006 * static_cast<double>(i);
    p.lon = 7.8 + 0.00009 * static_cast<double>(i);
    p.time = 1.7e9 + static_cast<double>(i);
    p.ele = std::round(800.0 + 0.5 * static_cast<double>(i) + noise(rng));
    p.*channel = static_cast<float>(p.ele - 90.0);
  }
  return pts;
}

Segment clean(std::vector<TrackPoint> pts, const CleanOptions& o) {
  CleanReport report;
  return clean_segment(Segment{std::move(pts)}, o, report);
}

// The smoothed channel plus 90 m is the smoothed elevation: the same kernel, over the
// same points (up to float rounding of the stored value). Short segments use the truncated
// kernels of the ends only; long ones cross the smoother's blocks of 1024 points.
TEST_P(CleanIgcAltitude, SmoothedLikeTheElevation) {
  for (std::size_t n : {5u, 12u, 3000u}) {
    SCOPED_TRACE(n);
    CleanOptions o;
    o.min_distance_m = 0.0;
    const auto raw = flight(n, f);
    const Segment s = clean(raw, o);
    ASSERT_EQ(s.points.size(), n);
    std::size_t changed = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const TrackPoint& p = s.points[i];
      ASSERT_TRUE(has(p, f));
      EXPECT_NEAR(static_cast<double>(p.*f), p.ele - 90.0, 1e-4 * std::abs(p.ele)) << i;
      EXPECT_FALSE(
          has(p, f == &TrackPoint::gnss_altitude ? &TrackPoint::pressure_altitude : &TrackPoint::gnss_altitude));
      if (std::abs(static_cast<double>(p.*f) - static_cast<double>(raw[i].*f)) > 0.01) ++changed;
    }
    EXPECT_GT(changed, n / 2);  // it was smoothed, not carried
    // The ends stay where they are, as elevations do.
    EXPECT_EQ(s.points.front().*f, raw.front().*f);
    EXPECT_EQ(s.points.back().*f, raw.back().*f);
  }
}

TEST_P(CleanIgcAltitude, AveragesOnlyOverNeighboursThatHaveOne) {
  // 1000 m on even points, none on odd ones: the even points stay at 1000 m (any
  // average of 1000s), the odd ones stay without; the elevation is unaffected.
  for (std::size_t n : {9u, 2500u}) {
    SCOPED_TRACE(n);
    auto pts = flight(n, f);
    for (std::size_t i = 0; i < n; ++i) pts[i].*f = i % 2 == 0 ? 1000.0f : kMissingF;
    CleanOptions o;
    o.min_distance_m = 0.0;
    const Segment s = clean(pts, o);
    ASSERT_EQ(s.points.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      if (i % 2 == 0) {
        EXPECT_FLOAT_EQ(s.points[i].*f, 1000.0f) << i;
      } else {
        EXPECT_FALSE(has(s.points[i], f)) << i;
      }
      EXPECT_TRUE(s.points[i].has_ele());
    }
  }
}

TEST_P(CleanIgcAltitude, AStepIsSmoothedAcross) {
  auto pts = flight(41, f);
  for (std::size_t i = 0; i < pts.size(); ++i) pts[i].*f = i < 20 ? 1000.0f : 1100.0f;
  CleanOptions o;
  o.min_distance_m = 0.0;
  const Segment s = clean(pts, o);
  ASSERT_EQ(s.points.size(), 41u);
  EXPECT_FLOAT_EQ(s.points[10].*f, 1000.0f);
  EXPECT_GT(s.points[19].*f, 1000.0f);
  EXPECT_LT(s.points[20].*f, 1100.0f);
  EXPECT_LT(s.points[19].*f, s.points[20].*f);
  EXPECT_FLOAT_EQ(s.points[30].*f, 1100.0f);
}

TEST_P(CleanIgcAltitude, TracksWithoutItStayWithout) {
  auto pts = flight(2000, f);
  for (TrackPoint& p : pts) p.*f = kMissingF;
  const Segment s = clean(pts, CleanOptions{});
  ASSERT_FALSE(s.points.empty());
  for (const TrackPoint& p : s.points) EXPECT_FALSE(p.has_pressure_altitude() || p.has_gnss_altitude());
}

TEST_P(CleanIgcAltitude, KeptPointsKeepTheirsThroughTheMinimumDistanceAndTheOrderSteps) {
  // Each point repeated 1 m further on (dropped by a 3 m minimum distance) and one exact
  // duplicate (dropped): the kept points carry their own altitude and heart rate.
  std::vector<TrackPoint> pts;
  for (std::size_t i = 0; i < 20; ++i) {
    TrackPoint p;
    p.lat = 46.6 + 0.0001 * static_cast<double>(i);  // about 11 m apart
    p.lon = 7.8;
    p.time = 1.7e9 + 2.0 * static_cast<double>(i);
    p.ele = 800.0 + static_cast<double>(i);
    p.*f = 700.0f + static_cast<float>(i);
    p.heart_rate = 100.0f + static_cast<float>(i);
    pts.push_back(p);
    if (i == 5) pts.push_back(p);  // exact duplicate
    if (i + 1 < 20) {
      TrackPoint q = p;
      q.lat += 0.000009;  // 1 m on
      q.time += 1.0;
      q.*f = -1.0f;  // would show if carried onto a kept point
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
    EXPECT_EQ(s.points[i].*f, 700.0f + static_cast<float>(i));
    EXPECT_EQ(s.points[i].heart_rate, 100.0f + static_cast<float>(i));
  }
}

INSTANTIATE_TEST_SUITE_P(Channels, CleanIgcAltitude,
                         ::testing::Values(&TrackPoint::pressure_altitude, &TrackPoint::gnss_altitude),
                         [](const ::testing::TestParamInfo<Channel>& param) {
                           return std::string(param.param == &TrackPoint::gnss_altitude ? "Gnss" : "Pressure");
                         });

// Both channels at once, as an IGC flight has them: each is smoothed over its own neighbours (GNSS
// holes do not move the pressure altitude, and the pressure channel does not change the GNSS one).
TEST(CleanIgcAltitudes, BothChannelsAreSmoothedEachOnItsOwn) {
  for (std::size_t n : {12u, 3000u}) {
    SCOPED_TRACE(n);
    auto pts = flight(n, &TrackPoint::pressure_altitude);
    for (std::size_t i = 0; i < n; ++i) {
      pts[i].gnss_altitude = static_cast<float>(pts[i].ele);
      if (i % 3 == 1) pts[i].gnss_altitude = kMissingF;  // no 3D fix
    }
    auto gnss_only = pts;
    for (TrackPoint& p : gnss_only) p.pressure_altitude = kMissingF;
    CleanOptions o;
    o.min_distance_m = 0.0;
    const Segment s = clean(pts, o);
    const Segment g = clean(gnss_only, o);
    ASSERT_EQ(s.points.size(), n);
    ASSERT_EQ(g.points.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      const TrackPoint& p = s.points[i];
      ASSERT_TRUE(p.has_pressure_altitude());
      EXPECT_NEAR(static_cast<double>(p.pressure_altitude), p.ele - 90.0, 1e-4 * std::abs(p.ele)) << i;
      EXPECT_EQ(p.has_gnss_altitude(), i % 3 != 1) << i;
      // The pressure channel beside it changes nothing in the GNSS one.
      if (p.has_gnss_altitude()) {
        EXPECT_EQ(p.gnss_altitude, g.points[i].gnss_altitude) << i;
      }
      EXPECT_EQ(p.has_gnss_altitude(), g.points[i].has_gnss_altitude()) << i;
    }
  }
}

}  // namespace
}  // namespace trailray::track
