#include "ui/viewer_session.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

#include "scene/camera/framing.hpp"
#include "ui/replay_follow.hpp"
#include "ui/track_picking.hpp"
#include "ui/waypoint_view.hpp"

namespace trailray::ui {
namespace {

bool same_view(const scene::LookAt& a, const scene::LookAt& b) {
  return a.target.lat_deg == b.target.lat_deg && a.target.lon_deg == b.target.lon_deg &&
         a.target.height_m == b.target.height_m && a.heading_deg == b.heading_deg && a.distance_m == b.distance_m &&
         a.pitch_deg == b.pitch_deg;
}

}  // namespace

void ViewerSession::place_camera(const scene::LookAt& view, const scene::Lens& lens) {
  // Made without the ground, then given it: the view is kept as placed (its pivot is not moved
  // onto tiles that happen to be in memory), the ground counts from the first move on.
  camera_.emplace(view, lens);
  if (ground_) camera_->set_ground(ground_);
}

bool ViewerSession::place_first_camera(const CameraRequest& request, const scene::Lens& lens,
                                       scene::Diagnostics* diagnostics) {
  const std::optional<scene::LookAt> view = first_view(request, lens, model_.tracks, model_.waypoints,
                                                       model_.neutral_ground_m, ground_, framing_room(lens), diagnostics);
  if (!view) return false;
  place_camera(*view, lens);
  return true;
}

void ViewerSession::set_ground(GroundHeight ground) {
  ground_ = std::move(ground);
  if (camera_) camera_->set_ground(ground_);
}

FramingRoom ViewerSession::framing_room(const scene::Lens& lens) const {
  return framing_room_ ? framing_room_(lens) : FramingRoom{};
}

std::optional<double> ViewerSession::ground_at(double lat_deg, double lon_deg) const {
  if (!ground_) return std::nullopt;
  const double h = ground_(lat_deg, lon_deg);
  if (std::isnan(h)) return std::nullopt;
  return h;
}

void ViewerSession::adopt(LoadedTracks loaded) {
  for (std::string& w : loaded.warnings) warnings_.push_back(std::move(w));
  for (std::string& e : loaded.errors) model_.errors.push_back(std::move(e));
  // Density and thermals count every track open: files added to open ones change all the counts
  // (the first files were counted together as they were built).
  const bool recount = !loaded.tracks.empty() && !model_.tracks.empty();
  for (scene::Track& t : loaded.tracks) model_.tracks.add(std::move(t));
  const scene::TrackStyle& style = model_.settings.style.tracks;
  if (recount && track::counts_neighbours(style.color_by)) {
    try {
      apply_color_metric(model_.tracks, style.color_by, style.neighbour_radius_m, model_.parallel_for);
    } catch (const std::exception& e) {
      model_.errors.emplace_back(e.what());
    }
  }
  if (!loaded.waypoints.empty()) {
    for (scene::Waypoint& w : loaded.waypoints) {
      if (w.kind != scene::WaypointKind::Thermal) w.visible = model_.settings.show_waypoints;  // --thermals' own
      model_.waypoints.points.push_back(std::move(w));
    }
    ++model_.waypoints.revision;
  }
  if (model_.selected_track < 0 && !model_.tracks.empty()) model_.selected_track = 0;
  keep_clock_span(model_);
}

void ViewerSession::replace_tracks(LoadedTracks loaded) {
  warnings_ = std::move(loaded.warnings);
  for (std::string& e : loaded.errors) model_.errors.push_back(std::move(e));
  scene::TrackSet fresh;
  for (scene::Track& t : loaded.tracks) fresh.add(std::move(t));
  model_.tracks = std::move(fresh);
  model_.hover = HoverState{};
  model_.selection = ChartSelection{};
  if (model_.selected_track >= static_cast<int>(model_.tracks.size())) model_.selected_track = -1;
  if (model_.selected_track < 0 && !model_.tracks.empty()) model_.selected_track = 0;
  keep_clock_span(model_);
}

void ViewerSession::hover_at(double x_px, double y_px) {
  if (camera_) hover_at(x_px, y_px, camera_->camera());
}

void ViewerSession::hover_at(double x_px, double y_px, const scene::Camera& camera) {
  if (!camera_) return;
  // The terrain under the cursor (from the tiles in memory): a track point behind it loses to
  // one in front.
  const std::optional<scene::GeoPosition> ground = camera_->ground_point_at(x_px, y_px);
  std::optional<double> ground_depth_m;
  if (ground)
    if (const auto seen = camera.project(scene::ecef_from(*ground))) ground_depth_m = seen->depth_m;
  // A pin's ball under the cursor wins over the track points around it.
  const int pin = pick_waypoint(model_.waypoints, camera, model_.settings.style.pins, x_px, y_px, kPickRadiusPx);
  if (pin >= 0) {
    model_.hover = HoverState{};
    model_.hover.waypoint = pin;
    return;
  }
  const HoverState picked = pick_track_point(model_.tracks, camera, x_px, y_px, kPickRadiusPx, ground_depth_m);
  if (picked.track >= 0 || !model_.hover.from_chart) model_.hover = picked;
  // An airspace's wall last: the walls stand everywhere, a track point or a pin is what is looked at.
  if (picked.track < 0 && !model_.hover.from_chart) {
    double ground_m = std::numeric_limits<double>::infinity();
    if (ground) ground_m = glm::length(scene::ecef_from(*ground) - camera.position());
    model_.hover.volume = pick_airspace(x_px, y_px, camera, ground_m);
  }
}

void ViewerSession::clear_hover() {
  if (!model_.hover.from_chart) model_.hover = HoverState{};
}

int ViewerSession::pick_airspace(double x_px, double y_px, const scene::Camera& camera, double ground_m) {
  if (model_.volumes.volumes.empty()) return -1;
  if (volume_shapes_revision_ != model_.volumes.revision) {
    volume_shapes_ = scene::volume_shapes(model_.volumes, model_.neutral_ground_m);
    volume_shapes_revision_ = model_.volumes.revision;
  }
  const auto hit = scene::pick_volume(volume_shapes_, camera.ray_through_pixel(x_px, y_px), ground_m);
  return hit ? static_cast<int>(hit->volume) : -1;
}

bool ViewerSession::keys(const KeyInput& keys, double seconds) {
  if (!camera_) return false;
  scene::CameraController& c = *camera_;
  const double step = std::min(0.1, 0.8 * seconds);  // fractions of the distance per frame
  bool held = false;
  const auto when = [&](ViewerKey key, auto&& action) {
    if (!keys.is_held(key)) return;
    action();
    held = true;
  };
  when(ViewerKey::forward, [&] { c.move(0.0, step); });
  when(ViewerKey::back, [&] { c.move(0.0, -step); });
  when(ViewerKey::right, [&] { c.move(step, 0.0); });
  when(ViewerKey::left, [&] { c.move(-step, 0.0); });
  when(ViewerKey::orbit_left, [&] { c.orbit(-200.0 * seconds, 0.0); });
  when(ViewerKey::orbit_right, [&] { c.orbit(200.0 * seconds, 0.0); });
  when(ViewerKey::tilt_up, [&] { c.tilt(40.0 * seconds); });
  when(ViewerKey::tilt_down, [&] { c.tilt(-40.0 * seconds); });
  const double cx = c.lens().width_px / 2.0, cy = c.lens().height_px / 2.0;
  when(ViewerKey::zoom_in, [&] { c.zoom(4.0 * seconds, cx, cy); });
  when(ViewerKey::zoom_out, [&] { c.zoom(-4.0 * seconds, cx, cy); });
  if (held) ++camera_moves_;
  if (keys.was_pressed(ViewerKey::north)) {
    c.reset_north();
    ++camera_moves_;
  }
  if (keys.was_pressed(ViewerKey::fly_to_selected)) fly_to_track(std::max(0, model_.selected_track));
  if (keys.was_pressed(ViewerKey::play_pause)) model_.clock.toggle();
  return held;
}

void ViewerSession::pointer(const PointerInput& in) {
  if (!camera_) return;
  // The hover reads the picture as it was drawn: the camera before this frame's gestures.
  const scene::Camera camera = camera_->camera();
  const double x = in.position.x, y = in.position.y;
  const bool moved = in.delta.x != 0.0 || in.delta.y != 0.0;
  if (in.left_clicked) click(x, y);
  if (in.left_double_clicked)
    double_click(x, y);
  else if (in.left_down && moved)
    orbit(in.delta.x, in.delta.y);
  if (in.right_down && moved) pan(x - in.delta.x, y - in.delta.y, x, y);
  if (in.wheel != 0.0) zoom(in.wheel, x, y);
  if (x >= 0 && y >= 0 && !in.left_down && !in.right_down) hover_at(x, y, camera);
}

void ViewerSession::click(double x_px, double y_px) {
  if (!camera_) return;
  // A click on a photo's pin shows the photo larger and flies to it.
  const int pin =
      pick_waypoint(model_.waypoints, camera_->camera(), model_.settings.style.pins, x_px, y_px, kPickRadiusPx);
  if (pin >= 0 && model_.waypoints.points[static_cast<std::size_t>(pin)].kind == scene::WaypointKind::Photo)
    fly_to_waypoint(pin);
}

void ViewerSession::double_click(double x_px, double y_px) {
  if (!camera_) return;
  if (const auto ground = camera_->ground_point_at(x_px, y_px)) {
    scene::LookAt to = camera_->view();
    to.target = *ground;
    to.distance_m *= 0.5;
    camera_->fly_to(to);
    ++camera_moves_;
  }
}

void ViewerSession::orbit(double dx_px, double dy_px) {
  if (!camera_) return;
  camera_->orbit(dx_px, dy_px);
  ++camera_moves_;
}

void ViewerSession::pan(double from_x_px, double from_y_px, double to_x_px, double to_y_px) {
  if (!camera_) return;
  camera_->pan(from_x_px, from_y_px, to_x_px, to_y_px);
  ++camera_moves_;
}

void ViewerSession::zoom(double steps, double x_px, double y_px) {
  if (!camera_) return;
  camera_->zoom(steps, x_px, y_px);
  ++camera_moves_;
}

void ViewerSession::update(double seconds) {
  if (camera_) camera_->update(seconds);
}

bool ViewerSession::follow_replay() {
  if (!camera_) return false;
  const scene::LookAt before = camera_->view();
  if (!ui::follow_replay(model_, *camera_) || same_view(before, camera_->view())) return false;
  ++camera_moves_;
  return true;
}

void ViewerSession::apply(const PanelActions& actions) {
  if (actions.fly_to_track >= 0) fly_to_track(actions.fly_to_track);
  if (actions.fly_to_waypoint >= 0) fly_to_waypoint(actions.fly_to_waypoint);
  if (actions.fly_to_point && camera_) {
    const scene::LookAt& now = camera_->view();
    camera_->fly_to(look_at_waypoint(*actions.fly_to_point, now.heading_deg, now.pitch_deg));
    ++camera_moves_;
  }
}

void ViewerSession::fly_to_track(int index) {
  if (!camera_ || index < 0 || index >= static_cast<int>(model_.tracks.size())) return;
  const scene::Track& t = model_.tracks[static_cast<std::size_t>(index)];
  scene::FramingOptions framing;
  framing.lens = camera_->lens();
  framing.preferred_heading_deg = camera_->view().heading_deg;
  const FramingRoom room = framing_room(framing.lens);
  framing.keep_clear = room.keep_clear;
  framing.area = room.area;
  // The ground under the track when no terrain is in memory: its lowest recorded point, else the
  // neutral ground.
  framing.ground_height_m = t.lowest_altitude();
  if (std::isnan(framing.ground_height_m)) framing.ground_height_m = model_.neutral_ground_m;
  const scene::Track* const one[] = {&t};
  const auto framed = scene::frame_tracks(one, framing);
  if (!framed.ok()) return;
  const double ground = ground_at(framed.value->look_at.target.lat_deg, framed.value->look_at.target.lon_deg)
                            .value_or(framed.value->ground_height_m);
  camera_->fly_to(scene::CameraController::look_at_from_camera(framed.value->camera, ground));
  ++camera_moves_;
}

void ViewerSession::fly_to_waypoint(int index) {
  if (index < 0 || index >= static_cast<int>(model_.waypoints.points.size())) return;
  const scene::Waypoint& w = model_.waypoints.points[static_cast<std::size_t>(index)];
  if (w.kind == scene::WaypointKind::Photo) enlarge_photo(index);
  if (!camera_) return;
  const scene::LookAt& now = camera_->view();
  camera_->fly_to(look_at_waypoint(w, now.heading_deg, now.pitch_deg));
  ++camera_moves_;
}

void ViewerSession::enlarge_photo(int index) {
  for (std::size_t i = 0; i < model_.waypoints.points.size(); ++i) {
    scene::Waypoint& w = model_.waypoints.points[i];
    w.enlarged = static_cast<int>(i) == index && w.kind == scene::WaypointKind::Photo && w.thumbnail != nullptr;
    if (!w.enlarged || !larger_photo_) continue;
    // The thumbnail has 128 texels on its long side; drawn four times larger it wants more.
    const int long_side = static_cast<int>(model_.settings.style.pins.photo_px * scene::kEnlargedPhotoScale * 2.0);
    if (std::max(w.thumbnail->pixels.width, w.thumbnail->pixels.height) < static_cast<std::uint32_t>(long_side / 2))
      larger_photo_(w, long_side);
  }
  ++model_.waypoints.revision;
}

int ViewerSession::enlarged_photo() const {
  for (std::size_t i = 0; i < model_.waypoints.points.size(); ++i)
    if (model_.waypoints.points[i].enlarged) return static_cast<int>(i);
  return -1;
}

}  // namespace trailray::ui
