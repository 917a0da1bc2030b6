#include "geo/wgs84.hpp"

#include <gtest/gtest.h>

#include <GeographicLib/Geocentric.hpp>

namespace trailray::geo {
namespace {

TEST(Wgs84, EcefFromGeodeticIsGeographicLibs) {
  double x = 0, y = 0, z = 0;
  GeographicLib::Geocentric::WGS84().Forward(46.68, 7.86, 3000.0, x, y, z);
  const glm::dvec3 p = ecef_from_geodetic(46.68, 7.86, 3000.0);
  EXPECT_DOUBLE_EQ(p.x, x);
  EXPECT_DOUBLE_EQ(p.y, y);
  EXPECT_DOUBLE_EQ(p.z, z);
}

TEST(Wgs84, GeodeticFromEcefRoundTrips) {
  for (double lat : {-89.9, -45.0, 0.0, 46.68, 89.9}) {
    for (double lon : {-179.9, -7.5, 0.0, 7.86, 179.9}) {
      for (double h : {-400.0, 0.0, 3000.0, 400000.0}) {
        const Geodetic g = geodetic_from_ecef(ecef_from_geodetic(lat, lon, h));
        EXPECT_NEAR(g.lat_deg, lat, 1e-12);
        EXPECT_NEAR(g.lon_deg, lon, 1e-12);
        EXPECT_NEAR(g.height_m, h, 1e-6);
      }
    }
  }
}

}  // namespace
}  // namespace trailray::geo
