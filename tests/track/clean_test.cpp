#include "track/clean.hpp"

#include <gtest/gtest.h>
#include <GeographicLib/Geodesic.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "geo/geodesic.hpp"
#include "geo/local_frame.hpp"

namespace trailray::track {
namespace {

constexpr double kLat0 = 46.5;
constexpr double kLon0 = 7.5;

// A point `s` metres from (kLat0, kLon0) along azimuth `azimuth_deg` (0 = north).
TrackPoint along(double s, double azimuth_deg = 0.0, double ele = kMissing, double time = kMissing) {
  TrackPoint p;
  GeographicLib::Geodesic::WGS84().Direct(kLat0, kLon0, azimuth_deg, s, p.lat, p.lon);
  p.ele = ele;
  p.time = time;
  return p;
}

double dist(const TrackPoint& a, const TrackPoint& b) { return geo::geodesic_distance_m(a.lat, a.lon, b.lat, b.lon); }

Track one_segment(std::vector<TrackPoint> pts) {
  Track t;
  t.segments.push_back(Segment{std::move(pts)});
  return t;
}

CleanOptions no_smoothing(double min_distance_m = 0.0) {
  CleanOptions o;
  o.min_distance_m = min_distance_m;
  o.smooth = false;
  return o;
}

TEST(Clean, DropsInvalidCoordinatesAndCountsThem) {
  std::vector<TrackPoint> pts{along(0), along(10), along(20), along(30)};
  TrackPoint nan_lat = along(15);
  nan_lat.lat = std::nan("");
  TrackPoint lat_91 = along(16);
  lat_91.lat = 91.0;
  TrackPoint lon_200 = along(17);
  lon_200.lon = 200.0;
  pts.insert(pts.begin() + 2, {nan_lat, lat_91, lon_200});

  CleanReport r;
  const Track out = clean_track(one_segment(pts), no_smoothing(), r);
  EXPECT_EQ(r.invalid_coordinates, 3u);
  EXPECT_EQ(r.total_dropped(), 3u);
  ASSERT_EQ(out.segments[0].points.size(), 4u);
  for (const auto& p : out.segments[0].points) EXPECT_TRUE(std::isfinite(p.lat) && std::abs(p.lat) <= 90);
}

TEST(Clean, SpreadsSameSecondRunsDropsBackwardTimestampsKeepsUntimedPoints) {
  // times: 0, 10, 10 (same second, another place), 5 (backward), 20, none, 20 (not after the
  // last kept 20), 30
  const std::vector<double> times{0, 10, 10, 5, 20, kMissing, 20, 30};
  std::vector<TrackPoint> pts;
  for (std::size_t i = 0; i < times.size(); ++i) pts.push_back(along(10.0 * double(i), 0, kMissing, times[i]));

  CleanReport r;
  const Track out = clean_track(one_segment(pts), no_smoothing(), r);
  EXPECT_EQ(r.non_increasing_time, 2u);
  EXPECT_EQ(r.spread_time, 1u);
  EXPECT_EQ(r.duplicate_points, 0u);
  EXPECT_EQ(r.invalid_coordinates, 0u);
  EXPECT_EQ(r.too_close, 0u);
  const auto& kept = out.segments[0].points;
  ASSERT_EQ(kept.size(), 6u);
  EXPECT_EQ(kept[0].time, 0);
  EXPECT_EQ(kept[1].time, 10);
  EXPECT_EQ(kept[2].time, 10.5);  // the next timestamp goes backward: spread over 1 s
  EXPECT_EQ(kept[3].time, 20);
  EXPECT_TRUE(std::isnan(kept[4].time));
  EXPECT_EQ(kept[5].time, 30);
  // The kept points are the original ones, in order.
  EXPECT_EQ(kept[2].lat, pts[2].lat);
  EXPECT_EQ(kept[3].lat, pts[4].lat);
}

TEST(Clean, TenHertzLoggerWithWholeSecondStampsKeepsItsGeometry) {
  // 10 fixes per second, 1 m apart, stamped with the whole second (a SkyTraq logger), plus
  // exact repeats of some fixes (XCTrack writes those).
  std::vector<TrackPoint> pts;
  for (int i = 0; i < 30; ++i) {
    pts.push_back(along(1.0 * i, 0, kMissing, 100.0 + i / 10));
    if (i % 7 == 0) pts.push_back(pts.back());
  }
  CleanOptions o = no_smoothing();
  o.min_distance_m = 0.0;
  CleanReport r;
  const auto kept = clean_track(one_segment(pts), o, r).segments[0].points;
  EXPECT_EQ(r.duplicate_points, 5u);
  EXPECT_EQ(r.non_increasing_time, 0u);
  EXPECT_EQ(r.spread_time, 27u);  // 9 in each of the 3 seconds
  ASSERT_EQ(kept.size(), 30u);
  for (std::size_t i = 0; i < kept.size(); ++i) EXPECT_NEAR(kept[i].time, 100.0 + 0.1 * double(i), 1e-9) << i;
}

TEST(Clean, AStuckClockRunLosesItsTimesNotItsPlaces) {
  // 51 fixes 30 m apart all stamped t=100 (igclib's no_time_increment.igc), then the clock runs.
  std::vector<TrackPoint> pts{along(0, 0, kMissing, 99)};
  for (int i = 0; i < 51; ++i) pts.push_back(along(30.0 * (i + 1), 0, kMissing, 100));
  pts.push_back(along(30.0 * 53, 0, kMissing, 160));
  CleanReport r;
  const auto kept = clean_track(one_segment(pts), no_smoothing(), r).segments[0].points;
  ASSERT_EQ(kept.size(), pts.size());
  EXPECT_EQ(r.frozen_time, 50u);
  EXPECT_EQ(r.spread_time, 0u);
  EXPECT_EQ(kept[1].time, 100.0);
  for (std::size_t i = 2; i + 1 < kept.size(); ++i) EXPECT_FALSE(kept[i].has_time()) << i;
  EXPECT_EQ(kept.back().time, 160.0);
}

TEST(Clean, AFrozenClockLosesItsTimesNotItsPoints) {
  // Every point stamped 1901-12-13T20:45:52.207Z give or take 0.3 ms (seen in the wild).
  std::vector<TrackPoint> pts;
  for (int i = 0; i < 50; ++i) pts.push_back(along(10.0 * i, 0, 1000, -2147483647.793 + (i % 2 ? 0.0003 : 0.0)));
  CleanReport r;
  const Track out = clean_track(one_segment(pts), no_smoothing(), r);
  EXPECT_EQ(r.frozen_time, 50u);
  EXPECT_EQ(r.non_increasing_time, 0u);
  ASSERT_EQ(out.segments[0].points.size(), 50u);
  for (const auto& p : out.segments[0].points) EXPECT_FALSE(p.has_time());

  // A real 10 Hz recording is not frozen; two equal stamps at two places are a same-second run.
  std::vector<TrackPoint> fast;
  for (int i = 0; i < 5; ++i) fast.push_back(along(1.0 * i, 0, kMissing, 0.1 * i));
  CleanReport r2;
  EXPECT_EQ(clean_track(one_segment(fast), no_smoothing(), r2).segments[0].points.size(), 5u);
  EXPECT_EQ(r2.frozen_time, 0u);
  CleanReport r3;
  clean_track(one_segment({along(0, 0, kMissing, 5), along(10, 0, kMissing, 5)}), no_smoothing(), r3);
  EXPECT_EQ(r3.frozen_time, 0u);
  EXPECT_EQ(r3.non_increasing_time, 0u);
  EXPECT_EQ(r3.spread_time, 1u);
}

TEST(Clean, TimeOrderIsCheckedPerSegmentNotAcrossTheGap) {
  Track t;
  t.segments.push_back(Segment{{along(0, 0, kMissing, 100), along(10, 0, kMissing, 110)}});
  t.segments.push_back(Segment{{along(20, 0, kMissing, 50), along(30, 0, kMissing, 60)}});
  CleanReport r;
  const Track out = clean_track(t, no_smoothing(), r);
  EXPECT_EQ(r.non_increasing_time, 0u);
  EXPECT_EQ(out.segments[1].points.size(), 2u);
}

TEST(Clean, MinimumDistanceDropsRepeatedPositions) {
  // A A A B B C (B 10 m, C 20 m from A), and a final D 30 m.
  const std::vector<TrackPoint> pts{along(0), along(0), along(1), along(10), along(10), along(20), along(30)};
  CleanReport r;
  const Track out = clean_track(one_segment(pts), no_smoothing(3.0), r);
  EXPECT_EQ(r.too_close, 3u);
  const auto& kept = out.segments[0].points;
  ASSERT_EQ(kept.size(), 4u);
  for (std::size_t i = 1; i < kept.size(); ++i) EXPECT_GE(dist(kept[i - 1], kept[i]), 3.0);
  EXPECT_NEAR(dist(kept[0], kept[3]), 30.0, 1e-6);
}

TEST(Clean, LastPointReplacesThePreviousKeptPointWhenTooClose) {
  const std::vector<TrackPoint> pts{along(0, 0, 1), along(10, 0, 2), along(11, 0, 3)};
  CleanReport r;
  const Track out = clean_track(one_segment(pts), no_smoothing(3.0), r);
  EXPECT_EQ(r.too_close, 1u);
  const auto& kept = out.segments[0].points;
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0].ele, 1);
  EXPECT_EQ(kept[1].ele, 3);  // the segment's last point survives
}

