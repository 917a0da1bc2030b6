#pragma once
// Tracks loaded for a viewer, as every front end hands them to its session
// (ui::ViewerSession::adopt): the desktop reads files on its cores (app/view/track_loading), the
// page the bytes its JavaScript passes in. What went wrong stays with them, for the window.

#include <string>
#include <vector>

#include "scene/pins/waypoints.hpp"
#include "scene/tracks/track_files.hpp"
#include "scene/tracks/track_set.hpp"

namespace trailray::ui {

struct LoadedTracks {
  std::vector<scene::Track> tracks;
  std::vector<scene::Waypoint> waypoints;  // the files' waypoints (scene::file_waypoints), thermal markers
  scene::RecordedPoints recorded;          // the readable files' points (framing, the sun's time)
  std::vector<std::string> errors;         // one per file that failed, naming it
  std::vector<std::string> warnings;       // of reading and of building the tracks
};

}  // namespace trailray::ui
