#pragma once
// The viewer's first view: the first camera every front end makes (scene/camera/first_camera:
// the camera asked for, else the tracks framed) with the framing kept where the viewer's panels
// and legend leave the window free, and its orbit pivot placed; the desktop's window and the page
// both call it through ViewerSession::place_first_camera.

#include <optional>

#include "scene/camera/camera.hpp"
#include "scene/camera/first_camera.hpp"
#include "scene/diagnostics.hpp"
#include "scene/pins/waypoints.hpp"
#include "scene/tracks/track_set.hpp"
#include "ui/framing_room.hpp"

namespace trailray::ui {

using CameraRequest = scene::CameraRequest;
using GroundHeight = scene::GroundHeight;
using FirstCameraError = scene::FirstCameraError;

// The requested look-at as it is, else the first camera (framed into `room`) with its pivot where
// the view's centre meets the neutral ground (no tile read for it). nullopt when nothing was
// asked for and there is nothing to frame (no track, no waypoint). Throws FirstCameraError.
std::optional<scene::LookAt> first_view(const CameraRequest& request, const scene::Lens& lens,
                                        const scene::TrackSet& tracks, const scene::WaypointSet& waypoints,
                                        double neutral_ground_m, const GroundHeight& ground, const FramingRoom& room,
                                        scene::Diagnostics* diagnostics = nullptr);

}  // namespace trailray::ui
