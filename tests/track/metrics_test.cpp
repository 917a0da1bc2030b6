#include "track/metrics.hpp"

#include <gtest/gtest.h>
#include <GeographicLib/Geodesic.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "geo/geodesic.hpp"
#include "track/track_builders.hpp"

namespace trailray::track {
namespace {

using test::kLat0;
using test::kLon0;
using test::north;
using test::one_segment;

// Every channel finite or NaN, parallel to the points.
void expect_sane(const Track& t, const TrackMetrics& m) {
  ASSERT_EQ(m.segments.size(), t.segments.size());
  for (std::size_t s = 0; s < t.segments.size(); ++s) {
    const SegmentMetrics& sm = m.segments[s];
    const std::size_t n = t.segments[s].points.size();
    for (const auto* ch : {&sm.distance_m, &sm.distance_3d_m, &sm.elapsed_s, &sm.speed_ms, &sm.vspeed_ms, &sm.slope_pct,
                           &sm.glide_ratio}) {
      ASSERT_EQ(ch->size(), n);
      for (double v : *ch) EXPECT_FALSE(std::isinf(v));
    }
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_TRUE(std::isfinite(sm.distance_m[i]));
      EXPECT_TRUE(std::isfinite(sm.distance_3d_m[i]));
      if (i > 0) {
        EXPECT_GE(sm.distance_m[i], sm.distance_m[i - 1]);
      }
      if (std::isfinite(sm.speed_ms[i])) {
        EXPECT_GE(sm.speed_ms[i], 0.0);
      }
      if (std::isfinite(sm.glide_ratio[i])) {
        EXPECT_GE(sm.glide_ratio[i], 0.0);
      }
    }
  }
}

TEST(Metrics, SpeedAlongAMeridian100MetresEvery10Seconds) {
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 20; ++i) pts.push_back(north(100.0 * i, 500.0, 1000.0 + 10.0 * i));
  const Track t = one_segment(pts);
  const TrackMetrics m = compute_metrics(t);
  expect_sane(t, m);
  const SegmentMetrics& s = m.segments[0];
  for (std::size_t i = 0; i < pts.size(); ++i) {
    EXPECT_NEAR(s.distance_m[i], 100.0 * double(i), 1e-6) << i;
    EXPECT_NEAR(s.distance_3d_m[i], 100.0 * double(i), 1e-6) << i;
    EXPECT_DOUBLE_EQ(s.elapsed_s[i], 10.0 * double(i));
    EXPECT_NEAR(s.speed_ms[i] * 3.6, 36.0, 1e-9) << i;
    EXPECT_NEAR(s.vspeed_ms[i], 0.0, 1e-12) << i;
    EXPECT_NEAR(s.slope_pct[i], 0.0, 1e-9) << i;
    EXPECT_TRUE(std::isnan(s.glide_ratio[i])) << "level flight is not gliding";
  }
}

TEST(Metrics, ClimbingOneMetrePerSecondIsTenPercent) {
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 20; ++i) pts.push_back(north(100.0 * i, 500.0 + 10.0 * i, 10.0 * i));
  const Track t = one_segment(pts);
  const TrackMetrics m = compute_metrics(t);
  expect_sane(t, m);
  const SegmentMetrics& s = m.segments[0];
  for (std::size_t i = 0; i < pts.size(); ++i) {
    EXPECT_NEAR(s.vspeed_ms[i], 1.0, 1e-9) << i;
    EXPECT_NEAR(s.slope_pct[i], 10.0, 1e-6) << i;
    EXPECT_TRUE(std::isnan(s.glide_ratio[i])) << "no glide ratio while climbing";
    EXPECT_NEAR(s.distance_3d_m[i], std::hypot(100.0, 10.0) * double(i), 1e-6) << i;
  }
}

TEST(Metrics, GlideRatioWhileSinking) {
  // 10 m/s forward, 1 m/s down: glide ratio 10.
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 20; ++i) pts.push_back(north(100.0 * i, 2000.0 - 10.0 * i, 10.0 * i));
  const TrackMetrics m = compute_metrics(one_segment(pts));
  for (std::size_t i = 0; i < pts.size(); ++i) {
    EXPECT_NEAR(m.segments[0].vspeed_ms[i], -1.0, 1e-9);
    EXPECT_NEAR(m.segments[0].glide_ratio[i], 10.0, 1e-6);
    EXPECT_NEAR(m.segments[0].slope_pct[i], -10.0, 1e-6);
  }
}

