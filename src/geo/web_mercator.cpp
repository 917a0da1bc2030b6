#include "geo/web_mercator.hpp"

#include <algorithm>
#include <cmath>

namespace trailray::geo {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;
constexpr double kDegPerRad = 180.0 / std::numbers::pi;

// std::clamp would turn NaN into a bound (the comparisons fail); keep it NaN instead.
double clamp_lat(double lat_deg) {
  if (std::isnan(lat_deg)) return lat_deg;
  return std::clamp(lat_deg, -kMercatorMaxLatDeg, kMercatorMaxLatDeg);
}

}  // namespace

MercatorPoint mercator_from_latlon(double lat_deg, double lon_deg) {
  const double phi = clamp_lat(lat_deg) * kRadPerDeg;
  // asinh(tan(phi)) is ln(tan(pi/4 + phi/2)) without the cancellation of the logarithm near 1
  // at the equator.
  return MercatorPoint{kMercatorRadiusM * lon_deg * kRadPerDeg, kMercatorRadiusM * std::asinh(std::tan(phi))};
}

LatLon latlon_from_mercator(double x_m, double y_m) {
  return LatLon{std::atan(std::sinh(y_m / kMercatorRadiusM)) * kDegPerRad, x_m / kMercatorRadiusM * kDegPerRad};
}

double mercator_scale_factor(double lat_deg) { return 1.0 / std::cos(clamp_lat(lat_deg) * kRadPerDeg); }

}  // namespace trailray::geo
