#pragma once
// What a viewer is, once for every front end (the desktop's window, app/view/, and the page,
// web/): the model the panels edit (tracks, waypoints, volumes, settings, hover, selection,
// replay clock), the camera that moves over it, and what the person's input does to them: hover
// and picking over pins, tracks and airspace walls, keys and mouse gestures, flights to a track,
// a waypoint or a photo (shown larger), the replay's camera follow, and the panels' actions.
// GL-free: a front end hands it input (its own key codes mapped to ViewerKey, pixels of the
// picture), time (seconds since the last frame) and what it lays out itself (the room its panels
// and legend leave for a framing), draws what it holds, and shows its state
// (session_state.hpp).

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "scene/camera/camera.hpp"
#include "scene/camera/camera_controller.hpp"
#include "scene/diagnostics.hpp"
#include "scene/volumes/volume_shapes.hpp"
#include "ui/first_camera.hpp"
#include "ui/framing_room.hpp"
#include "ui/loaded_tracks.hpp"
#include "ui/viewer_keys.hpp"
#include "ui/viewer_model.hpp"
#include "ui/viewer_panels.hpp"

namespace trailray::ui {

// One frame of the mouse over the picture (not over a panel: the front end asks its interface
// first), in the picture's pixels (device pixels, y down).
struct PointerInput {
  glm::dvec2 position{-1.0};  // negative: outside the picture
  glm::dvec2 delta{0.0};      // moved since the last frame
  bool left_down = false, right_down = false;
  bool left_clicked = false, left_double_clicked = false;
  double wheel = 0.0;  // steps, positive: toward the picture (zoom in)
};

// Where a framing may put the tracks (the panels' and the legend's room), for the picture's lens.
using FramingRoomFunction = std::function<FramingRoom(const scene::Lens& lens)>;
// Makes a photo's picture larger for its enlarged pin (the desktop decodes the file again at
// `long_side_px`); a front end that fetches it later (the page asks its URL) leaves this unset.
using LargerPhotoFunction = std::function<void(scene::Waypoint& photo, int long_side_px)>;

class ViewerSession {
 public:
  ViewerModel& model() { return model_; }
  const ViewerModel& model() const { return model_; }

  // The camera, once placed (the page has none until there is something to look at).
  bool has_camera() const { return camera_.has_value(); }
  scene::CameraController& camera() { return *camera_; }
  const scene::CameraController& camera() const { return *camera_; }
  void place_camera(const scene::LookAt& view, const scene::Lens& lens);
  // The first view (first_camera.hpp) for `lens` with the front end's framing room; false (and no
  // camera) when nothing was asked for and there is nothing to frame. Throws FirstCameraError.
  bool place_first_camera(const CameraRequest& request, const scene::Lens& lens,
                          scene::Diagnostics* diagnostics = nullptr);

  // The ground's height where known (the terrain in memory; NaN elsewhere): the camera keeps
  // above it, the hover's terrain hides track points behind it, a flight's pivot stands on it.
  // Unset: the camera knows no ground (the pivot's height stands in).
  void set_ground(GroundHeight ground);
  void set_framing_room(FramingRoomFunction room) { framing_room_ = std::move(room); }
  void set_larger_photo(LargerPhotoFunction larger) { larger_photo_ = std::move(larger); }
  FramingRoom framing_room(const scene::Lens& lens) const;

  // Tracks loaded: added to those open (density and thermal counts done again over all of them),
  // their waypoints to the pins, their errors to the model's (shown in a window) and their
  // warnings to warnings(). The first track becomes the selected one.
  void adopt(LoadedTracks loaded);
  // Every track built again (the page, after an option or a file): replaces the tracks, the
  // hover and the chart's selection; the warnings are these.
  void replace_tracks(LoadedTracks loaded);
  const std::vector<std::string>& warnings() const { return warnings_; }

  // The hover at pixel (x, y) of the picture with `camera` (the camera now when not given): a
  // pin's ball first, then the nearest track point (one in front of the terrain before one behind
  // it), then an airspace's wall in front of the terrain. A point the chart set stays while the
  // cursor is over no track.
  void hover_at(double x_px, double y_px);
  void hover_at(double x_px, double y_px, const scene::Camera& camera);
  void clear_hover();  // the pointer left the picture (a point the chart set stays)

  // One frame's keys (viewer_keys.hpp), `seconds` the frame's time; true while one that moves
  // the camera is held (the front end keeps drawing frames).
  bool keys(const KeyInput& keys, double seconds);
  // One frame of the mouse over the picture: a click on a photo's pin shows it larger and flies
  // there, a double click flies to the ground point, a left drag orbits, a right drag pans, the
  // wheel zooms toward the pointer; with no button held the hover follows it.
  void pointer(const PointerInput& pointer);
  void click(double x_px, double y_px);         // a photo's pin there: fly_to_waypoint
  void double_click(double x_px, double y_px);  // fly to the ground there, half as far
  void orbit(double dx_px, double dy_px);
  void pan(double from_x_px, double from_y_px, double to_x_px, double to_y_px);
  void zoom(double steps, double x_px, double y_px);

  // The camera's flight, `seconds` on.
  void update(double seconds);
  // The replay's camera follow (replay_follow.hpp); true when it moved the camera.
  bool follow_replay();
  // What the panels asked for this frame: flights to a track, a waypoint, a thermal's marker (a
  // film is the front end's).
  void apply(const PanelActions& actions);
  // Flies so that track `index` fills the framing room (from the heading now).
  void fly_to_track(int index);
  // Flies to waypoint `index` (a photo's: shown larger too).
  void fly_to_waypoint(int index);
  // The photo of waypoint `index` shown larger over its pin, every other photo at its thumbnail's
  // size; its picture made larger through set_larger_photo's function when it is too small.
  void enlarge_photo(int index);
  int enlarged_photo() const;  // the waypoint shown larger, -1: none

  // How often the person's input moved the camera (gestures, keys, flights begun, the follow; not
  // its placing): a front end that draws only on change compares it with the last it saw.
  std::uint64_t camera_moves() const { return camera_moves_; }

 private:
  // The airspace wall under the pixel, in front of the terrain `ground_m` away (infinity: none).
  int pick_airspace(double x_px, double y_px, const scene::Camera& camera, double ground_m);
  std::optional<double> ground_at(double lat_deg, double lon_deg) const;

  ViewerModel model_;
  std::optional<scene::CameraController> camera_;
  GroundHeight ground_;
  FramingRoomFunction framing_room_;
  LargerPhotoFunction larger_photo_;
  std::vector<std::string> warnings_;
  // The airspaces' walls as the hover picks them, made again when the set's revision changes.
  std::vector<scene::VolumeShape> volume_shapes_;
  std::uint64_t volume_shapes_revision_ = ~std::uint64_t{0};
  std::uint64_t camera_moves_ = 0;
};

}  // namespace trailray::ui
