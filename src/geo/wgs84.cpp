#include "geo/wgs84.hpp"

#include <GeographicLib/Geocentric.hpp>

namespace trailray::geo {

glm::dvec3 ecef_from_geodetic(double lat_deg, double lon_deg, double height_m) {
  glm::dvec3 p{};
  GeographicLib::Geocentric::WGS84().Forward(lat_deg, lon_deg, height_m, p.x, p.y, p.z);
  return p;
}

Geodetic geodetic_from_ecef(const glm::dvec3& p) {
  Geodetic g;
  GeographicLib::Geocentric::WGS84().Reverse(p.x, p.y, p.z, g.lat_deg, g.lon_deg, g.height_m);
  return g;
}

}  // namespace trailray::geo
