#include "geo/geodesic.hpp"

#include <gtest/gtest.h>

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
