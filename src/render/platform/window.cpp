#include "render/platform/window.hpp"

#include <GLFW/glfw3.h>
#ifdef __EMSCRIPTEN__
#include <emscripten/html5.h>
#endif

#include <cstdlib>
#include <string>

#include "render/gl/framebuffer_readback.hpp"

namespace trailray::render {
namespace {

// GLFW reports errors through a callback: the last one is kept for the exception's message.
thread_local std::string last_glfw_error;

void remember_error(int /*code*/, const char* description) { last_glfw_error = description ? description : "?"; }

std::string take_error() {
  std::string e = last_glfw_error.empty() ? std::string("unknown GLFW error") : last_glfw_error;
  last_glfw_error.clear();
  return e;
}

bool has_display() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 != nullptr && *x11 != '\0') || (wayland != nullptr && *wayland != '\0');
}

constexpr const char* kNoDisplayHint =
    "run under X11/Wayland or xvfb-run; for pictures without a window use trailray render";

}  // namespace

Window::Window(const WindowOptions& options) {
  glfwSetErrorCallback(remember_error);
  if (!has_display())
    throw RenderError(std::string("no display: ") + kNoDisplayHint + " (neither DISPLAY nor WAYLAND_DISPLAY is set)");
  if (glfwInit() != GLFW_TRUE) throw RenderError("no display: " + take_error() + "; " + kNoDisplayHint);
  glfwDefaultWindowHints();
  // An ES 3.0 context through EGL: the API and shaders of the headless context (DESIGN.md).
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
  glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
  glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
  // The scene is composed into its own target and blitted: the window needs no depth buffer.
  glfwWindowHint(GLFW_DEPTH_BITS, 0);
  glfwWindowHint(GLFW_STENCIL_BITS, 0);
  window_ = glfwCreateWindow(static_cast<int>(options.width_px), static_cast<int>(options.height_px),
                             options.title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    const std::string why = take_error();
    glfwTerminate();
    throw RenderError("no OpenGL ES 3.0 window through EGL: " + why);
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(options.vsync ? 1 : 0);
  glfwSetWindowUserPointer(window_, this);
  glfwSetDropCallback(window_, &Window::on_drop);
  try {
    capabilities_ = query_gl_capabilities();
  } catch (...) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw;
  }
}

Window::~Window() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool Window::should_close() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
void Window::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void Window::poll_events() { glfwPollEvents(); }
void Window::swap_buffers() { glfwSwapBuffers(window_); }

std::uint32_t Window::framebuffer_width() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return static_cast<std::uint32_t>(w > 0 ? w : 0);
}

std::uint32_t Window::framebuffer_height() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return static_cast<std::uint32_t>(h > 0 ? h : 0);
}

double Window::content_scale() const {
#ifdef __EMSCRIPTEN__
  // Emscripten's GLFW is the 3.2 API, without content scales: the page's device pixel ratio.
  const double ratio = emscripten_get_device_pixel_ratio();
  return ratio > 0.0 ? ratio : 1.0;
#else
  float x = 1.0f, y = 1.0f;
  glfwGetWindowContentScale(window_, &x, &y);
  return y > 0.0f ? static_cast<double>(y) : 1.0;
#endif
}

std::vector<std::string> Window::take_dropped_files() {
  std::vector<std::string> out;
  out.swap(dropped_);
  return out;
}

std::vector<std::string> Window::describe() const { return capabilities_.describe(); }

void Window::on_drop(GLFWwindow* window, int count, const char** paths) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
  if (self == nullptr) return;
  for (int i = 0; i < count; ++i) self->dropped_.emplace_back(paths[i]);
}

scene::RgbaImage Window::read_pixels() const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return read_rgba8(0, 0, static_cast<int>(framebuffer_width()), static_cast<int>(framebuffer_height()));
}

}  // namespace trailray::render
