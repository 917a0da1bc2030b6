#include "geo/web_mercator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace trailray::geo {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kR = 6378137.0;

// The textbook forward projection, written out here rather than taken from the implementation:
// y = R ln(tan(pi/4 + phi/2)).
double textbook_y(double lat_deg) { return kR * std::log(std::tan(kPi / 4.0 + lat_deg * kPi / 360.0)); }

TEST(WebMercator, Constants) {
  EXPECT_DOUBLE_EQ(kMercatorHalfExtentM, 20037508.342789244);
  // The latitude limit is where the world becomes square: y(limit) == x(180).
  EXPECT_NEAR(kMercatorMaxLatDeg, 85.05112878, 1e-8);
  EXPECT_NEAR(textbook_y(kMercatorMaxLatDeg), kMercatorHalfExtentM, 1e-6);
  EXPECT_NEAR(std::atan(std::sinh(kPi)) * 180.0 / kPi, kMercatorMaxLatDeg, 1e-13);
}

TEST(WebMercator, KnownValues) {
  const MercatorPoint origin = mercator_from_latlon(0.0, 0.0);
  EXPECT_EQ(origin.x, 0.0);
  EXPECT_EQ(origin.y, 0.0);
  const MercatorPoint east = mercator_from_latlon(0.0, 180.0);
  EXPECT_NEAR(east.x, 20037508.342789244, 1e-7);
  const MercatorPoint west = mercator_from_latlon(0.0, -180.0);
  EXPECT_NEAR(west.x, -20037508.342789244, 1e-7);
  // 45 N, 90 W: the EPSG:3857 numbers every GIS prints.
  const MercatorPoint p = mercator_from_latlon(45.0, -90.0);
  EXPECT_NEAR(p.x, -10018754.171394622, 1e-7);
  EXPECT_NEAR(p.y, 5621521.486192066, 1e-7);
  const MercatorPoint s = mercator_from_latlon(-45.0, 90.0);
  EXPECT_NEAR(s.x, 10018754.171394622, 1e-7);
  EXPECT_NEAR(s.y, -5621521.486192066, 1e-7);
}

TEST(WebMercator, AgreesWithTheTextbookFormula) {
  std::mt19937_64 rng(20240601);
  std::uniform_real_distribution<double> lat(-85.0, 85.0), lon(-180.0, 180.0);
  for (int i = 0; i < 2000; ++i) {
    const double la = lat(rng), lo = lon(rng);
    const MercatorPoint p = mercator_from_latlon(la, lo);
    EXPECT_NEAR(p.x, kR * lo * kPi / 180.0, 1e-8);
    EXPECT_NEAR(p.y, textbook_y(la), 1e-6) << la;
  }
}

TEST(WebMercator, LatitudeIsClampedAtTheLimit) {
  const double edge = mercator_from_latlon(kMercatorMaxLatDeg, 0.0).y;
  EXPECT_NEAR(edge, kMercatorHalfExtentM, 1e-6);
  EXPECT_EQ(mercator_from_latlon(85.1, 0.0).y, edge);
  EXPECT_EQ(mercator_from_latlon(90.0, 0.0).y, edge);
  EXPECT_EQ(mercator_from_latlon(1e9, 0.0).y, edge);
  EXPECT_EQ(mercator_from_latlon(-90.0, 0.0).y, -edge);
  EXPECT_TRUE(std::isfinite(mercator_from_latlon(std::numeric_limits<double>::infinity(), 0.0).y));
  EXPECT_TRUE(std::isnan(mercator_from_latlon(std::numeric_limits<double>::quiet_NaN(), 0.0).y));
  // Just inside the limit is not clamped.
  EXPECT_LT(mercator_from_latlon(85.0, 0.0).y, edge - 10000.0);
}

TEST(WebMercator, RoundTrip) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> lat(-kMercatorMaxLatDeg, kMercatorMaxLatDeg), lon(-180.0, 180.0);
  for (int i = 0; i < 5000; ++i) {
    const double la = lat(rng), lo = lon(rng);
    const MercatorPoint p = mercator_from_latlon(la, lo);
    const LatLon back = latlon_from_mercator(p.x, p.y);
    EXPECT_NEAR(back.lat, la, 1e-12);
    EXPECT_NEAR(back.lon, lo, 1e-12);
  }
  for (const double la : {kMercatorMaxLatDeg, -kMercatorMaxLatDeg, kMercatorMaxLatDeg - 1e-9, 0.0, 1e-12}) {
    for (const double lo : {-180.0, 180.0, 179.999999999, -179.999999999}) {
      const MercatorPoint p = mercator_from_latlon(la, lo);
      const LatLon back = latlon_from_mercator(p.x, p.y);
      EXPECT_NEAR(back.lat, la, 1e-12);
      EXPECT_NEAR(back.lon, lo, 1e-12);
    }
  }
  // Beyond the limit the round trip lands on it.
  const MercatorPoint pole = mercator_from_latlon(89.0, 10.0);
  EXPECT_NEAR(latlon_from_mercator(pole.x, pole.y).lat, kMercatorMaxLatDeg, 1e-12);
}

TEST(WebMercator, ScaleFactor) {
  EXPECT_DOUBLE_EQ(mercator_scale_factor(0.0), 1.0);
  EXPECT_NEAR(mercator_scale_factor(60.0), 2.0, 1e-12);
  EXPECT_NEAR(mercator_scale_factor(-60.0), 2.0, 1e-12);
  EXPECT_NEAR(mercator_scale_factor(45.0), std::sqrt(2.0), 1e-12);
  // Clamped like the projection: finite at the pole, equal to the value at the limit.
  EXPECT_DOUBLE_EQ(mercator_scale_factor(90.0), mercator_scale_factor(kMercatorMaxLatDeg));
  EXPECT_NEAR(mercator_scale_factor(kMercatorMaxLatDeg), std::cosh(kPi), 1e-9);
  // It is the derivative of the projection: dy/d(ground north) = k, with ground = R dphi.
  for (const double la : {-70.0, -30.0, 0.0, 12.5, 46.686, 80.0}) {
    const double h = 1e-6;  // degrees
    const double dy = mercator_from_latlon(la + h, 0.0).y - mercator_from_latlon(la - h, 0.0).y;
    const double ground = kR * (2.0 * h) * kPi / 180.0;
    EXPECT_NEAR(dy / ground, mercator_scale_factor(la), 1e-6 * mercator_scale_factor(la)) << la;
  }
}

}  // namespace
}  // namespace trailray::geo
