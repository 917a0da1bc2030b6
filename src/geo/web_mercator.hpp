#pragma once
// Spherical Web Mercator (EPSG:3857), the projection behind the XYZ / TMS tile pyramids that
// terrain and imagery sources serve: WGS84 latitude and longitude put on a sphere of radius
// a = 6378137 m and projected conformally. It addresses tiles and pixels; it does not measure
// tracks (geodesic.hpp does): besides the scale factor below, treating the ellipsoid as a sphere
// makes it non-conformal on the Earth by up to about 0.7 %.

#include <numbers>

namespace trailray::geo {

// Projected metres: x east from the Greenwich meridian, y north from the equator.
struct MercatorPoint {
  double x = 0.0, y = 0.0;
};

// Degrees.
struct LatLon {
  double lat = 0.0, lon = 0.0;
};

inline constexpr double kMercatorRadiusM = 6378137.0;  // the WGS84 semi-major axis

// Half the width of the projected world, pi * R = 20037508.342789244 m: longitudes -180..180 map
// to x in [-kMercatorHalfExtentM, kMercatorHalfExtentM].
inline constexpr double kMercatorHalfExtentM = std::numbers::pi * kMercatorRadiusM;

// The latitude at which y reaches kMercatorHalfExtentM: atan(sinh(pi)) = 85.0511287798066
// degrees, usually quoted as 85.05112878. The poles project to infinity, so the tile pyramid cuts
// the world there to make it a square (tile 0/0/0); latitudes beyond are clamped onto its edge.
// The full-precision value is used, not the rounded one: 85.05112878 lies 2e-10 degrees north of
// the edge, outside the pyramid.
inline constexpr double kMercatorMaxLatDeg = 85.051128779806592;

// Latitude clamped to +-kMercatorMaxLatDeg. Longitude is projected as given (x is linear in it,
// no wrapping): tile code wraps it where it needs to. NaN stays NaN.
MercatorPoint mercator_from_latlon(double lat_deg, double lon_deg);

// The inverse; latitudes come out within +-90 for any y (+-kMercatorMaxLatDeg for y within the
// square world), longitude is linear in x (no wrapping).
LatLon latlon_from_mercator(double x_m, double y_m);

// Mercator metres per ground metre at a latitude on the sphere, 1 / cos(lat) (the same east and
// north, the projection being conformal): a 10 m ground distance at 60 N spans 20 Mercator
// metres. The latitude is clamped like mercator_from_latlon's, so the factor stays finite
// (at most about 11.6).
double mercator_scale_factor(double lat_deg);

}  // namespace trailray::geo
