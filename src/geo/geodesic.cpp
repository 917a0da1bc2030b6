#include "geo/geodesic.hpp"

#include <GeographicLib/Geodesic.hpp>

namespace trailray::geo::detail {

double geodesic_inverse_m(double lat1, double lon1, double lat2, double lon2) {
  double s12 = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(lat1, lon1, lat2, lon2, s12);
  return s12;
}

}  // namespace trailray::geo::detail
