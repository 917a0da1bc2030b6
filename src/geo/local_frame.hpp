#pragma once
// A local east-north-up Cartesian frame (metres) tangent to the WGS84 ellipsoid at an
// origin. Used where metric operations (smoothing, slopes) need a flat frame.

#include <GeographicLib/LocalCartesian.hpp>

namespace trailray::geo {

struct Enu {
  double east = 0.0, north = 0.0, up = 0.0;
};

class LocalFrame {
 public:
  LocalFrame(double lat0, double lon0, double h0 = 0.0) : cartesian_(lat0, lon0, h0) {}

  Enu to_local(double lat, double lon, double h) const {
    Enu e;
    cartesian_.Forward(lat, lon, h, e.east, e.north, e.up);
    return e;
  }
  void to_geodetic(const Enu& e, double& lat, double& lon, double& h) const {
    cartesian_.Reverse(e.east, e.north, e.up, lat, lon, h);
  }

 private:
  GeographicLib::LocalCartesian cartesian_;
};

}  // namespace trailray::geo