TEST(Clean, LastPointTooCloseToTheFirstKeepsBoth) {
  const std::vector<TrackPoint> pts{along(0, 0, 1), along(1, 0, 2), along(2, 0, 3)};
  CleanReport r;
  const Track out = clean_track(one_segment(pts), no_smoothing(3.0), r);
  EXPECT_EQ(r.too_close, 1u);  // the middle one
  const auto& kept = out.segments[0].points;
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0].ele, 1);
  EXPECT_EQ(kept[1].ele, 3);
}

TEST(Clean, MinimumDistanceCountsElevationSoAVerticalClimbSurvives) {
  // A drone going straight up 2 m per fix, 1 m sideways: 2.2 m in 3D, kept at 2 m minimum...
  std::vector<TrackPoint> pts;
  for (int i = 0; i < 10; ++i) pts.push_back(along(1.0 * i, 0, 100.0 + 2.0 * i, double(i)));
  CleanReport r;
  EXPECT_EQ(clean_track(one_segment(pts), no_smoothing(2.0), r).segments[0].points.size(), 10u);
  EXPECT_EQ(r.too_close, 0u);
  // ...while without elevations the same positions are 1 m apart and thinned.
  for (auto& p : pts) p.ele = kMissing;
  CleanReport r2;
  EXPECT_LT(clean_track(one_segment(pts), no_smoothing(2.0), r2).segments[0].points.size(), 6u);
  EXPECT_GT(r2.too_close, 4u);
}

