#include "render/frame_target.hpp"

#include "render/gl/framebuffer_readback.hpp"

namespace trailray::render {

void ImageTarget::receive(const ColorDepthTarget& frame) { image = read_rgba8(0, 0, frame.width(), frame.height()); }

void DefaultFramebufferTarget::receive(const ColorDepthTarget& frame) {
  const int width = window_width_px > 0 ? window_width_px : frame.width();
  const int height = window_height_px > 0 ? window_height_px : frame.height();
  const bool scaled = width != frame.width() || height != frame.height();
  frame.bind();
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, frame.width(), frame.height(), 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                    scaled ? GL_LINEAR : GL_NEAREST);
  // Left bound and covered, so what the window draws next (its interface) lands on the frame.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
}

void KeptFrameTarget::receive(const ColorDepthTarget& frame) {
  if (!kept_ || kept_->width() != frame.width() || kept_->height() != frame.height())
    kept_.emplace(frame.width(), frame.height());
  frame.bind();
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, kept_->framebuffer_id());
  glBlitFramebuffer(0, 0, frame.width(), frame.height(), 0, 0, frame.width(), frame.height(), GL_COLOR_BUFFER_BIT,
                    GL_NEAREST);
  DefaultFramebufferTarget::receive(*kept_);
}

bool KeptFrameTarget::show_kept() {
  const int width = window_width_px > 0 ? window_width_px : (kept_ ? kept_->width() : 0);
  const int height = window_height_px > 0 ? window_height_px : (kept_ ? kept_->height() : 0);
  if (!kept_ || kept_->width() != width || kept_->height() != height) return false;
  DefaultFramebufferTarget::receive(*kept_);
  return true;
}

}  // namespace trailray::render