TEST(Metrics, GlideRatioNeedsASinkRateAboveTheThreshold) {
  // Sinking 0.05 m/s: below min_sink_for_glide_ms = 0.1.
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 10; ++i) pts.push_back(north(100.0 * i, 2000.0 - 0.5 * i, 10.0 * i));
  const TrackMetrics m = compute_metrics(one_segment(pts));
  for (double g : m.segments[0].glide_ratio) EXPECT_TRUE(std::isnan(g));
}

TEST(Metrics, SpeedWindowIsCentredInTime) {
  // 1 Hz: 2 m/s for 50 s, then 4 m/s. With a 10 s window the speed at the change is 3 m/s and
  // 5 s or more away from it the exact speeds.
  std::vector<TrackPoint> pts;
  double s = 0;
  for (int t = 0; t <= 100; ++t) {
    pts.push_back(north(s, kMissing, double(t)));
    s += t < 50 ? 2.0 : 4.0;
  }
  const TrackMetrics m = compute_metrics(one_segment(pts));
  const auto& v = m.segments[0].speed_ms;
  EXPECT_NEAR(v[50], 3.0, 1e-6);
  EXPECT_NEAR(v[45], 2.0, 1e-6);
  EXPECT_NEAR(v[55], 4.0, 1e-6);
  EXPECT_NEAR(v[48], (7 * 2.0 + 3 * 4.0) / 10.0, 1e-6);
  EXPECT_NEAR(v[0], 2.0, 1e-6);    // one-sided at the start
  EXPECT_NEAR(v[100], 4.0, 1e-6);  // and at the end
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_TRUE(std::isnan(m.segments[0].vspeed_ms[i]));
}

TEST(Metrics, SpeedWindowReachesBeyondItsEdges) {
  // Irregular sampling: a fix 1 s after the first (20 m off), then one every 10 s. The window
  // of the first point reaches the first fix at or after t + 5 s instead of the 1-s neighbour.
  const std::vector<TrackPoint> pts{north(0, kMissing, 0), north(20, kMissing, 1), north(30, kMissing, 11),
                                    north(40, kMissing, 21), north(50, kMissing, 31)};
  const TrackMetrics m = compute_metrics(one_segment(pts));
  const auto& v = m.segments[0].speed_ms;
  EXPECT_NEAR(v[0], 30.0 / 11.0, 1e-9);
  EXPECT_NEAR(v[1], 30.0 / 11.0, 1e-9);  // t = 0 .. 11
  EXPECT_NEAR(v[2], 20.0 / 20.0, 1e-9);  // t = 1 .. 21
  EXPECT_NEAR(v[4], 1.0, 1e-9);          // one-sided at the end: t = 21 .. 31
}

TEST(Metrics, SlopeWindowIsCentredInDistance) {
  // A point every 5 m without times: 0 % for 100 m, then 20 %.
  std::vector<TrackPoint> pts;
  double ele = 100.0;
  for (int i = 0; i <= 40; ++i) {
    pts.push_back(north(5.0 * i, ele));
    if (i >= 20) ele += 1.0;
  }
  MetricsOptions o;
  o.slope_window_m = 48.0;  // +-24 m: no point on the window's edge
  const TrackMetrics m = compute_metrics(one_segment(pts), o);
  const auto& slope = m.segments[0].slope_pct;
  EXPECT_NEAR(slope[10], 0.0, 1e-6);
  EXPECT_NEAR(slope[30], 20.0, 1e-6);
  EXPECT_NEAR(slope[20], 10.0, 1e-6);                   // window 76..124 m: half flat, half at 20 %
  EXPECT_TRUE(std::isnan(m.segments[0].speed_ms[10]));  // no time, no speed
  EXPECT_TRUE(std::isnan(m.segments[0].elapsed_s[10]));
}