TEST(Clean, MinimumDistanceZeroDisables) {
  const std::vector<TrackPoint> pts{along(0), along(0), along(0.5), along(1)};
  CleanReport r;
  const Track out = clean_track(one_segment(pts), no_smoothing(0.0), r);
  EXPECT_EQ(r.too_close, 0u);
  EXPECT_EQ(out.segments[0].points.size(), 4u);
}

TEST(Clean, MinimumDistanceIsNotMeasuredAcrossSegments) {
  Track t;
  t.segments.push_back(Segment{{along(0), along(50)}});
  t.segments.push_back(Segment{{along(50), along(100)}});  // starts where the first ended
  CleanReport r;
  const Track out = clean_track(t, no_smoothing(3.0), r);
  EXPECT_EQ(r.too_close, 0u);
  EXPECT_EQ(out.segments[1].points.size(), 2u);
}

TEST(Clean, EmptyAndTinySegmentsStayValid) {
  Track t;
  t.name = "n";
  t.segments.push_back(Segment{});
  t.segments.push_back(Segment{{along(0, 0, 500, 0)}});
  t.segments.push_back(Segment{{along(0, 0, 500, 0), along(0, 0, 500, 1)}});  // identical positions
  CleanReport r;
  const Track out = clean_track(t, CleanOptions{}, r);
  EXPECT_EQ(out.name, "n");
  ASSERT_EQ(out.segments.size(), 3u);
  EXPECT_TRUE(out.segments[0].points.empty());
  ASSERT_EQ(out.segments[1].points.size(), 1u);
  ASSERT_EQ(out.segments[2].points.size(), 2u);
  EXPECT_EQ(out.segments[1].points[0].lat, t.segments[1].points[0].lat);
  for (const auto& s : out.segments)
    for (const auto& p : s.points) {
      EXPECT_TRUE(std::isfinite(p.lat) && std::isfinite(p.lon) && std::isfinite(p.ele) && std::isfinite(p.time));
    }
  EXPECT_EQ(r.total_dropped(), 0u);
}

