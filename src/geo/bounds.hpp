#pragma once
// Latitude/longitude bounding box, degrees. Empty until the first point is added.

#include <algorithm>
#include <limits>

namespace trailray::geo {

struct LatLonBounds {
  double min_lat = std::numeric_limits<double>::infinity();
  double min_lon = std::numeric_limits<double>::infinity();
  double max_lat = -std::numeric_limits<double>::infinity();
  double max_lon = -std::numeric_limits<double>::infinity();

  bool empty() const { return min_lat > max_lat; }
  void add(double lat, double lon) {
    min_lat = std::min(min_lat, lat);
    max_lat = std::max(max_lat, lat);
    min_lon = std::min(min_lon, lon);
    max_lon = std::max(max_lon, lon);
  }
};

}  // namespace trailray::geo
