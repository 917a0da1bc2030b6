#pragma once
// The script commands (view_script.hpp) that act on the viewer's session, carried out the same
// way by every front end: the desktop's `view --script` and the page's trailray_run_script, so one
// script of inputs drives both and what they print can be compared.

#include <optional>
#include <string>

#include "ui/view_script.hpp"
#include "ui/viewer_session.hpp"

namespace trailray::ui {

// Carries out `command` on the session: orbit, pan, zoom, select, select-waypoint (flights arrive
// at once), play, speed, and the prints (print-waypoints, print-hover, print-marker,
// print-camera, print-state). Returns what it prints (lines ending in '\n'; "" for none), nullopt
// for a command that is the front end's (hover, frames, pictures, panels, films). Throws
// ScriptError "FILE:LINE: ..." for a track or waypoint that is not there, or when there is no
// camera yet for a command that needs one.
std::optional<std::string> run_session_command(ViewerSession& session, const ScriptCommand& command,
                                               const std::string& file);

}  // namespace trailray::ui
