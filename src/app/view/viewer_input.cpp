// The viewer's input: the window's mouse and keys handed to the session (ui/viewer_session.hpp),
// files dropped on the window loaded in the background and adopted.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <initializer_list>

#include "app/view/viewer_shell.hpp"
#include "app/view/viewer_ui.hpp"
#include "ui/viewer_keys.hpp"
#include "ui/viewer_session.hpp"

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
    if (any) session_.fly_to_track(first_new);
  }
}

void ViewerApp::handle_mouse() {
  const ImGuiIO& io = ImGui::GetIO();
  if (imgui_.wants_mouse()) return;
  // ImGui's mouse (interface units) in the picture's pixels.
  ui::PointerInput pointer;
  pointer.position = {io.MousePos.x * io.DisplayFramebufferScale.x, io.MousePos.y * io.DisplayFramebufferScale.y};
  pointer.delta = {io.MouseDelta.x * io.DisplayFramebufferScale.x, io.MouseDelta.y * io.DisplayFramebufferScale.y};
  pointer.left_down = ImGui::IsMouseDown(ImGuiMouseButton_Left);
  pointer.right_down = ImGui::IsMouseDown(ImGuiMouseButton_Right);
  pointer.left_clicked = ImGui::IsMouseClicked(ImGuiMouseButton_Left);
  pointer.left_double_clicked = ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left);
  pointer.wheel = io.MouseWheel;
  session_.pointer(pointer);
}

void ViewerApp::handle_keys(double wall_s) {
  if (imgui_.wants_keyboard()) return;
  // GLFW's keys as the session's (ui/viewer_keys.hpp); P, the screenshot, is the window's.
  using ui::ViewerKey;
  ui::KeyInput keys;
  const auto held = [&](ViewerKey key, std::initializer_list<int> codes) {
    for (const int code : codes)
      if (ImGui::IsKeyDown(code)) keys.hold(key);
  };
  const auto pressed = [&](ViewerKey key, int code) {
    if (ImGui::IsKeyPressed(code, false)) keys.press(key);
  };
  held(ViewerKey::forward, {GLFW_KEY_W, GLFW_KEY_UP});
  held(ViewerKey::back, {GLFW_KEY_S, GLFW_KEY_DOWN});
  held(ViewerKey::right, {GLFW_KEY_D, GLFW_KEY_RIGHT});
  held(ViewerKey::left, {GLFW_KEY_A, GLFW_KEY_LEFT});
  held(ViewerKey::orbit_left, {GLFW_KEY_Q});
  held(ViewerKey::orbit_right, {GLFW_KEY_E});
  held(ViewerKey::tilt_up, {GLFW_KEY_PAGE_UP});
  held(ViewerKey::tilt_down, {GLFW_KEY_PAGE_DOWN});
  held(ViewerKey::zoom_in, {GLFW_KEY_EQUAL, GLFW_KEY_KP_ADD});
  held(ViewerKey::zoom_out, {GLFW_KEY_MINUS, GLFW_KEY_KP_SUBTRACT});
  pressed(ViewerKey::north, GLFW_KEY_N);
  pressed(ViewerKey::fly_to_selected, GLFW_KEY_F);
  pressed(ViewerKey::play_pause, GLFW_KEY_SPACE);
  session_.keys(keys, wall_s);
  if (ImGui::IsKeyPressed(GLFW_KEY_P, false)) {
    char name[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(name, sizeof name, "trailray-%Y%m%d-%H%M%S.png", std::localtime(&now));
    screenshot(name, true);
  }
}

}  // namespace trailray::app::view
