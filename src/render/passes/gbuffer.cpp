#include "render/passes/gbuffer.hpp"

#include <array>

namespace trailray::render {

DistanceEncoding distance_encoding_for(const GlCapabilities& capabilities) {
  return capabilities.color_buffer_float ? DistanceEncoding::float32 : DistanceEncoding::packed_rgba8;
}

GBuffer::GBuffer(int width, int height, DistanceEncoding encoding)
    : width_(width),
      height_(height),
      encoding_(encoding),
      albedo_(make_texture_2d(GL_SRGB8_ALPHA8, width, height)),
      normal_(make_texture_2d(GL_RGB10_A2, width, height)),
      distance_(make_texture_2d(encoding == DistanceEncoding::float32 ? GL_R32F : GL_RGBA8, width, height)),
      depth_(make_renderbuffer(GL_DEPTH_COMPONENT24, width, height)),
      framebuffer_(Framebuffer::create()) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, albedo_.id(), 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, normal_.id(), 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, distance_.id(), 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  const std::array<GLenum, 3> attachments{GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  glDrawBuffers(static_cast<GLsizei>(attachments.size()), attachments.data());
  check_framebuffer_complete(GL_FRAMEBUFFER, encoding == DistanceEncoding::float32 ? "G-buffer (float distance)"
                                                                                   : "G-buffer (packed distance)");
}

void GBuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, width_, height_);
}

void GBuffer::bind_and_clear() const {
  bind();
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  const std::array<float, 4> zero{0.0f, 0.0f, 0.0f, 0.0f};
  for (GLint buffer = 0; buffer < 3; ++buffer) glClearBufferfv(GL_COLOR, buffer, zero.data());
  const float far = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &far);
}

}  // namespace trailray::render
