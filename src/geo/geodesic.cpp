#include "geo/geodesic.hpp"

#include <GeographicLib/Geodesic.hpp>

namespace trailray::geo {

double geodesic_distance_m(double lat1, double lon1, double lat2, double lon2) {
  if (lat1 == lat2 && lon1 == lon2) return 0.0;  // repeated fixes are common; skip the solver
  double s12 = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(lat1, lon1, lat2, lon2, s12);
  return s12;
}

}  // namespace trailray::geo