TEST(Clean, SmoothingKeepsAStraightLineStraightAndItsEndpoints) {
  // 41 points north-east, 10 m apart, climbing 1 m per point.
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 40; ++i) pts.push_back(along(10.0 * i, 45.0, 1000.0 + i, 1000.0 + i));
  CleanReport r;
  const Track out = clean_track(one_segment(pts), CleanOptions{}, r);
  const auto& s = out.segments[0].points;
  ASSERT_EQ(s.size(), pts.size());
  EXPECT_EQ(s.front().lat, pts.front().lat);
  EXPECT_EQ(s.front().lon, pts.front().lon);
  EXPECT_EQ(s.front().ele, pts.front().ele);
  EXPECT_EQ(s.back().lat, pts.back().lat);
  EXPECT_EQ(s.back().lon, pts.back().lon);
  EXPECT_EQ(s.back().ele, pts.back().ele);
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_LT(dist(s[i], pts[i]), 0.01) << i;  // not pulled along or off the line
    EXPECT_NEAR(s[i].ele, pts[i].ele, 1e-9) << i;
    EXPECT_EQ(s[i].time, pts[i].time);
  }
}

TEST(Clean, SmoothingReducesJitter) {
  // A line due north with deterministic sideways and vertical noise of sigma 3 m.
  std::mt19937 rng(42);
  std::normal_distribution<double> noise(0.0, 3.0);
  std::vector<TrackPoint> pts;
  std::vector<double> true_ele;
  for (int i = 0; i < 400; ++i) {
    TrackPoint p = along(5.0 * i);
    double lat = 0, lon = 0;
    GeographicLib::Geodesic::WGS84().Direct(p.lat, p.lon, 90.0, noise(rng), lat, lon);
    p.lat = lat;
    p.lon = lon;
    true_ele.push_back(1000.0 + 0.1 * i);
    p.ele = true_ele.back() + noise(rng);
    pts.push_back(p);
  }
  const geo::LocalFrame frame(kLat0, kLon0);
  auto variances = [&](const std::vector<TrackPoint>& v) {
    double east = 0, up = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      east += std::pow(frame.to_local(v[i].lat, v[i].lon, 0).east, 2);
      up += std::pow(v[i].ele - true_ele[i], 2);
    }
    return std::pair{east / double(v.size()), up / double(v.size())};
  };
  CleanOptions o;
  o.min_distance_m = 0.0;
  CleanReport r;
  const Track out = clean_track(one_segment(pts), o, r);
  const auto [east_before, up_before] = variances(pts);
  const auto [east_after, up_after] = variances(out.segments[0].points);
  EXPECT_GT(east_before, 5.0);
  EXPECT_LT(east_after, 0.5 * east_before);
  EXPECT_LT(up_after, 0.5 * up_before);
}

TEST(Clean, ElevationIsSmoothedOnlyOverPointsThatHaveOne) {
  std::vector<TrackPoint> pts;
  for (int i = 0; i < 20; ++i) pts.push_back(along(10.0 * i, 0, i % 3 == 1 ? kMissing : 500.0));
  CleanReport r;
  const Track out = clean_track(one_segment(pts), CleanOptions{}, r);
  const auto& s = out.segments[0].points;
  ASSERT_EQ(s.size(), pts.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (i % 3 == 1) {
      EXPECT_FALSE(s[i].has_ele()) << i;
    } else {
      EXPECT_DOUBLE_EQ(s[i].ele, 500.0) << i;  // missing neighbours are not zeros
    }
  }
}

