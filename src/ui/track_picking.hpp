#pragma once
// Which track point is under the cursor in the 3D view: the visible tracks' points projected
// with the camera on the CPU (their geometry), the nearest one to the cursor within a few
// pixels. Points hidden by terrain count too (the track pass shows them as ghosts), but one in
// front of the terrain wins: where a track passes in front of a ridge and again behind it, the
// cursor on the near pass reads the near pass.

#include <glm/glm.hpp>

#include <optional>
#include <vector>

#include "scene/camera/camera.hpp"
#include "ui/viewer_model.hpp"

namespace trailray::ui {

inline constexpr double kPickRadiusPx = 8.0;

// The nearest track point of a visible track within `radius_px` of pixel (x, y); among points at
// the same pixel distance, the one nearer the camera. `ground_depth_m`: the view depth of the
// terrain under the cursor (nullopt: none, nothing is hidden); points behind it by more than a
// small tolerance are taken only when no point in front is within the radius.
// HoverState::track is -1 when there is none.
HoverState pick_track_point(const scene::TrackSet& tracks, const scene::Camera& camera, double x_px, double y_px,
                            double radius_px = kPickRadiusPx, std::optional<double> ground_depth_m = std::nullopt);

// Where an ECEF point appears (pixel), nullopt behind the camera.
std::optional<glm::dvec2> screen_position(const scene::Camera& camera, const glm::dvec3& ecef);

}  // namespace trailray::ui
