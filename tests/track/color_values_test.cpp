#include "track/color_values.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "track/metrics.hpp"
#include "track/track_builders.hpp"

namespace trailray::track {
namespace {

using test::north;
using test::one_segment;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr float kInfF = std::numeric_limits<float>::infinity();

std::vector<std::vector<float>> values_of(const Track& t, ColorMetric metric,
                                          const std::vector<std::vector<double>>* ground = nullptr) {
  return color_values(t, compute_metrics(t), metric, ground);
}

// Every value of every segment finite or NaN, parallel to the points.
void expect_parallel_and_never_infinite(const Track& t, const std::vector<std::vector<float>>& v) {
  ASSERT_EQ(v.size(), t.segments.size());
  for (std::size_t s = 0; s < v.size(); ++s) {
    ASSERT_EQ(v[s].size(), t.segments[s].points.size());
    for (float x : v[s]) EXPECT_FALSE(std::isinf(x));
  }
}

// 21 points 100 m apart along a meridian, 10 s apart, climbing `climb_m` per point.
Track steady_track(double climb_m) {
  std::vector<TrackPoint> pts;
  for (int i = 0; i <= 20; ++i) pts.push_back(north(100.0 * i, 500.0 + climb_m * i, 1000.0 + 10.0 * i));
  return one_segment(pts);
}

TEST(ColorValues, HundredMetresEveryTenSecondsIs36KmH) {
  const Track t = steady_track(0.0);
  const auto v = values_of(t, ColorMetric::speed);
  expect_parallel_and_never_infinite(t, v);
  // 100 m / 10 s = 10 m/s = 36 km/h.
  for (float x : v[0]) EXPECT_NEAR(x, 36.0, 1e-4);
}

TEST(ColorValues, ClimbingTenMetresPerPointIsOneMetrePerSecondAndTenPercent) {
  const Track up = steady_track(10.0);
  const auto up_vspeed = values_of(up, ColorMetric::vspeed);
  const auto up_slope = values_of(up, ColorMetric::slope);
  for (float x : up_vspeed[0]) EXPECT_NEAR(x, 1.0, 1e-5);  // 10 m / 10 s
  for (float x : up_slope[0]) EXPECT_NEAR(x, 10.0, 1e-4);  // 10 m / 100 m
  const Track down = steady_track(-5.0);
  const auto down_vspeed = values_of(down, ColorMetric::vspeed);
  const auto down_slope = values_of(down, ColorMetric::slope);
  for (float x : down_vspeed[0]) EXPECT_NEAR(x, -0.5, 1e-5);
  for (float x : down_slope[0]) EXPECT_NEAR(x, -5.0, 1e-4);
}

TEST(ColorValues, AltitudeIsThePointsElevation) {
  Track t = one_segment({north(0.0, 412.5), north(100.0), north(200.0, -3.0)});
  const auto v = values_of(t, ColorMetric::altitude);
  expect_parallel_and_never_infinite(t, v);
  EXPECT_FLOAT_EQ(v[0][0], 412.5f);
  EXPECT_TRUE(std::isnan(v[0][1])) << "no elevation, no value";
  EXPECT_FLOAT_EQ(v[0][2], -3.0f);
}

TEST(ColorValues, ElapsedTimeCountsFromTheTracksFirstTimestampAcrossSegments) {
  Track t = one_segment({north(0.0), north(100.0, kNaN, 5000.0), north(200.0, kNaN, 5030.0)});
  t.segments.push_back(Segment{{north(300.0, kNaN, 5600.0), north(400.0, kNaN, 5660.0)}});
  const auto v = values_of(t, ColorMetric::time);
  expect_parallel_and_never_infinite(t, v);
  EXPECT_TRUE(std::isnan(v[0][0])) << "a point without a time has no elapsed time";
  EXPECT_FLOAT_EQ(v[0][1], 0.0f);
  EXPECT_FLOAT_EQ(v[0][2], 30.0f);
  EXPECT_FLOAT_EQ(v[1][0], 600.0f);
  EXPECT_FLOAT_EQ(v[1][1], 660.0f);
}

TEST(ColorValues, RecordedChannelsPassThroughAndMissingOnesAreNaN) {
  std::vector<TrackPoint> pts{north(0.0), north(100.0), north(200.0)};
  pts[0].heart_rate = 142.0f;
  pts[0].cadence = 88.0f;
  pts[0].power = 251.0f;
  pts[2].heart_rate = 150.0f;
  pts[2].power = kInfF;  // a broken reading must not become an infinite colour
  const Track t = one_segment(pts);
  const auto hr = values_of(t, ColorMetric::hr);
  const auto cadence = values_of(t, ColorMetric::cadence);
  const auto power = values_of(t, ColorMetric::power);
  for (const auto* v : {&hr, &cadence, &power}) expect_parallel_and_never_infinite(t, *v);
  EXPECT_FLOAT_EQ(hr[0][0], 142.0f);
  EXPECT_TRUE(std::isnan(hr[0][1]));
  EXPECT_FLOAT_EQ(hr[0][2], 150.0f);
  EXPECT_FLOAT_EQ(cadence[0][0], 88.0f);
  EXPECT_TRUE(std::isnan(cadence[0][2]));
  EXPECT_FLOAT_EQ(power[0][0], 251.0f);
  EXPECT_TRUE(std::isnan(power[0][2]));
}

TEST(ColorValues, MissingTimesAndRepeatedTimestampsGiveNaNNeverInfinity) {
  // No times at all: no speed, vertical speed or elapsed time.
  const Track untimed = one_segment({north(0.0, 500.0), north(100.0, 510.0), north(200.0, 520.0)});
  for (ColorMetric m : {ColorMetric::speed, ColorMetric::vspeed, ColorMetric::time}) {
    const auto v = values_of(untimed, m);
    expect_parallel_and_never_infinite(untimed, v);
    for (float x : v[0]) EXPECT_TRUE(std::isnan(x)) << color_metric_name(m);
  }
  // Two points 100 m apart at the same second (a raw, uncleaned track): no finite speed exists.
  const Track same_time = one_segment({north(0.0, 500.0, 100.0), north(100.0, 520.0, 100.0)});
  for (ColorMetric m : {ColorMetric::speed, ColorMetric::vspeed}) {
    const auto v = values_of(same_time, m);
    expect_parallel_and_never_infinite(same_time, v);
    for (float x : v[0]) EXPECT_TRUE(std::isnan(x)) << color_metric_name(m);
  }
  // An elevation a float cannot hold: NaN, not the infinity a plain cast would give.
  const Track huge = one_segment({north(0.0, 1e300), north(100.0, 1e300)});
  const auto altitude = values_of(huge, ColorMetric::altitude);
  expect_parallel_and_never_infinite(huge, altitude);
  EXPECT_TRUE(std::isnan(altitude[0][0]));
}

TEST(ColorValues, SolidHasNoValues) {
  const Track t = steady_track(0.0);
  const auto v = values_of(t, ColorMetric::solid);
  expect_parallel_and_never_infinite(t, v);
  for (float x : v[0]) EXPECT_TRUE(std::isnan(x));
}

TEST(ColorValues, HeightAboveGroundIsElevationMinusGround) {
  Track t = one_segment({north(0.0, 1500.0), north(100.0, 1480.0), north(200.0), north(300.0, 900.0)});
  t.segments.push_back(Segment{{north(400.0, 2000.0)}});
  const std::vector<std::vector<double>> ground{{1200.0, 1490.0, 1000.0, kNaN}, {1750.5}};
  const auto v = values_of(t, ColorMetric::agl, &ground);
  expect_parallel_and_never_infinite(t, v);
  EXPECT_FLOAT_EQ(v[0][0], 300.0f);
  EXPECT_FLOAT_EQ(v[0][1], -10.0f) << "below the ground model is reported, not hidden";
  EXPECT_TRUE(std::isnan(v[0][2])) << "no elevation";
  EXPECT_TRUE(std::isnan(v[0][3])) << "no ground height";
  EXPECT_FLOAT_EQ(v[1][0], 249.5f);
}

TEST(ColorValues, ShapeMismatchesThrow) {
  Track t = one_segment({north(0.0, 1500.0), north(100.0, 1480.0)});
  t.segments.push_back(Segment{{north(400.0, 2000.0)}});
  const TrackMetrics m = compute_metrics(t);
  const std::vector<std::vector<double>> too_few_segments{{1.0, 2.0}};
  const std::vector<std::vector<double>> too_few_points{{1.0, 2.0}, {}};
  const std::vector<std::vector<double>> right{{1.0, 2.0}, {3.0}};
  EXPECT_THROW(color_values(t, m, ColorMetric::agl), std::invalid_argument) << "agl without ground heights";
  EXPECT_THROW(color_values(t, m, ColorMetric::agl, &too_few_segments), std::invalid_argument);
  EXPECT_THROW(color_values(t, m, ColorMetric::agl, &too_few_points), std::invalid_argument);
  EXPECT_NO_THROW(color_values(t, m, ColorMetric::agl, &right));

  TrackMetrics other = compute_metrics(one_segment({north(0.0), north(1.0)}));
  EXPECT_THROW(color_values(t, other, ColorMetric::speed), std::invalid_argument);
  EXPECT_THROW(color_values(t, other, ColorMetric::time), std::invalid_argument);
  other = m;
  other.segments[1].slope_pct.clear();
  EXPECT_THROW(color_values(t, other, ColorMetric::slope), std::invalid_argument);
  // Metrics that read the points only do not need matching metrics.
  EXPECT_NO_THROW(color_values(t, TrackMetrics{}, ColorMetric::altitude));
}

// The linear-interpolation percentile, written out: rank p/100 * (n - 1) in 1..n.
double percentile_of_one_to_n(double p, int n) {
  const double rank = p / 100.0 * (n - 1);
  const double below = std::floor(rank);
  return (below + 1.0) + (rank - below);  // value at rank r is r + 1
}

TEST(RobustRange, PercentilesInterpolateOverAllVectorsTogether) {
  std::vector<float> all;
  for (int i = 1; i <= 100; ++i) all.push_back(static_cast<float>(i));
  std::shuffle(all.begin(), all.end(), std::mt19937(7));
  // Split over two "tracks", with values that do not count.
  std::vector<std::vector<float>> values{std::vector<float>(all.begin(), all.begin() + 37),
                                         std::vector<float>(all.begin() + 37, all.end())};
  values[0].push_back(std::numeric_limits<float>::quiet_NaN());
  values[1].push_back(kInfF);
  values[1].push_back(-kInfF);
  const auto r = robust_range(values, false);
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->min, percentile_of_one_to_n(2.0, 100), 1e-9);   // 2.98
  EXPECT_NEAR(r->max, percentile_of_one_to_n(98.0, 100), 1e-9);  // 98.02
  EXPECT_NEAR(r->min, 2.98, 1e-9);
  EXPECT_NEAR(r->max, 98.02, 1e-9);

