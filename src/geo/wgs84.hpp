#pragma once
// WGS84 ellipsoid constants and the local metric at a latitude: the meridional radius of
// curvature M and the prime-vertical radius N, which turn small latitude / longitude
// differences into metres (north = M * dlat, east = N * cos(lat) * dlon, angles in radians).
// Also a cheap sine / cosine for latitudes, used on hot paths instead of libm's, and the
// conversions between geodetic positions and Earth-centred, Earth-fixed coordinates.

#include <glm/vec3.hpp>

#include <cmath>
#include <numbers>

namespace trailray::geo::wgs84 {

inline constexpr double kA = 6378137.0;            // semi-major axis, metres
inline constexpr double kF = 1.0 / 298.257223563;  // flattening
inline constexpr double kE2 = kF * (2.0 - kF);     // first eccentricity squared
inline constexpr double kRadPerDeg = std::numbers::pi / 180.0;

// sin and cos of x in radians for |x| <= pi/2 (a latitude): polynomials of degree 8 in x^2
// (Chebyshev fits on that range, truncation below 1e-17), evaluated by Estrin's scheme for a
// short dependency chain; within 4e-16 of libm. Inline arithmetic without range reduction or a
// call, so loops around them stay short and can be vectorised. Outside the range the error
// grows quickly: do not use them there.
inline double sin_lat(double x) {
  const double u = x * x, u2 = u * u, u4 = u2 * u2, u8 = u4 * u4;
  const double p01 = 1.0 - 1.6666666666666665307e-01 * u;
  const double p23 = 8.3333333333331863840e-03 - 1.9841269841208675170e-04 * u;
  const double p45 = 2.7557319211229606622e-06 - 2.5052106890569519539e-08 * u;
  const double p67 = 1.6058940878486559931e-10 - 7.6430265579716326635e-13 * u;
  const double p8 = 2.7215749422983442826e-15;
  return x * ((p01 + p23 * u2) + (p45 + p67 * u2) * u4 + p8 * u8);
}
inline double cos_lat(double x) {
  const double u = x * x, u2 = u * u, u4 = u2 * u2, u8 = u4 * u4;
  const double p01 = 1.0 - 4.9999999999999974243e-01 * u;
  const double p23 = 4.1666666666663882340e-02 - 1.3888888888772989911e-03 * u;
  const double p45 = 2.4801587277414924404e-05 - 2.7557316391025750805e-07 * u;
  const double p67 = 2.0876561839933163279e-09 - 1.1462901901757274785e-11 * u;
  const double p8 = 4.6089770030017970304e-14;
  return (p01 + p23 * u2) + (p45 + p67 * u2) * u4 + p8 * u8;
}

// Squares of the radii of curvature at a latitude, from sin^2 of the latitude (no square root):
// M = a (1 - e^2) / W^3 (metres per radian of latitude), N = a / W (metres per radian of
// longitude, divided by cos(latitude)), W^2 = 1 - e^2 sin^2(latitude).
struct RadiiSquared {
  double meridional_m2;
  double prime_vertical_m2;
};
inline RadiiSquared radii_squared_from_sin2(double sin2_lat) {
  const double inv_w2 = 1.0 / (1.0 - kE2 * sin2_lat);
  const double n2 = (kA * kA) * inv_w2;
  return RadiiSquared{n2 * ((1.0 - kE2) * (1.0 - kE2)) * (inv_w2 * inv_w2), n2};
}

// A longitude difference in degrees brought into [-180, 180] by one turn at most (enough for
// the difference of two longitudes in [-180, 180]; larger inputs stay outside the range).
inline double wrap_dlon_deg(double dlon) {
  if (dlon > 180.0) return dlon - 360.0;
  if (dlon < -180.0) return dlon + 360.0;
  return dlon;
}

}  // namespace trailray::geo::wgs84

namespace trailray::geo {

// A geodetic position: degrees, and metres above the WGS84 ellipsoid.
struct Geodetic {
  double lat_deg = 0.0, lon_deg = 0.0, height_m = 0.0;
};

// Earth-centred, Earth-fixed (ECEF, WGS84) coordinates in metres of a geodetic position, and
// back: the exact conversions (GeographicLib), the one place in the program that does them.
// ECEF points and directions are glm::dvec3 throughout.
glm::dvec3 ecef_from_geodetic(double lat_deg, double lon_deg, double height_m);
Geodetic geodetic_from_ecef(const glm::dvec3& p);

}  // namespace trailray::geo