TEST(Clean, SmoothingDoesNotCrossSegmentBoundaries) {
  Track t;
  Segment low, high;
  for (int i = 0; i < 10; ++i) low.points.push_back(along(10.0 * i, 0, 0.0));
  for (int i = 10; i < 20; ++i) high.points.push_back(along(10.0 * i, 0, 1000.0));
  t.segments = {low, high};
  CleanReport r;
  const Track out = clean_track(t, CleanOptions{}, r);
  for (const auto& p : out.segments[0].points) EXPECT_DOUBLE_EQ(p.ele, 0.0);
  for (const auto& p : out.segments[1].points) EXPECT_DOUBLE_EQ(p.ele, 1000.0);
}

TEST(Clean, SmoothingDoesNotCrossAPause) {
  // 10 points every 10 s, then signal lost for 10 minutes and 5 km further on, 10 more points.
  std::vector<TrackPoint> pts;
  for (int i = 0; i < 10; ++i) pts.push_back(along(10.0 * i, 0, 100.0, 10.0 * i));
  for (int i = 0; i < 10; ++i) pts.push_back(along(5000.0 + 10.0 * i, 0, 600.0, 700.0 + 10.0 * i));
  CleanOptions o;
  o.min_distance_m = 0.0;
  CleanReport r;
  const Track kept = clean_track(one_segment(pts), o, r);
  const auto& s = kept.segments[0].points;
  ASSERT_EQ(s.size(), pts.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_LT(dist(s[i], pts[i]), 0.01) << i;
    EXPECT_NEAR(s[i].ele, pts[i].ele, 1e-9) << i;
  }
  // With the limit off, the two stretches are averaged into each other.
  o.max_gap_s = 0.0;
  const Track blurred_track = clean_track(one_segment(pts), o, r);
  const auto& blurred = blurred_track.segments[0].points;
  EXPECT_GT(dist(blurred[9], pts[9]), 100.0);
  EXPECT_GT(blurred[9].ele, 150.0);
}

TEST(Clean, SmoothingMovesACornerInward) {
  // An L-shaped path: the corner point is pulled toward the inside, the ends stay.
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 10; ++i) pts.push_back(along(10.0 * i, 0.0));
  const TrackPoint corner = pts.back();
  for (int i = 1; i <= 10; ++i) {
    TrackPoint p;
    GeographicLib::Geodesic::WGS84().Direct(corner.lat, corner.lon, 90.0, 10.0 * i, p.lat, p.lon);
    pts.push_back(p);
  }
  CleanOptions o;
  o.min_distance_m = 0.0;
  CleanReport r;
  const Track out = clean_track(one_segment(pts), o, r);
  const auto& s = out.segments[0].points;
  ASSERT_EQ(s.size(), pts.size());
  EXPECT_GT(dist(s[10], corner), 2.0);
  EXPECT_LT(s[10].lat, corner.lat);
  EXPECT_GT(s[10].lon, corner.lon);
  EXPECT_EQ(s.front().lat, pts.front().lat);
  EXPECT_EQ(s.back().lon, pts.back().lon);
}

TEST(Clean, NonFiniteElevationOrTimeBecomesMissing) {
  TrackPoint p = along(10, 0, std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity());
  CleanReport r;
  const Track out = clean_track(one_segment({along(0, 0, 1, 0), p, along(20, 0, 3, 2)}), no_smoothing(), r);
  EXPECT_EQ(r.invalid_values, 1u);
  EXPECT_EQ(r.total_dropped(), 0u);
  ASSERT_EQ(out.segments[0].points.size(), 3u);
  EXPECT_FALSE(out.segments[0].points[1].has_ele());
  EXPECT_FALSE(out.segments[0].points[1].has_time());
}

TEST(Clean, ReportAddsUp) {
  std::vector<TrackPoint> pts{along(0, 0, kMissing, 0), along(0, 0, kMissing, 0), along(1, 0, kMissing, 1),
                              along(50, 0, kMissing, 2)};
  TrackPoint bad = along(60);
  bad.lon = std::nan("");
  pts.push_back(bad);
  pts.push_back(along(100, 0, kMissing, 3));
  CleanReport r;
  const Track out = clean_track(one_segment(pts), CleanOptions{}, r);
  EXPECT_EQ(r.invalid_coordinates, 1u);
  EXPECT_EQ(r.duplicate_points, 1u);
  EXPECT_EQ(r.non_increasing_time, 0u);
  EXPECT_EQ(r.too_close, 1u);
  EXPECT_EQ(r.total_dropped(), 3u);
  EXPECT_EQ(out.segments[0].points.size() + r.total_dropped(), pts.size());
}

