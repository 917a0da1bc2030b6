// The viewer's input: mouse gestures and hover, keys, files dropped on the window.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <limits>

#include "app/view/viewer_shell.hpp"
#include "app/view/viewer_ui.hpp"
#include "ui/track_picking.hpp"
#include "ui/waypoint_view.hpp"

namespace trailray::app::view {

void ViewerApp::take_dropped_files() {
  std::vector<std::string> dropped = window_.take_dropped_files();
  if (!dropped.empty()) {
    TrackLoadInputs inputs = load_inputs(neutral_);
    inputs.tracks_open = model_.tracks.size();
    // Colours chosen against what is open now; files dropped together share one load.
    inputs.style.color_by = model_.settings.style.tracks.color_by;
    loading_.push_back(load_viewer_tracks_async(std::move(dropped), std::move(inputs)));
  }
  for (auto it = loading_.begin(); it != loading_.end();) {
    if (it->wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
      ++it;
      continue;
    }
    LoadedViewerTracks loaded = it->get();
    it = loading_.erase(it);
    const int first_new = static_cast<int>(model_.tracks.size());
    const bool any = !loaded.tracks.empty();
    adopt(std::move(loaded));
    if (any) fly_to_track(first_new);
  }
}

void ViewerApp::update_hover(double x_px, double y_px, const scene::Camera& camera) {
  // The terrain under the cursor (from the tiles in memory): a track point behind it loses to
  // one in front.
  std::optional<double> ground_depth_m;
  if (const auto ground = controller_.ground_point_at(x_px, y_px))
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
    if (const auto ground = controller_.ground_point_at(x_px, y_px))
      ground_m = glm::length(scene::ecef_from(*ground) - camera.position());
    model_.hover.volume = pick_airspace(x_px, y_px, camera, ground_m);
  }
}

int ViewerApp::pick_airspace(double x_px, double y_px, const scene::Camera& camera, double ground_m) {
  if (model_.volumes.volumes.empty()) return -1;
  if (volume_shapes_revision_ != model_.volumes.revision) {
    volume_shapes_ = scene::volume_shapes(model_.volumes, neutral_);
    volume_shapes_revision_ = model_.volumes.revision;
  }
  const auto hit = scene::pick_volume(volume_shapes_, camera.ray_through_pixel(x_px, y_px), ground_m);
  return hit ? static_cast<int>(hit->volume) : -1;
}

void ViewerApp::handle_mouse(const scene::Camera& camera) {
  const ImGuiIO& io = ImGui::GetIO();
  if (imgui_.wants_mouse()) return;
  const double x = io.MousePos.x * io.DisplayFramebufferScale.x, y = io.MousePos.y * io.DisplayFramebufferScale.y;
  const glm::dvec2 delta(io.MouseDelta.x * io.DisplayFramebufferScale.x,
                         io.MouseDelta.y * io.DisplayFramebufferScale.y);
  // A click on a photo's pin shows the photo larger and flies to it.
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && model_.hover.waypoint >= 0 &&
      static_cast<std::size_t>(model_.hover.waypoint) < model_.waypoints.points.size() &&
      model_.waypoints.points[static_cast<std::size_t>(model_.hover.waypoint)].kind == scene::WaypointKind::Photo)
    fly_to_waypoint(model_.hover.waypoint);
  if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    if (const auto ground = controller_.ground_point_at(x, y)) {
      scene::LookAt to = controller_.view();
      to.target = *ground;
      to.distance_m *= 0.5;
      controller_.fly_to(to);
    }
  } else if (ImGui::IsMouseDown(ImGuiMouseButton_Left) && (delta.x != 0.0 || delta.y != 0.0)) {
    controller_.orbit(delta.x, delta.y);
  }
  if (ImGui::IsMouseDown(ImGuiMouseButton_Right) && (delta.x != 0.0 || delta.y != 0.0))
    controller_.pan(x - delta.x, y - delta.y, x, y);
  if (io.MouseWheel != 0.0f) controller_.zoom(io.MouseWheel, x, y);
  if (x >= 0 && y >= 0 && !ImGui::IsMouseDown(ImGuiMouseButton_Left) && !ImGui::IsMouseDown(ImGuiMouseButton_Right))
    update_hover(x, y, camera);
}

void ViewerApp::handle_keys(double wall_s) {
  if (imgui_.wants_keyboard()) return;
  const double step = std::min(0.1, 0.8 * wall_s);  // fractions of the distance per frame
  const auto down = [](int key) { return ImGui::IsKeyDown(key); };
  if (down(GLFW_KEY_W) || down(GLFW_KEY_UP)) controller_.move(0.0, step);
  if (down(GLFW_KEY_S) || down(GLFW_KEY_DOWN)) controller_.move(0.0, -step);
  if (down(GLFW_KEY_D) || down(GLFW_KEY_RIGHT)) controller_.move(step, 0.0);
  if (down(GLFW_KEY_A) || down(GLFW_KEY_LEFT)) controller_.move(-step, 0.0);
  if (down(GLFW_KEY_Q)) controller_.orbit(-200.0 * wall_s, 0.0);
  if (down(GLFW_KEY_E)) controller_.orbit(200.0 * wall_s, 0.0);
  if (down(GLFW_KEY_PAGE_UP)) controller_.tilt(40.0 * wall_s);
  if (down(GLFW_KEY_PAGE_DOWN)) controller_.tilt(-40.0 * wall_s);
  const glm::dvec2 centre(controller_.lens().width_px / 2.0, controller_.lens().height_px / 2.0);
  if (down(GLFW_KEY_EQUAL) || down(GLFW_KEY_KP_ADD)) controller_.zoom(4.0 * wall_s, centre.x, centre.y);
  if (down(GLFW_KEY_MINUS) || down(GLFW_KEY_KP_SUBTRACT)) controller_.zoom(-4.0 * wall_s, centre.x, centre.y);
  if (ImGui::IsKeyPressed(GLFW_KEY_N, false)) controller_.reset_north();
  if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) fly_to_track(std::max(0, model_.selected_track));
  if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) model_.clock.toggle();
  if (ImGui::IsKeyPressed(GLFW_KEY_P, false)) {
    char name[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(name, sizeof name, "trailray-%Y%m%d-%H%M%S.png", std::localtime(&now));
    screenshot(name, true);
  }
}

}  // namespace trailray::app::view