TEST(Metrics, WindowsDoNotCrossAPause) {
  // Moving 10 m/s, a 300 s stop at the same place without points, moving again.
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 5; ++i) pts.push_back(north(100.0 * i, 500.0, 10.0 * i));
  for (int i = 5; i <= 10; ++i) pts.push_back(north(100.0 * i, 500.0, 350.0 + 10.0 * i));
  const TrackMetrics m = compute_metrics(one_segment(pts));
  const auto& v = m.segments[0].speed_ms;
  EXPECT_NEAR(v[5], 10.0, 1e-6);  // before the pause: from its left neighbours only
  EXPECT_NEAR(v[6], 10.0, 1e-6);  // after it: from its right neighbours only
  // The pause still does not add distance.
  EXPECT_NEAR(m.segments[0].distance_m.back(), 1000.0, 1e-6);

  MetricsOptions no_pauses;
  no_pauses.max_gap_s = 0.0;  // disabled: the window spans the stop
  const TrackMetrics m2 = compute_metrics(one_segment(pts), no_pauses);
  EXPECT_LT(m2.segments[0].speed_ms[5], 1.0);
}

TEST(Metrics, ASparseLoggerHasNoPausesBetweenItsFixes) {
  // A fix every 120 s (a planned route with times, a logger saving power), 10 m/s north, climbing
  // 1 m every 100 m: every gap is over 60 s, but none is longer than the track's usual step.
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 20; ++i) pts.push_back(north(1200.0 * i, 500.0 + 12.0 * i, 120.0 * i));
  const SegmentMetrics m = compute_metrics(one_segment(pts)).segments[0];
  for (std::size_t i = 0; i < pts.size(); ++i) {
    EXPECT_NEAR(m.speed_ms[i], 10.0, 1e-6) << i;
    EXPECT_NEAR(m.vspeed_ms[i], 0.1, 1e-6) << i;
    EXPECT_NEAR(m.slope_pct[i], 1.0, 1e-6) << i;
  }
}

TEST(Metrics, SteepnessDoesNotStopAtAPause) {
  // Walking up 10 % at 1 m/s, a fix a second, then 200 s without a fix (a tunnel, a pause)
  // while 20 m further on: speed windows stop at the pause, the slope is measured over distance.
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 60; ++i) pts.push_back(north(1.0 * i, 500.0 + 0.1 * i, 1.0 * i));
  for (int i = 0; i <= 60; ++i) pts.push_back(north(80.0 + i, 508.0 + 0.1 * i, 260.0 + i));
  const SegmentMetrics m = compute_metrics(one_segment(pts)).segments[0];
  for (std::size_t i = 0; i < pts.size(); ++i) EXPECT_NEAR(m.slope_pct[i], 10.0, 1e-6) << i;
  EXPECT_NEAR(m.speed_ms[60], 1.0, 1e-6);  // from its own side of the pause only
  EXPECT_NEAR(m.speed_ms[61], 1.0, 1e-6);
}

TEST(Metrics, GapBetweenSegmentsAddsNoDistanceAndWindowsStayInside) {
  Track t;
  Segment a, b;
  for (int i = 0; i <= 5; ++i) a.points.push_back(north(100.0 * i, 500.0 + i, 10.0 * i));
  // The second segment starts 10 km further and 20 s later, climbing faster.
  for (int i = 0; i <= 5; ++i) b.points.push_back(north(10000.0 + 50.0 * i, 900.0 + 5.0 * i, 70.0 + 10.0 * i));
  t.segments = {a, b};
  const TrackMetrics m = compute_metrics(t);
  expect_sane(t, m);
  EXPECT_NEAR(m.segments[0].distance_m.back(), 500.0, 1e-6);
  EXPECT_DOUBLE_EQ(m.segments[1].distance_m.front(), m.segments[0].distance_m.back());
  EXPECT_NEAR(m.segments[1].distance_m.back(), 750.0, 1e-6);
  EXPECT_DOUBLE_EQ(m.segments[1].distance_3d_m.front(), m.segments[0].distance_3d_m.back());
  EXPECT_DOUBLE_EQ(m.segments[1].elapsed_s.front(), 70.0);  // from the track's first timestamp
  EXPECT_NEAR(m.segments[0].speed_ms.back(), 10.0, 1e-6);
  EXPECT_NEAR(m.segments[1].speed_ms.front(), 5.0, 1e-6);
  EXPECT_NEAR(m.segments[0].vspeed_ms.back(), 0.1, 1e-9);
  EXPECT_NEAR(m.segments[1].vspeed_ms.front(), 0.5, 1e-9);
  EXPECT_NEAR(m.segments[1].slope_pct.front(), 10.0, 1e-6);
}

