#include "render/frame_target.hpp"

#include "render/gl/framebuffer_readback.hpp"

namespace trailray::render {

void ImageTarget::receive(const ColorDepthTarget& frame) { image = read_rgba8(0, 0, frame.width(), frame.height()); }

void DefaultFramebufferTarget::receive(const ColorDepthTarget& frame) {
  frame.bind();
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, frame.width(), frame.height(), 0, 0, frame.width(), frame.height(), GL_COLOR_BUFFER_BIT,
                    GL_NEAREST);
  // Left bound and covered, so what the window draws next (its interface) lands on the frame.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, frame.width(), frame.height());
}

}  // namespace trailray::render
