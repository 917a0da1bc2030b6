#include "geo/geodesic.hpp"

#include <gtest/gtest.h>
#include <GeographicLib/Geodesic.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include "geo/wgs84.hpp"

using trailray::geo::geodesic_distance_m;

TEST(Geodesic, OneDegreeOfLatitudeAtTheEquator) {
  // WGS84 meridian arc from 0 to 1 degree: 110574.389 m (Karney / GeographicLib).
  EXPECT_NEAR(geodesic_distance_m(0, 0, 1, 0), 110574.389, 0.01);
}

TEST(Geodesic, OneDegreeOfLongitudeAtTheEquator) {
  // a * pi / 180 with a = 6378137 m.
  EXPECT_NEAR(geodesic_distance_m(0, 0, 0, 1), 111319.491, 0.01);
}

TEST(Geodesic, RepeatedPointIsZero) { EXPECT_EQ(geodesic_distance_m(46.7, 7.8, 46.7, 7.8), 0.0); }

TEST(Geodesic, IsSymmetric) {
  EXPECT_DOUBLE_EQ(geodesic_distance_m(46.68, 7.82, 46.72, 7.86), geodesic_distance_m(46.72, 7.86, 46.68, 7.82));
}

// --- The short-step fast path against GeographicLib -------------------------------------------

namespace {

double reference_m(double lat1, double lon1, double lat2, double lon2) {
  double s12 = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(lat1, lon1, lat2, lon2, s12);
  return s12;
}

double normalised_lon(double lon) {
  if (lon > 180.0) return lon - 360.0;
  if (lon < -180.0) return lon + 360.0;
  return lon;
}

// The bound documented in geodesic.hpp.
double bound_m(double d) { return 2e-8 + 1e-9 * d; }

enum class Where { Anywhere, NearAPole, AtTheAntimeridian };

// Random pairs whose differences reach `max_step_deg` (steps of all lengths: a third of them
// scaled down by up to 10^-6, so millimetre steps are covered too).
void compare_random_pairs(Where where, double max_step_deg, int count, unsigned seed, double& worst_abs,
                          double& worst_rel) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < count; ++k) {
    double lat1 = (2.0 * u(rng) - 1.0) * 90.0;
    if (where == Where::NearAPole) lat1 = (u(rng) < 0.5 ? -1.0 : 1.0) * (90.0 - u(rng) * 0.2);
    double lon1 = (2.0 * u(rng) - 1.0) * 180.0;
    if (where == Where::AtTheAntimeridian)
      lon1 = u(rng) < 0.5 ? 180.0 - u(rng) * max_step_deg : -180.0 + u(rng) * max_step_deg;
    const double scale = u(rng) < 0.3 ? std::pow(10.0, -6.0 * u(rng)) : 1.0;
    const double lat2 = lat1 + (2.0 * u(rng) - 1.0) * max_step_deg * scale;
    if (std::abs(lat2) > 90.0) continue;
    const double lon2 = normalised_lon(lon1 + (2.0 * u(rng) - 1.0) * max_step_deg * scale);
    const double ref = reference_m(lat1, lon1, lat2, lon2);
    const double got = geodesic_distance_m(lat1, lon1, lat2, lon2);
    const double err = std::abs(got - ref);
    ASSERT_LE(err, bound_m(ref)) << lat1 << " " << lon1 << " -> " << lat2 << " " << lon2 << ": " << got << " vs "
                                 << ref;
    worst_abs = std::max(worst_abs, err);
    if (ref > 100.0) worst_rel = std::max(worst_rel, err / ref);
  }
}

}  // namespace

TEST(Geodesic, ShortStepsAgreeWithGeographicLibEverywhere) {
  const double t = trailray::geo::kShortStepMaxDeg;
  double worst_abs = 0.0, worst_rel = 0.0;
  compare_random_pairs(Where::Anywhere, t, 200000, 1, worst_abs, worst_rel);
  compare_random_pairs(Where::NearAPole, t, 50000, 2, worst_abs, worst_rel);
  compare_random_pairs(Where::AtTheAntimeridian, t, 50000, 3, worst_abs, worst_rel);
  compare_random_pairs(Where::Anywhere, t / 50.0, 50000, 4, worst_abs, worst_rel);  // ~100 m steps
  // The documented figures (geodesic.hpp): at most 3.6 micrometres; 6.4e-10 relative over 100 m.
  EXPECT_LT(worst_abs, 4e-6);
  EXPECT_LT(worst_rel, 7e-10);
}