TEST(Metrics, DuplicateTimestampsAndRepeatedPositionsNeverDivideByZero) {
  // Raw recording: a repeated fix (same time, same place), a duplicate time at a new place,
  // a backward jump.
  const std::vector<TrackPoint> pts{north(0, 100, 0),    north(100, 101, 10), north(100, 101, 10), north(150, 102, 10),
                                    north(200, 103, 20), north(250, 104, 15), north(300, 105, 30), north(300, 105, 30)};
  const Track t = one_segment(pts);
  const TrackMetrics m = compute_metrics(t);
  expect_sane(t, m);
  const auto& v = m.segments[0].speed_ms;
  for (std::size_t i = 0; i < pts.size(); ++i) EXPECT_FALSE(std::isinf(m.segments[0].vspeed_ms[i]));
  EXPECT_NEAR(v[0], 10.0, 1e-6);         // 0 s -> 10 s (the duplicate-time group)
  EXPECT_NEAR(v[1], 10.0, 1e-6);         // widened to t = 0 and t = 20: 200 m / 20 s
  EXPECT_NEAR(v[4], 5.0, 1e-6);          // t = 20, before the backward jump: from the t = 10 group only
  EXPECT_NEAR(v[5], 50.0 / 15.0, 1e-6);  // a new run starts at the backward jump
  EXPECT_TRUE(std::isfinite(v[6]));
  EXPECT_TRUE(std::isfinite(v[7]));
}

TEST(Metrics, OnlyRepeatedFixesGiveNoRate) {
  // Two identical points with identical times, and a segment of one point.
  Track t;
  t.segments.push_back(Segment{{north(0, 100, 5), north(0, 100, 5)}});
  t.segments.push_back(Segment{{north(10, 100, 6)}});
  t.segments.push_back(Segment{});
  const TrackMetrics m = compute_metrics(t);
  expect_sane(t, m);
  for (const auto& s : m.segments)
    for (std::size_t i = 0; i < s.distance_m.size(); ++i) {
      EXPECT_TRUE(std::isnan(s.speed_ms[i]));
      EXPECT_TRUE(std::isnan(s.vspeed_ms[i]));
      EXPECT_TRUE(std::isnan(s.slope_pct[i]));
      EXPECT_TRUE(std::isnan(s.glide_ratio[i]));
    }
  EXPECT_EQ(m.segments[0].distance_m[1], 0.0);
  EXPECT_EQ(m.segments[1].elapsed_s[0], 1.0);
}

TEST(Metrics, TwoPointsMoving) {
  const TrackMetrics m = compute_metrics(one_segment({north(0, 100, 0), north(50, 110, 10)}));
  EXPECT_NEAR(m.segments[0].speed_ms[0], 5.0, 1e-6);
  EXPECT_NEAR(m.segments[0].speed_ms[1], 5.0, 1e-6);
  EXPECT_NEAR(m.segments[0].vspeed_ms[1], 1.0, 1e-9);
  EXPECT_NEAR(m.segments[0].slope_pct[1], 20.0, 1e-6);
}

TEST(Metrics, EmptyTrack) {
  const Track t;
  const TrackMetrics m = compute_metrics(t);
  EXPECT_TRUE(m.segments.empty());
}

