#pragma once
// The viewer's camera as a person moves it: a pivot on the ground, and the camera at a distance
// from it with a heading and pitch (scene::LookAt). Mouse and keyboard gestures change those:
//
//   orbit   left drag: heading and pitch around the pivot
//   pan     right drag: the ground point under the cursor follows the cursor
//   zoom    wheel: the distance shrinks or grows toward the ground point under the cursor,
//           which stays under the cursor (the whole view is scaled about that point)
//   tilt    keyboard: pitch
//   move    keyboard: the pivot slides in the view's heading, by a fraction of the distance
//   fly_to  an animated flight to another view (a track, a double-clicked point, north up)
//
// The camera never goes below the ground: after each change it is lifted (steeper pitch, then
// a longer distance) to stay `clearance_m` above the ground function's height under it.
// No window, GL or ImGui here: the math is tested alone (tests/scene/camera/camera_controller_test),
// and every front end (the desktop viewer, the page) moves its camera with it.

#include <functional>
#include <optional>

#include "scene/camera/camera.hpp"

namespace trailray::scene {

// The terrain height at a place, metres (NaN: unknown there). Must not block (the frame loop
// calls it): the viewer passes the heights of tiles already in memory.
using GroundFunction = std::function<double(double lat_deg, double lon_deg)>;

struct CameraControls {
  double orbit_deg_per_px = 0.25;
  double zoom_factor_per_step = 0.8;  // the distance is multiplied by this per wheel step in
  double min_distance_m = 10.0, max_distance_m = 3.0e6;
  double min_pitch_deg = -89.0, max_pitch_deg = -1.0;
  double clearance_m = 5.0;  // the camera stays this far above the ground at least
  double fly_seconds = 1.2;  // duration of an animated flight
};

class CameraController {
 public:
  CameraController(const scene::LookAt& view, const scene::Lens& lens, GroundFunction ground = {},
                   const CameraControls& controls = {});

  // The look-at that reproduces `camera`: the pivot where its centre ray meets the ground at
  // `ground_height_m` (the ellipsoid raised by it), else a point `fallback_distance_m` ahead.
  static scene::LookAt look_at_from_camera(const scene::Camera& camera, double ground_height_m,
                                           double fallback_distance_m = 1000.0);

  const scene::LookAt& view() const { return view_; }
  const scene::Lens& lens() const { return lens_; }
  void set_image_size(std::uint32_t width_px, std::uint32_t height_px);
  void set_ground(GroundFunction ground) { ground_ = std::move(ground); }
  // The renderer's camera for the current view.
  scene::Camera camera() const;

  void orbit(double dx_px, double dy_px);
  void pan(double from_x_px, double from_y_px, double to_x_px, double to_y_px);
  // steps > 0 zooms in (closer), < 0 out; toward the ground under pixel (x, y).
  void zoom(double steps, double x_px, double y_px);
  void tilt(double degrees);
  // Moves the pivot `right` and `forward` (fractions of the distance) in the view's heading.
  void move(double right, double forward);
  // Replay's camera follow: the pivot jumps to `pivot` (the marker) each frame; with a heading
  // (chase) the camera also turns to look along it, from behind.
  void follow(const scene::GeoPosition& pivot, std::optional<double> heading_deg = std::nullopt);
  void reset_north();  // an animated turn to heading 0
  void fly_to(const scene::LookAt& target);
  bool animating() const { return flight_.has_value(); }
  // Advances a flight by `seconds` of wall time.
  void update(double seconds);
  // Where the ray through pixel (x, y) first meets the ground (the ground function where it
  // knows the height, else the pivot's height); nullopt when the ray does not come down to it.
  std::optional<scene::GeoPosition> ground_point_at(double x_px, double y_px) const;

 private:
  struct Flight {
    scene::LookAt from, to;
    double elapsed_s = 0.0;
  };
  double ground_at(double lat_deg, double lon_deg) const;  // the ground function, NaN-safe
  void keep_above_ground();
  void set_target_on_ground();  // the pivot's height from the ground function, where known

  scene::LookAt view_;
  scene::Lens lens_;
  GroundFunction ground_;
  CameraControls controls_;
  std::optional<Flight> flight_;
};

}  // namespace trailray::scene