TEST(Geodesic, LongStepsAreGeographicLibExactly) {
  // Beyond the threshold the result is GeographicLib's, bit for bit.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 20000; ++k) {
    const double lat1 = (2.0 * u(rng) - 1.0) * 90.0;
    const double lon1 = (2.0 * u(rng) - 1.0) * 180.0;
    const double step = trailray::geo::kShortStepMaxDeg * (1.0 + 1e-9 + 20.0 * u(rng));
    const bool along_lat = u(rng) < 0.5;
    const double lat2 = along_lat ? lat1 + (u(rng) < 0.5 ? step : -step) : lat1;
    if (std::abs(lat2) > 90.0) continue;
    const double lon2 = along_lat ? lon1 : normalised_lon(lon1 + (u(rng) < 0.5 ? step : -step));
    ASSERT_EQ(geodesic_distance_m(lat1, lon1, lat2, lon2), reference_m(lat1, lon1, lat2, lon2));
  }
  // Either side of a pole (a short geodesic, a long way in longitude).
  EXPECT_EQ(geodesic_distance_m(89.999, 10.0, 89.999, -170.0), reference_m(89.999, 10.0, 89.999, -170.0));
  EXPECT_NEAR(geodesic_distance_m(89.999, 10.0, 89.999, -170.0), 2 * 111.694, 0.01);
}

TEST(Geodesic, AcrossTheAntimeridian) {
  // 0.002 degrees of longitude at the equator: a * 0.002 * pi / 180 = 222.639 m, either way round.
  EXPECT_NEAR(geodesic_distance_m(0.0, 179.999, 0.0, -179.999), 222.639, 0.001);
  EXPECT_NEAR(geodesic_distance_m(0.0, -179.999, 0.0, 179.999), 222.639, 0.001);
  EXPECT_NEAR(geodesic_distance_m(0.0, 180.0, 0.0, -180.0), 0.0, 1e-9);
  EXPECT_NEAR(geodesic_distance_m(60.0, 179.99, 60.01, -179.99), reference_m(60.0, 179.99, 60.01, -179.99), 1e-7);
}

TEST(Geodesic, AtAPole) {
  // At the pole every longitude is the same point.
  EXPECT_NEAR(geodesic_distance_m(90.0, 0.0, 90.0, 0.04), 0.0, 1e-9);
  const double ref1 = reference_m(90.0, 0.0, 89.99, 0.03), ref2 = reference_m(-90.0, 0.0, -89.95, -0.05);
  EXPECT_NEAR(geodesic_distance_m(90.0, 0.0, 89.99, 0.03), ref1, bound_m(ref1));
  EXPECT_NEAR(geodesic_distance_m(-90.0, 0.0, -89.95, -0.05), ref2, bound_m(ref2));
}

TEST(Geodesic, InvalidInputIsNotANumber) {
  EXPECT_TRUE(std::isnan(geodesic_distance_m(std::nan(""), 0.0, 0.0, 0.0)));
  EXPECT_TRUE(std::isnan(geodesic_distance_m(0.0, 0.0, 0.0, std::nan(""))));
  EXPECT_TRUE(std::isnan(geodesic_distance_m(90.01, 0.0, 90.0, 0.0)));
}

TEST(Geodesic, ShortStepIsSymmetric) {
  EXPECT_EQ(geodesic_distance_m(46.68, 7.82, 46.6801, 7.8202), geodesic_distance_m(46.6801, 7.8202, 46.68, 7.82));
  EXPECT_EQ(geodesic_distance_m(-3.0, 179.99, -3.01, -179.98), geodesic_distance_m(-3.01, -179.98, -3.0, 179.99));
}

TEST(Wgs84, LatitudeSineAndCosineMatchLibm) {
  namespace w = trailray::geo::wgs84;
  for (int k = -20000; k <= 20000; ++k) {
    const double x = std::numbers::pi / 2.0 * k / 20000.0;
    ASSERT_NEAR(w::sin_lat(x), std::sin(x), 4e-16) << x;
    ASSERT_NEAR(w::cos_lat(x), std::cos(x), 4e-16) << x;
  }
}
