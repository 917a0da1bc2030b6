#pragma once
// The shape of a draw's capsules (track_pass.hpp TrackDraw): what routes and pins change.

#include <optional>

#include "scene/style.hpp"

namespace trailray::render {

// How a draw's capsules differ from a recorded track's (the pass settings'): a route is thinner
// and dashed, a pin's stem and ball have widths of their own and stand raised above the ground.
struct CapsuleShape {
  std::optional<scene::TrackWidth> width;  // else the settings' width
  std::optional<double> min_width_px;      // else the settings' minimum
  // > 0: dashed along the line, dashes and gaps of about this many pixels (a power of two of
  // metres, so the pattern holds still while the camera moves); the buffer's values are the
  // metres along the line.
  float dash_px = 0.0f;
  // Each segment's last point is raised along the local vertical by max(lift_px pixels, lift_m):
  // a pin's stem reaches up to its ball (a segment of one point), which rests on it.
  float lift_px = 0.0f, lift_m = 0.0f;
  // How a segment's points make capsules: a polyline (a track), or standing alone, so that
  // thousands of pins are one draw: pairs (points 2k, 2k+1: stems) or singles (each point: balls).
  enum class Capsules { polyline = 0, pairs = 1, singles = 2 };
  Capsules capsules = Capsules::polyline;
};

}  // namespace trailray::render
