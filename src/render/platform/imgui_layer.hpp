#pragma once
// Dear ImGui on a Window (or a canvas whose page feeds the input): the ImGui context, its GLFW backend (input: installs
// GLFW's callbacks and chains any installed before) and its OpenGL 3 backend compiled for ES 3 ("#version 300 es"),
// with the legend's font (DejaVu Sans, compiled in) so the interface reads the same on every machine. One layer per
// window; the caller draws widgets between begin_frame and render.

#include <array>
#include <optional>

#include "render/platform/window.hpp"

namespace trailray::render {

class ImGuiLayer {
 public:
  // `font_px`: the interface's font size in pixels. Throws RenderError when a backend fails.
  explicit ImGuiLayer(Window& window, float font_px = 15.0f);
  // Without a window (the page's canvas): the caller feeds ImGui's input itself (io.DisplaySize,
  // DeltaTime, mouse, keys) before each begin_frame; only the ES 3 renderer backend runs.
  explicit ImGuiLayer(float font_px = 15.0f);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // The backends' NewFrame, then ImGui::NewFrame. With `scripted_cursor`, the mouse is not the
  // real one: it is there (window pixels), or nowhere when its x is NaN, with no button down.
  void begin_frame(std::optional<std::array<float, 2>> scripted_cursor = std::nullopt);
  // ImGui::Render and the draw lists into the framebuffer bound now (the window's, 0).
  void render();
  // Whether ImGui wants the mouse / keyboard this frame (the camera must not take them then).
  bool wants_mouse() const;
  bool wants_keyboard() const;

 private:
  void create_context(float font_px);
  Window* window_ = nullptr;
};

}  // namespace trailray::render
