#pragma once
// A desktop window with an OpenGL ES 3.0 context, for `trailray view` (DESIGN.md: render/ owns
// everything that touches GL). GLFW opens the window and creates the context through EGL, the
// same API and the same GLSL ES 3.00 shaders as the headless context (gl_context.hpp), so the
// viewer draws with the renderer `trailray render` uses.
//
// GLFW is a process-wide library: one Window at a time (the viewer needs no more). Input is
// polled by the caller (poll_events) and delivered through GLFW's callbacks, which ImGui's GLFW
// backend installs and chains (imgui_layer.hpp); the window itself only reports dropped files.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "render/gl/gl_capabilities.hpp"
#include "render/gl/render_error.hpp"
#include "scene/pictures/rgba_image.hpp"

struct GLFWwindow;

namespace trailray::render {

struct WindowOptions {
  std::string title = "trailray";
  std::uint32_t width_px = 1280, height_px = 720;
  bool visible = true;
  bool vsync = true;  // false: swap without waiting (frame timing, scripted runs)
};

class Window {
 public:
  // Opens the window and makes its context current on this thread. Throws RenderError when
  // there is no display ("no display: run under X11/Wayland or xvfb-run; ...") or no OpenGL ES 3
  // context through EGL, with GLFW's reason.
  explicit Window(const WindowOptions& options);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  bool should_close() const;
  void request_close();
  void poll_events();
  void swap_buffers();
  // The size of the default framebuffer in pixels (differs from the window's size in screen
  // coordinates on HiDPI displays).
  std::uint32_t framebuffer_width() const;
  std::uint32_t framebuffer_height() const;
  // Device pixels per screen coordinate the system asks for (1 on an ordinary display, 2 on a
  // typical HiDPI one): the frame's pixel ratio, so labels read the same size everywhere.
  double content_scale() const;
  // Files dropped onto the window since the last call, oldest first.
  std::vector<std::string> take_dropped_files();
  // What the window shows now (its default framebuffer, interface included), top-down.
  scene::RgbaImage read_pixels() const;
  const GlCapabilities& capabilities() const { return capabilities_; }
  std::vector<std::string> describe() const;  // GL renderer and version, for --verbose

 private:
  static void on_drop(GLFWwindow* window, int count, const char** paths);
  GLFWwindow* window_ = nullptr;
  std::vector<std::string> dropped_;
  GlCapabilities capabilities_;
};

}  // namespace trailray::render
