#pragma once
// A uniform grid over the airspaces' bounding boxes (cells of kCellDeg degrees), so a point is
// tested against the few airspaces whose box covers its cell instead of all of them: a
// country's file (several hundred airspaces) against a 10-hour 1 Hz flight takes milliseconds.
//
// Geometry: a boundary's edges are straight lines in latitude/longitude (OpenAir gives no other
// rule; arcs are already points at most 1 m from the true arc). A boundary across the
// antimeridian has continuous longitudes (past +-180, see airspace.hpp): a point is compared with
// it a whole turn away where that brings it into the box. Distances to the boundary are geodesic
// (see depth_inside_m).

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "track/airspace/airspace.hpp"

namespace trailray::track::airspace {

struct BoundingBox {
  double lat_min = 0, lat_max = 0, lon_min = 0, lon_max = 0;
  bool contains(double lat, double lon) const {
    return lat >= lat_min && lat <= lat_max && lon >= lon_min && lon <= lon_max;
  }
};

class AirspaceIndex {
 public:
  static constexpr double kCellDeg = 0.2;

  explicit AirspaceIndex(const AirspaceFile& file);

  const AirspaceFile& file() const { return file_; }
  const BoundingBox& box(std::size_t airspace) const { return boxes_[airspace]; }

  // Airspaces whose bounding box may hold (lat, lon); empty when none. The list is shared: do
  // not keep it across calls.
  const std::vector<std::uint32_t>& candidates(double lat, double lon) const;

  // Whether (lat, lon) lies inside the airspace's boundary (even-odd rule; any longitude).
  bool contains(std::size_t airspace, double lat, double lon) const;

  // Geodesic distance in metres from (lat, lon) to the nearest point of the boundary.
  double distance_to_boundary_m(std::size_t airspace, double lat, double lon) const;

 private:
  static std::int64_t cell_key(std::int64_t x, std::int64_t y) { return (x << 32) ^ (y & 0xffffffff); }

  const AirspaceFile& file_;
  std::vector<BoundingBox> boxes_;
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> cells_;
  std::vector<std::uint32_t> wide_;  // boxes too big for the grid: tested everywhere
  mutable std::vector<std::uint32_t> scratch_;
};

}  // namespace trailray::track::airspace