// --- Smoothing and the minimum distance against straightforward reference implementations ------

// Smoothing as defined in clean.hpp, computed the slow, obvious way: for every point the
// exact weighted 3D (ECEF) mean of its window, projected back onto the ellipsoid; elevations
// summed over the window in order, skipping missing ones. Stretches split at pauses.
void reference_smooth(std::vector<TrackPoint>& pts, const CleanOptions& o) {
  auto smooth = [&](std::size_t first, std::size_t last) {
    const std::size_t n = last - first;
    if (n < 3) return;
    const std::size_t half = static_cast<std::size_t>(o.smooth_half_width);
    std::vector<glm::dvec3> ecef;
    std::vector<double> ele;
    for (std::size_t i = first; i < last; ++i) {
      ecef.push_back(geo::ecef_from_geodetic(pts[i].lat, pts[i].lon, 0.0));
      ele.push_back(pts[i].ele);
    }
    for (std::size_t i = 1; i + 1 < n; ++i) {
      const std::size_t k = std::min({half, i, n - 1 - i});
      glm::dvec3 sum{};
      double wsum = 0.0, ele_sum = 0.0, ele_wsum = 0.0;
      for (std::size_t j = i - k; j <= i + k; ++j) {
        const double d = static_cast<double>(j > i ? j - i : i - j);
        const double w = std::exp(-d * d / (2.0 * o.smooth_sigma * o.smooth_sigma));
        sum.x += w * ecef[j].x;
        sum.y += w * ecef[j].y;
        sum.z += w * ecef[j].z;
        wsum += w;
        if (!std::isnan(ele[j])) {
          ele_sum += w * ele[j];
          ele_wsum += w;
        }
      }
      sum.x /= wsum;
      sum.y /= wsum;
      sum.z /= wsum;
      TrackPoint& p = pts[first + i];
      const geo::Geodetic g = geo::geodetic_from_ecef(sum);
      p.lat = g.lat_deg;
      p.lon = g.lon_deg;
      if (p.has_ele()) p.ele = ele_sum / ele_wsum;
    }
  };
  std::size_t start = 0;
  double last_time = kMissing;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!pts[i].has_time()) continue;
    if (!std::isnan(last_time) && pts[i].time - last_time > o.max_gap_s) {
      smooth(start, i);
      start = i;
    }
    last_time = pts[i].time;
  }
  smooth(start, pts.size());
}

// A random walk of n points from (lat, lon), steps of about step_m in a slowly turning
// direction, 1 s apart; a pause (2 minutes) every 1500 points; some points without an
// elevation or a time.
std::vector<TrackPoint> random_walk(std::size_t n, double lat, double lon, double step_m, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> turn(0.0, 20.0), jitter(0.0, 0.3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<TrackPoint> pts;
  double azimuth = 360.0 * u(rng), t = 0.0, ele = 500.0;
  for (std::size_t i = 0; i < n; ++i) {
    TrackPoint p;
    p.lat = lat;
    p.lon = lon;
    p.time = t;
    ele += 2.0 * jitter(rng);
    p.ele = ele;
    if (u(rng) < 0.02) p.ele = kMissing;
    if (u(rng) < 0.01 && i > 0) p.time = kMissing;
    pts.push_back(p);
    t += (i + 1) % 1500 == 0 ? 120.0 : 1.0;
    azimuth += turn(rng);
    double lat2 = 0.0, lon2 = 0.0;
    GeographicLib::Geodesic::WGS84().Direct(lat, lon, azimuth, step_m * (1.0 + jitter(rng)), lat2, lon2);
    lat = lat2;
    lon = lon2;
  }
  return pts;
}

void expect_smoothing_matches_reference(const std::vector<TrackPoint>& pts, const CleanOptions& o, const char* what) {
  CleanReport r;
  const Track out = clean_track(one_segment(pts), o, r);
  ASSERT_EQ(r.total_dropped(), 0u) << what;
  std::vector<TrackPoint> expected = pts;
  reference_smooth(expected, o);
  const auto& got = out.segments[0].points;
  ASSERT_EQ(got.size(), expected.size()) << what;
  double worst = 0.0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    ASSERT_TRUE(std::abs(got[i].lon) <= 180.0) << what << " " << i;
    worst = std::max(worst, dist(got[i], expected[i]));
    // Elevations: the same sums in the same order, bit for bit.
    if (expected[i].has_ele()) {
      ASSERT_EQ(got[i].ele, expected[i].ele) << what << " " << i;
    } else {
      ASSERT_FALSE(got[i].has_ele()) << what << " " << i;
    }
    ASSERT_TRUE(got[i].time == expected[i].time || (!got[i].has_time() && !expected[i].has_time())) << what << i;
  }
  EXPECT_LT(worst, 1e-4) << what;  // clean.hpp: within 0.1 mm of the exact 3D mean
}

