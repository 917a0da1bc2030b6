#pragma once
// An OpenGL ES 3 context without a window, through EGL: renders into framebuffer objects, for
// `trailray render`, the tests and CI (DESIGN.md: render/ owns everything that touches GL).
//
// Headless EGL has two ways in, tried in this order unless one is asked for:
//   1. the device platform (EGL_EXT_platform_device): one display per GPU, no X or Wayland
//      needed; how NVIDIA's driver renders headless;
//   2. Mesa's surfaceless platform (EGL_MESA_platform_surfaceless): Mesa's GPU drivers through a
//      render node, else llvmpipe on the CPU (what CI and this project's tests run on);
//   3. the device platform's software devices (Mesa's llvmpipe "device"), when 2 is missing.
// The context is made current on the creating thread; GL calls need it current on theirs.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "render/gl/gl_capabilities.hpp"
#include "render/gl/render_error.hpp"

namespace trailray::render {

enum class EglPlatform { device, surfaceless };
std::string_view to_string(EglPlatform platform);  // "device", "surfaceless"

struct HeadlessContextOptions {
  // Only this platform (with `device`: GPUs first, then software devices); nullopt tries all.
  std::optional<EglPlatform> platform;
  // The lowest OpenGL ES version accepted (drivers usually give their newest, e.g. 3.2).
  int gles_major = 3, gles_minor = 0;
};

class GlContext {
 public:
  // Creates the context and makes it current on this thread, then queries its capabilities.
  // Throws RenderError when no way works, naming each attempt and why it failed, e.g. "no
  // OpenGL ES 3.0 context: EGL device 0 (software): ... ; Mesa surfaceless: eglInitialize
  // failed (EGL_NOT_INITIALIZED)".
  static GlContext create_headless(const HeadlessContextOptions& options = {});

  GlContext(GlContext&& other) noexcept;
  GlContext& operator=(GlContext&& other) noexcept;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;
  // Releases the context (unbinding it first where it is current); GL objects still alive are
  // freed with it, so destroy them first (their wrappers would otherwise delete stale names).
  ~GlContext();

  // The accessors below throw RenderError on a moved-from context (it holds none).
  // Makes the context current on the calling thread. Throws RenderError when EGL refuses.
  void make_current() const;
  bool is_current() const;

  EglPlatform platform() const;
  // "EGL 1.5 (Mesa Project), surfaceless platform" or "EGL 1.5 (NVIDIA), device platform,
  // EGL device 0 (/dev/dri/renderD128)".
  const std::string& egl_description() const;
  const GlCapabilities& capabilities() const;
  // The lines `--verbose` logs at start: EGL, then GlCapabilities::describe().
  std::vector<std::string> describe() const;

 private:
  struct State;
  explicit GlContext(std::unique_ptr<State> state);
  void release() noexcept;
  const State& state() const;
  std::unique_ptr<State> state_;
};

}  // namespace trailray::render
