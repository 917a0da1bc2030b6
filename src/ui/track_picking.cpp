#include "ui/track_picking.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace trailray::ui {

std::optional<glm::dvec2> screen_position(const scene::Camera& camera, const glm::dvec3& ecef) {
  const auto p = camera.project(ecef);
  if (!p) return std::nullopt;
  return glm::dvec2(p->x_px, p->y_px);
}

HoverState pick_track_point(const scene::TrackSet& tracks, const scene::Camera& camera, double x_px, double y_px,
                            double radius_px, std::optional<double> ground_depth_m) {
  // A point on the ground must not count as hidden by the ground it lies on: a few metres, and
  // a little more far away where the terrain mesh is coarser.
  const auto hidden = [&](double depth_m) {
    return ground_depth_m && depth_m > *ground_depth_m + std::max(5.0, 0.003 * *ground_depth_m);
  };
  HoverState best;
  bool best_hidden = true;
  double best_px = radius_px, best_depth = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < tracks.size(); ++t) {
    if (!tracks[t].visible) continue;
    // Flat point numbers run through the segments' polylines in order.
    std::size_t i = 0;
    for (const scene::TrackPolyline& line : tracks[t].geometry.segments)
      for (const glm::dvec3& point : line.points_ecef) {
        const auto p = camera.project(point);
        ++i;
        if (!p) continue;
        const double d = std::hypot(p->x_px - x_px, p->y_px - y_px);
        if (d > radius_px) continue;
        const bool h = hidden(p->depth_m);
        const bool better = best.track < 0 || (best_hidden && !h) ||
                            (h == best_hidden && (d < best_px || (d == best_px && p->depth_m < best_depth)));
        if (better) {
          best_hidden = h;
          best_px = d;
          best_depth = p->depth_m;
          best.track = static_cast<int>(t);
          best.point = i - 1;
        }
      }
  }
  return best;
}

}  // namespace trailray::ui