TEST(Clean, SmoothingMatchesTheExact3DMean) {
  CleanOptions o;
  o.min_distance_m = 0.0;
  // Several blocks, pauses, missing elevations and times; a cyclist, a car, a sparse logger.
  expect_smoothing_matches_reference(random_walk(5000, 46.5, 7.5, 5.0, 1), o, "5 m steps");
  expect_smoothing_matches_reference(random_walk(3000, -33.9, 151.2, 30.0, 2), o, "30 m steps");
  expect_smoothing_matches_reference(random_walk(2000, 60.0, 10.0, 1500.0, 3), o, "1.5 km steps");
  // Across the antimeridian, and around a pole (the exact path).
  expect_smoothing_matches_reference(random_walk(3000, -16.5, 179.99, 20.0, 4), o, "antimeridian");
  expect_smoothing_matches_reference(random_walk(3000, 89.98, 0.0, 10.0, 5), o, "north pole");
  // Other kernels: no smoothing of ends beyond the stretch, a kernel wider than a block.
  for (const auto& [half_width, sigma] :
       std::vector<std::pair<int, double>>{{1, 1.0}, {2, 0.7}, {8, 3.0}, {1500, 400.0}}) {
    o.smooth_half_width = half_width;
    o.smooth_sigma = sigma;
    expect_smoothing_matches_reference(random_walk(3500, 46.5, 7.5, 5.0, 6), o, "kernel");
  }
}

// The minimum distance as defined in clean.hpp, point by point.
std::vector<TrackPoint> reference_min_distance(const std::vector<TrackPoint>& in, double min_distance_m,
                                               std::size_t& too_close) {
  std::vector<TrackPoint> out{in.front()};
  for (std::size_t i = 1; i < in.size(); ++i) {
    const TrackPoint& p = in[i];
    const TrackPoint& prev = out.back();
    double d = geo::geodesic_distance_m(prev.lat, prev.lon, p.lat, p.lon);
    if (prev.has_ele() && p.has_ele()) d = std::hypot(d, p.ele - prev.ele);
    if (d >= min_distance_m) {
      out.push_back(p);
    } else if (i + 1 < in.size()) {
      ++too_close;
    } else if (out.size() >= 2) {
      out.back() = p;
      ++too_close;
    } else {
      out.push_back(p);
    }
  }
  return out;
}

TEST(Clean, MinimumDistanceMatchesThePointByPointDefinition) {
  for (const double step : {1.0, 3.0, 5.0}) {
    std::vector<TrackPoint> pts = random_walk(4000, 46.5, 7.5, step, 7);
    for (auto& p : pts) p.time = kMissing;  // no time checks: only the distance drops points
    std::size_t too_close = 0;
    const std::vector<TrackPoint> expected = reference_min_distance(pts, 3.0, too_close);
    CleanReport r;
    const Track out = clean_track(one_segment(pts), no_smoothing(3.0), r);
    const auto& got = out.segments[0].points;
    EXPECT_EQ(r.too_close, too_close) << step;
    ASSERT_EQ(got.size(), expected.size()) << step;
    for (std::size_t i = 0; i < got.size(); ++i) {
      ASSERT_EQ(got[i].lat, expected[i].lat) << step << " " << i;
      ASSERT_EQ(got[i].lon, expected[i].lon) << step << " " << i;
    }
  }
}

}  // namespace
}  // namespace trailray::track
