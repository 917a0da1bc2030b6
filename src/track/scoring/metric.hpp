#pragma once
// Distances for XC scoring and the bounds the optimiser prunes with.
//
// Two models, both on the WGS84 ellipsoid:
// - Fcc: the FCC closed-form formula (a latitude-dependent flat projection). It is what
//   igc-xc-score uses by default, so scores match its output exactly at 0.01 km per leg.
//   Error against the true geodesic: about 5 m per 100 km.
// - Geodesic: Karney's exact geodesic (GeographicLib via geo/geodesic); equal to Vincenty's
//   (igc-xc-score's `hp=true`) to well under a millimetre.
//
// The optimiser works on index ranges of the fix list; each range has a Box: its latitude and
// longitude extent and a sphere (ECEF, on the ellipsoid surface) that holds its fixes. From two
// boxes it needs an upper and a lower bound of the distance between any fix of one and any fix
// of the other. Why each bound holds is said where it is computed (metric.cpp).

#include <vector>

#include "track/scoring/fixes.hpp"

namespace trailray::track::scoring {

enum class DistanceModel { Fcc, Geodesic };

struct Box {
  double lat_min = 0, lat_max = 0, lon_min = 0, lon_max = 0;  // degrees
  double cx = 0, cy = 0, cz = 0, radius = 0;                  // km, ECEF sphere around the fixes
  // FCC coefficients at the box's smallest and largest |latitude| (see metric.cpp); `side` is
  // +1 or -1 when the whole box lies in one hemisphere, 0 when it touches the equator.
  double k1_at_min = 0, k1_at_max = 0, k2_at_min = 0, k2_at_max = 0;
  int side = 0;
};

class Metric {
 public:
  Metric(const std::vector<Fix>& fixes, DistanceModel model);

  DistanceModel model() const { return model_; }
  // Distance in km between fixes i and j.
  double distance(int i, int j) const;
  // Distance in km between two arbitrary positions (degrees).
  double distance(double lat1, double lon1, double lat2, double lon2) const;
  // Bounds in km on distance(i, j) for every i in the box a and j in the box b.
  double upper(const Box& a, const Box& b) const;
  double lower(const Box& a, const Box& b) const;
  // A box holding one fix.
  const Box& point_box(int i) const { return points_[static_cast<std::size_t>(i)]; }
  // The smallest box holding both.
  static Box merge(const Box& a, const Box& b);
  // Fills the FCC coefficient fields from the latitude extent.
  static void set_coefficients(Box& b);

 private:
  const std::vector<Fix>& fixes_;
  DistanceModel model_;
  std::vector<Box> points_;
  std::vector<double> half_cos_, half_sin_;  // cos and sin of half the latitude, for the FCC mean latitude
};

// The FCC formula on two positions (degrees), km.
double fcc_distance_km(double lat1, double lon1, double lat2, double lon2);

}  // namespace trailray::track::scoring