TEST(Metrics, MissingTimesAndElevationsGiveNaNNotGarbage) {
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 10; ++i)
    pts.push_back(north(100.0 * i, i % 2 ? kMissing : 500.0 + i, i == 4 ? kMissing : 10.0 * i));
  const Track t = one_segment(pts);
  const TrackMetrics m = compute_metrics(t);
  expect_sane(t, m);
  const SegmentMetrics& s = m.segments[0];
  EXPECT_TRUE(std::isnan(s.elapsed_s[4]));
  EXPECT_TRUE(std::isnan(s.speed_ms[4]));
  EXPECT_NEAR(s.speed_ms[5], 10.0, 1e-6);  // from point 3 to 6: 300 m in 30 s, point 4 still counted
  for (int i = 1; i <= 9; i += 2) {
    EXPECT_TRUE(std::isnan(s.vspeed_ms[i]));
    EXPECT_TRUE(std::isnan(s.slope_pct[i]));
  }
  // Elevation rises 2 m per 200 m between the points that have one: 1 %.
  EXPECT_NEAR(s.slope_pct[6], 1.0, 1e-6);
  EXPECT_NEAR(s.vspeed_ms[6], 0.1, 1e-9);
  // 3D distance falls back to the 2D step where an elevation is missing.
  EXPECT_NEAR(s.distance_3d_m.back(), 1000.0, 1e-6);
}

TEST(Metrics, InvalidCoordinatesInARawTrackDoNotPoisonDistances) {
  std::vector<TrackPoint> pts{north(0, kMissing, 0), north(100, kMissing, 10), north(200, kMissing, 20)};
  pts[1].lat = std::nan("");
  const Track t = one_segment(pts);
  const TrackMetrics m = compute_metrics(t);
  expect_sane(t, m);
  EXPECT_EQ(m.segments[0].distance_m.back(), 0.0);
}

TEST(Metrics, SegmentMetricsAloneMatchTheTrackRun) {
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 10; ++i) pts.push_back(north(100.0 * i, 500.0 + i, 10.0 * i));
  const TrackMetrics m = compute_metrics(one_segment(pts));
  const SegmentMetrics s = compute_segment_metrics(Segment{pts});
  EXPECT_EQ(s.distance_m, m.segments[0].distance_m);
  EXPECT_EQ(s.speed_ms, m.segments[0].speed_ms);
  EXPECT_EQ(s.elapsed_s, m.segments[0].elapsed_s);
}

TEST(Metrics, RatesDoNotDependOnWhetherEveryPointHasEveryChannel) {
  // A segment where every point has a time and an elevation takes a shorter path through the
  // rates; adding a point without either must not change anything for the others. Times with
  // pauses and backward jumps (a raw track), 2000 points.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<TrackPoint> pts;
  double t = 1000.0, ele = 800.0, s = 0.0;
  for (int i = 0; i < 2000; ++i) {
    pts.push_back(north(s, ele, t));
    const double r = u(rng);
    t += r < 0.01 ? 120.0 : r < 0.02 ? -3.0 : 1.0;
    ele += 4.0 * (u(rng) - 0.5);
    s += 8.0 * u(rng);
  }
  std::vector<TrackPoint> with_bare = pts;
  with_bare.push_back(north(s));  // no time, no elevation
  const TrackMetrics a = compute_metrics(one_segment(pts));
  const TrackMetrics b = compute_metrics(one_segment(with_bare));
  const SegmentMetrics& ma = a.segments[0];
  const SegmentMetrics& mb = b.segments[0];
  auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
  std::size_t rates = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    ASSERT_TRUE(same(ma.distance_m[i], mb.distance_m[i])) << i;
    ASSERT_TRUE(same(ma.speed_ms[i], mb.speed_ms[i])) << i;
    ASSERT_TRUE(same(ma.vspeed_ms[i], mb.vspeed_ms[i])) << i;
    ASSERT_TRUE(same(ma.slope_pct[i], mb.slope_pct[i])) << i;
    ASSERT_TRUE(same(ma.glide_ratio[i], mb.glide_ratio[i])) << i;
    rates += std::isfinite(ma.speed_ms[i]) && std::isfinite(ma.vspeed_ms[i]) && std::isfinite(ma.slope_pct[i]);
  }
  EXPECT_GT(rates, 1900u);
  expect_sane(one_segment(with_bare), b);
}

}  // namespace
}  // namespace trailray::track
