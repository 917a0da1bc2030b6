#include "track/task/earth.hpp"

#include <GeographicLib/Geodesic.hpp>

#include <cmath>

#include "geo/geodesic.hpp"
#include "geo/wgs84.hpp"

namespace trailray::track::task {

namespace {

constexpr double kRad = 3.14159265358979323846 / 180.0;

double haversine_m(const geo::LatLon& a, const geo::LatLon& b) {
  const double p1 = a.lat * kRad, p2 = b.lat * kRad;
  const double dp = p2 - p1, dl = (b.lon - a.lon) * kRad;
  const double h =
      std::sin(dp / 2) * std::sin(dp / 2) + std::cos(p1) * std::cos(p2) * std::sin(dl / 2) * std::sin(dl / 2);
  return 2.0 * kFaiSphereRadiusM * std::asin(std::sqrt(std::fmin(1.0, h)));
}

}  // namespace

double Earth::distance_m(const geo::LatLon& a, const geo::LatLon& b) const {
  if (model_ == EarthModel::FaiSphere) return haversine_m(a, b);
  return geo::geodesic_distance_m(a.lat, a.lon, b.lat, b.lon);
}

geo::LatLon Earth::destination(const geo::LatLon& from, double azimuth_deg, double distance_m) const {
  if (model_ == EarthModel::FaiSphere) {
    const double p1 = from.lat * kRad, l1 = from.lon * kRad, az = azimuth_deg * kRad;
    const double d = distance_m / kFaiSphereRadiusM;
    const double sp2 = std::sin(p1) * std::cos(d) + std::cos(p1) * std::sin(d) * std::cos(az);
    const double p2 = std::asin(std::fmax(-1.0, std::fmin(1.0, sp2)));
    const double l2 =
        l1 + std::atan2(std::sin(az) * std::sin(d) * std::cos(p1), std::cos(d) - std::sin(p1) * std::sin(p2));
    return {p2 / kRad, geo::wgs84::wrap_dlon_deg(l2 / kRad)};
  }
  geo::LatLon out;
  GeographicLib::Geodesic::WGS84().Direct(from.lat, from.lon, azimuth_deg, distance_m, out.lat, out.lon);
  return out;
}

double Earth::azimuth_deg(const geo::LatLon& from, const geo::LatLon& to) const {
  if (from.lat == to.lat && from.lon == to.lon) return 0.0;
  if (model_ == EarthModel::FaiSphere) {
    const double p1 = from.lat * kRad, p2 = to.lat * kRad, dl = (to.lon - from.lon) * kRad;
    return std::atan2(std::sin(dl) * std::cos(p2),
                      std::cos(p1) * std::sin(p2) - std::sin(p1) * std::cos(p2) * std::cos(dl)) /
           kRad;
  }
  double s12 = 0.0, azi1 = 0.0, azi2 = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(from.lat, from.lon, to.lat, to.lon, s12, azi1, azi2);
  return azi1;
}

}  // namespace trailray::track::task
