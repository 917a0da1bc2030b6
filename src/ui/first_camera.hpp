#pragma once
// The viewer's first camera, the one function every front end calls (the desktop's window and the
// page): the camera asked for (a placement or a look-at), else a framing of the visible tracks
// where the panels and the legend leave the picture free (the largest group of tracks near each
// other when they lie too far apart for one view), else of the waypoints when there is no track.

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "scene/camera/camera.hpp"
#include "scene/camera/framing.hpp"
#include "scene/diagnostics.hpp"
#include "scene/pins/waypoints.hpp"
#include "scene/tracks/track_set.hpp"
#include "ui/framing_room.hpp"

namespace trailray::ui {

// The camera the person asked for (the command line's --camera or --look-at, the page's options).
struct CameraRequest {
  std::optional<scene::CameraPlacement> placement;
  std::optional<scene::LookAt> look_at;
};

// The ground's height at a place (metres; NaN: unknown, the neutral ground stands in).
using GroundHeight = std::function<double(double lat_deg, double lon_deg)>;

class FirstCameraError : public std::runtime_error {
 public:
  FirstCameraError(std::string option, std::string why)
      : std::runtime_error(option.empty() ? why : option + ": " + why), option_(std::move(option)), why_(std::move(why)) {}
  // "--camera" or "--look-at" when the request could not be made, "" when nothing could be framed.
  const std::string& option() const { return option_; }
  const std::string& why() const { return why_; }  // without the option's name

 private:
  std::string option_, why_;
};

// The first camera. `ground`: the height under a requested camera (none: the neutral ground).
// Throws FirstCameraError when the request makes no camera or there is nothing to frame.
// The warning that only a group of the tracks is framed goes to `diagnostics` (may be null).
scene::Camera first_camera(const CameraRequest& request, const scene::Lens& lens, const scene::TrackSet& tracks,
                           const scene::WaypointSet* waypoints, double neutral_ground_m, const GroundHeight& ground,
                           const FramingRoom& room, scene::Diagnostics* diagnostics = nullptr);

// The same as the viewer's orbit pivot: the requested look-at as it is, else the first camera
// with its pivot where the view's centre meets the neutral ground (no tile read for it).
// nullopt when nothing was asked for and there is nothing to frame (no track, no waypoint).
std::optional<scene::LookAt> first_view(const CameraRequest& request, const scene::Lens& lens,
                                        const scene::TrackSet& tracks, const scene::WaypointSet& waypoints,
                                        double neutral_ground_m, const GroundHeight& ground, const FramingRoom& room,
                                        scene::Diagnostics* diagnostics = nullptr);

}  // namespace trailray::ui
