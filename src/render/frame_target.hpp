#pragma once
// Where a frame goes (Renderer::draw): the renderer composes the frame offscreen, at the
// camera's lens size, then hands it to its target, which reads it back into a picture, copies it
// into a window; a browser canvas or a video encoder's frame is one more kind of target.

#include <optional>
#include <string_view>

#include "render/gl/frame_profiler.hpp"
#include "render/passes/terrain_pass.hpp"
#include "scene/pictures/rgba_image.hpp"

namespace trailray::render {

class FrameTarget {
 public:
  virtual ~FrameTarget() = default;

  // Receives the composed frame (bound for reading and drawing when called). Throws RenderError.
  virtual void receive(const ColorDepthTarget& frame) = 0;
  // The profiler's name for receive (empty: not timed).
  virtual std::string_view pass_name() const { return {}; }

  // When set, the frame's passes are timed as one profiler frame (begun after the tiles are
  // loaded).
  FrameProfiler* profiler = nullptr;
  // Device pixels per logical pixel where the frame is shown (a high-DPI window: 2; `render
  // --pixel-ratio`): labels are drawn that much larger, so they read the same and stay crisp.
  double pixel_ratio = 1.0;
};

// The frame read back into a picture (top-down, sRGB): `trailray render`, screenshots, tests.
class ImageTarget : public FrameTarget {
 public:
  void receive(const ColorDepthTarget& frame) override;
  std::string_view pass_name() const override { return "readback"; }

  scene::RgbaImage image;  // the last frame received
};

// The frame copied into the default framebuffer (a window's), which is left bound with a
// viewport over all of it. The window is the lens's size, or `window_width_px` x
// `window_height_px` when set: a smaller frame (the viewer's while the camera moves) is then
// scaled up to it, filtered linearly.
class DefaultFramebufferTarget : public FrameTarget {
 public:
  void receive(const ColorDepthTarget& frame) override;

  int window_width_px = 0, window_height_px = 0;  // 0: the frame's size
};

// A DefaultFramebufferTarget that keeps a copy of the last frame, so that a window whose
// interface changed but whose scene did not (the page: a panel hovered, a tooltip) shows the
// same picture again under the new interface without drawing the scene (show_kept).
class KeptFrameTarget : public DefaultFramebufferTarget {
 public:
  void receive(const ColorDepthTarget& frame) override;
  // The kept frame copied into the default framebuffer as receive did; false when none is kept
  // (nothing drawn yet, or the window's size changed since).
  bool show_kept();

 private:
  std::optional<ColorDepthTarget> kept_;
};

}  // namespace trailray::render