  const auto whole = robust_range(values, false, 0.0, 100.0);
  ASSERT_TRUE(whole);
  EXPECT_DOUBLE_EQ(whole->min, 1.0);
  EXPECT_DOUBLE_EQ(whole->max, 100.0);
  const auto quartiles = robust_range(values, false, 25.0, 75.0);
  ASSERT_TRUE(quartiles);
  EXPECT_NEAR(quartiles->min, percentile_of_one_to_n(25.0, 100), 1e-9);  // 25.75
  EXPECT_NEAR(quartiles->max, percentile_of_one_to_n(75.0, 100), 1e-9);  // 75.25
}

TEST(RobustRange, OneSpikeDoesNotMoveTheRange) {
  std::vector<float> speeds;
  for (int i = 0; i < 1000; ++i) speeds.push_back(10.0f + static_cast<float>(i % 11));  // 10..20 km/h
  const std::vector<std::vector<float>> clean{speeds};
  speeds[500] = 4000.0f;  // one GPS jump
  const std::vector<std::vector<float>> spiked{speeds};
  const auto a = robust_range(clean, false);
  const auto b = robust_range(spiked, false);
  ASSERT_TRUE(a && b);
  EXPECT_LE(b->max, 20.0);
  EXPECT_NEAR(b->min, a->min, 1e-9);
  EXPECT_NEAR(b->max, a->max, 1e-9);
  // Without trimming the spike would set the top of the scale.
  EXPECT_DOUBLE_EQ(robust_range(spiked, false, 0.0, 100.0)->max, 4000.0);
}

TEST(RobustRange, SignedMetricsGetARangeSymmetricAboutZero) {
  std::vector<float> vspeed;
  for (int i = 0; i <= 100; ++i) vspeed.push_back(-2.0f + 0.07f * static_cast<float>(i));  // -2 .. 5
  const std::vector<std::vector<float>> values{vspeed};
  const auto plain = robust_range(values, false);
  const auto sym = robust_range(values, true);
  ASSERT_TRUE(plain && sym);
  EXPECT_LT(plain->min, 0.0);
  EXPECT_DOUBLE_EQ(sym->max, std::max(std::abs(plain->min), std::abs(plain->max)));
  EXPECT_DOUBLE_EQ(sym->min, -sym->max);
  EXPECT_NEAR(sym->max, plain->max, 1e-12) << "the larger magnitude is the climb";

  // Only sinking: still symmetric, from the sink side.
  const std::vector<std::vector<float>> sinking{{-3.0f, -2.0f, -1.0f}};
  const auto s = robust_range(sinking, true, 0.0, 100.0);
  ASSERT_TRUE(s);
  EXPECT_DOUBLE_EQ(s->min, -3.0);
  EXPECT_DOUBLE_EQ(s->max, 3.0);
}

TEST(RobustRange, ZeroWidthIsWidenedAndNoValueIsNoRange) {
  const std::vector<std::vector<float>> constant{{7.0f, 7.0f, 7.0f}};
  const auto c = robust_range(constant, false);
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(c->min, 6.5);
  EXPECT_DOUBLE_EQ(c->max, 7.5);
  const std::vector<std::vector<float>> lake{{2000.0f}};
  const auto l = robust_range(lake, false);
  ASSERT_TRUE(l);
  EXPECT_DOUBLE_EQ(l->min, 1980.0);  // 1% of the value is wider than 0.5
  EXPECT_DOUBLE_EQ(l->max, 2020.0);
  const std::vector<std::vector<float>> level{{0.0f, 0.0f}};
  const auto z = robust_range(level, true);
  ASSERT_TRUE(z);
  EXPECT_DOUBLE_EQ(z->min, -0.5);
  EXPECT_DOUBLE_EQ(z->max, 0.5);

  const std::vector<std::vector<float>> nothing{{}, {std::numeric_limits<float>::quiet_NaN(), kInfF}};
  EXPECT_FALSE(robust_range(nothing, false));
  EXPECT_FALSE(robust_range({}, true));
}

TEST(RobustRange, RejectsPercentilesOutOfOrder) {
  const std::vector<std::vector<float>> v{{1.0f, 2.0f}};
  EXPECT_THROW(robust_range(v, false, 60.0, 40.0), std::invalid_argument);
  EXPECT_THROW(robust_range(v, false, -1.0, 50.0), std::invalid_argument);
  EXPECT_THROW(robust_range(v, false, 0.0, 101.0), std::invalid_argument);
  EXPECT_THROW(robust_range(v, false, kNaN, 98.0), std::invalid_argument);
}

TEST(ParseValueRange, AcceptsFiniteIncreasingPairs) {
  const auto a = parse_value_range("0:40");
  ASSERT_TRUE(a);
  EXPECT_DOUBLE_EQ(a->min, 0.0);
  EXPECT_DOUBLE_EQ(a->max, 40.0);
  const auto b = parse_value_range("-5:5");
  ASSERT_TRUE(b);
  EXPECT_DOUBLE_EQ(b->min, -5.0);
  EXPECT_DOUBLE_EQ(b->max, 5.0);
  const auto c = parse_value_range("-12.5:-0.25");
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(c->min, -12.5);
  EXPECT_DOUBLE_EQ(c->max, -0.25);
  const auto d = parse_value_range("1500:3.2e3");
  ASSERT_TRUE(d);
  EXPECT_DOUBLE_EQ(d->max, 3200.0);
}

TEST(ParseValueRange, RejectsEverythingElse) {
  for (const char* bad : {"5:5",   "6:5",    "a:b",   "1:",   ":1",   ":",    "",     "5",      "nan:1", "1:nan",
                          "1:inf", "-inf:0", "1:2:3", "1:2 ", " 1:2", "1 :2", "1:2x", "1..5:6", "--1:2", "1e999:2"}) {
    EXPECT_FALSE(parse_value_range(bad)) << '"' << bad << '"';
  }
}

TEST(ColorValueFormat, PrecisionPerMetric) {
  EXPECT_EQ(format_color_value(ColorMetric::speed, 12.46), "12.5");
  EXPECT_EQ(format_color_value(ColorMetric::speed, 0.0), "0.0");
  EXPECT_EQ(format_color_value(ColorMetric::speed, 99.9), "99.9");
  EXPECT_EQ(format_color_value(ColorMetric::speed, 99.97), "100");
  EXPECT_EQ(format_color_value(ColorMetric::speed, 123.4), "123");
  EXPECT_EQ(format_color_value(ColorMetric::vspeed, -3.24), "-3.2");
  EXPECT_EQ(format_color_value(ColorMetric::vspeed, 2.0), "2.0") << "no plus sign";
  EXPECT_EQ(format_color_value(ColorMetric::vspeed, -0.04), "0.0") << "no negative zero";
  EXPECT_EQ(format_color_value(ColorMetric::slope, 12.6), "13");
  EXPECT_EQ(format_color_value(ColorMetric::slope, -7.4), "-7");
  EXPECT_EQ(format_color_value(ColorMetric::slope, -0.3), "0");
  EXPECT_EQ(format_color_value(ColorMetric::altitude, 2450.4), "2450");
  EXPECT_EQ(format_color_value(ColorMetric::agl, -12.0), "-12");
  EXPECT_EQ(format_color_value(ColorMetric::hr, 142.6), "143");
  EXPECT_EQ(format_color_value(ColorMetric::cadence, 88.0), "88");
  EXPECT_EQ(format_color_value(ColorMetric::power, 251.2), "251");
  EXPECT_EQ(format_color_value(ColorMetric::altitude, kNaN), "n/a");
}

TEST(ColorValueFormat, ElapsedTimeAsHoursAndWholeMinutes) {
  EXPECT_EQ(format_color_value(ColorMetric::time, 3900.0), "1:05");
  EXPECT_EQ(format_color_value(ColorMetric::time, 59.0), "0:00");
  EXPECT_EQ(format_color_value(ColorMetric::time, 60.0), "0:01");
  EXPECT_EQ(format_color_value(ColorMetric::time, 0.0), "0:00");
  EXPECT_EQ(format_color_value(ColorMetric::time, 3599.9), "0:59");
  EXPECT_EQ(format_color_value(ColorMetric::time, 36000.0 + 600.0), "10:10");
  EXPECT_EQ(format_color_value(ColorMetric::time, 100.0 * 3600.0), "100:00");
  EXPECT_EQ(format_color_value(ColorMetric::time, -60.0), "-0:01");
  EXPECT_EQ(format_color_value(ColorMetric::time, -59.0), "0:00") << "no negative zero";
}

TEST(ColorMetricNames, RoundTripAndLabels) {
  const auto names = color_metric_names();
  ASSERT_EQ(names.size(), 14u);
  EXPECT_EQ(names.front(), "solid");
  EXPECT_EQ(names[10], "phase");
  EXPECT_EQ(names.back(), "cover");
  for (std::string_view name : names) {
    const auto m = parse_color_metric(name);
    ASSERT_TRUE(m) << name;
    EXPECT_EQ(color_metric_name(*m), name);
  }
  EXPECT_FALSE(parse_color_metric("Speed"));
  EXPECT_FALSE(parse_color_metric("speed "));
  EXPECT_FALSE(parse_color_metric(""));
  EXPECT_EQ(color_metric_label(ColorMetric::agl), "Height above ground");
  EXPECT_EQ(color_metric_unit(ColorMetric::speed), "km/h");
  EXPECT_EQ(color_metric_unit(ColorMetric::slope), "%");
  EXPECT_EQ(color_metric_unit(ColorMetric::time), "");
  EXPECT_TRUE(color_metric_is_signed(ColorMetric::vspeed));
  EXPECT_FALSE(color_metric_is_signed(ColorMetric::speed));
  EXPECT_FALSE(color_metric_is_signed(ColorMetric::altitude));
  // Counts over all the tracks: whole numbers, no values of a track alone.
  EXPECT_TRUE(counts_neighbours(ColorMetric::density));
  EXPECT_TRUE(counts_neighbours(ColorMetric::thermals));
  EXPECT_FALSE(counts_neighbours(ColorMetric::phase));
  EXPECT_EQ(color_metric_unit(ColorMetric::density), "tracks");
  EXPECT_EQ(format_color_value(ColorMetric::density, 12.4), "12");
  EXPECT_EQ(format_color_value(ColorMetric::thermals, 0.0), "0");
}

}  // namespace
}  // namespace trailray::track
