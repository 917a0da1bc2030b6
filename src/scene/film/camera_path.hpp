#pragma once
// A camera path from a file (`trailray video --camera-path FILE`): keyframes at film times, each
// a camera placed as `--camera` places one or a look at a point as `--look-at` does, interpolated
// smoothly between them (Catmull-Rom through the looked-at point, the distance and the angles).
//
// The text, one keyframe a line ('#' starts a comment, blank lines are skipped):
//
//   0s    look-at 46.68,7.86,600 3000 180 -30     # WHEN look-at LAT,LON,ALT DISTANCE HEADING PITCH
//   12s   camera 46.70,7.80,2500,90,-20           # WHEN camera LAT,LON,ALT,HEADING,PITCH
//
// WHEN is a time in the film ("0", "12.5s", "1m30s"), rising from line to line.

#include <string>
#include <string_view>
#include <vector>

#include "scene/camera/camera.hpp"
#include "scene/film/film_camera.hpp"

namespace trailray::scene {

struct CameraKeyframe {
  double film_s = 0.0;
  FilmLook look;
};

// Errors name `name:LINE` and what is wrong there; at least one keyframe is needed.
Result<std::vector<CameraKeyframe>> parse_camera_path(std::string_view text, const std::string& name);

// The look at film time `film_s`: the first keyframe's before it, the last's after it.
FilmLook camera_path_look(const std::vector<CameraKeyframe>& keys, double film_s);

}  // namespace trailray::scene
