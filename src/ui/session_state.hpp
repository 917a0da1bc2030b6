#pragma once
// What a viewer shows, as JSON, the same from every front end (the desktop's script command
// `print-state`, the page's status): so a test drives both through one script of inputs and
// compares what they show.
//
//   {"tracks": [{"name", "points", "visible"}...], "selected_track": N,
//    "statistics": [the Statistics panel's lines for the selected track],
//    "hover": {"track": N (-1: none), "point", "waypoint", "airspace", "name", "lines": [tooltip]},
//    "camera": {"lat", "lon", "height", "distance", "heading", "pitch"} or null (none placed),
//    "enlarged_photo": {"waypoint", "name"} or null, "waypoints": N,
//    "replay": {"time", "playing"}, "warnings": [...], "errors": [...]}
//
// Numbers are rounded as `print-camera` prints them (degrees to 1e-6, metres to 0.1, angles to
// 0.01), so two front ends that agree to the printed digits give the same text.

#include <string>

#include "ui/viewer_session.hpp"

namespace trailray::ui {

std::string session_state_json(const ViewerSession& session);

}  // namespace trailray::ui
