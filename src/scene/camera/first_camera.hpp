#pragma once
// The first camera, the one rule every front end follows (`render`, `video`, the film of the
// viewer's "record film", the desktop viewer and the page): the camera asked for (a placement or a
// look-at, standing on the ground's height there), else a framing of the visible tracks into the
// part of the picture the front end leaves free (the largest group of tracks near each other
// when they lie too far apart for one view, with a warning), else of the waypoints when there is
// no track point.

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "scene/camera/camera.hpp"
#include "scene/camera/framing.hpp"
#include "scene/diagnostics.hpp"
#include "scene/pins/waypoints.hpp"
#include "scene/tracks/track_set.hpp"

namespace trailray::scene {

// The camera the person asked for (the command line's --camera or --look-at, the page's options);
// neither: frame the tracks.
struct CameraRequest {
  std::optional<CameraPlacement> placement;
  std::optional<LookAt> look_at;
};

// The ground's height at a place in metres (NaN: unknown; the neutral ground stands in).
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

// Where the framing may put the tracks: out of `keep_clear` (the legend's corner), into `area` of
// the picture (nullopt: all of it).
struct FramingSpace {
  KeptClearCorner keep_clear;
  std::optional<ImageArea> area;
};

// The first camera. `ground`: the height under a requested camera (unset: the neutral ground).
// Throws FirstCameraError when the request makes no camera or there is nothing to frame; the
// warning that only a group of the tracks is framed goes to `diagnostics` (may be null).
Camera first_camera(const CameraRequest& request, const Lens& lens, const TrackSet& tracks,
                    const WaypointSet* waypoints, double neutral_ground_m, const GroundHeight& ground,
                    const FramingSpace& space = {}, Diagnostics* diagnostics = nullptr);

}  // namespace trailray::scene
