#pragma once
// A track as the renderer draws it: per segment its points in ECEF (double) with the colour
// attribute and the curtain's heights (render/passes/track_buffer.hpp uploads it).

#include <glm/glm.hpp>

#include <vector>

namespace trailray::scene {

// One segment of a track: its points in ECEF (metres, double), and per point the colour
// attribute (empty: no values; NaN: that point has none) and the height above the ground for
// the curtain (empty: no curtain; NaN: none at that point).
struct TrackPolyline {
  std::vector<glm::dvec3> points_ecef;
  std::vector<float> values;
  std::vector<float> heights_above_ground_m;
};

struct TrackGeometry {
  std::vector<TrackPolyline> segments;
};

}  // namespace trailray::scene
