#include "render/passes/ssao_pass.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "render/gl/render_error.hpp"

namespace trailray::render {
namespace {

void throw_on_gl_error(const char* what) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) throw RenderError(std::string(what) + " failed (GL error " + std::to_string(error) + ")");
}

std::array<float, 16> to_floats(const glm::dmat4& m) {
  std::array<float, 16> out{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) out[static_cast<std::size_t>(c * 4 + r)] = static_cast<float>(m[c][r]);
  return out;
}

}  // namespace

std::vector<glm::vec3> hemisphere_kernel(int count) {
  std::vector<glm::vec3> kernel;
  const double golden_angle = M_PI * (3.0 - std::sqrt(5.0));
  const double min_z = std::sin(10.0 * M_PI / 180.0);
  for (int i = 0; i < count; ++i) {
    const double f = (i + 0.5) / count;
    const double z = min_z + (1.0 - min_z) * (1.0 - f);  // from near the zenith down to 10 degrees
    const double r = std::sqrt(1.0 - z * z);
    const double phi = golden_angle * i;
    const double length = 0.1 + 0.9 * f * f;
    kernel.emplace_back(glm::dvec3(r * std::cos(phi), r * std::sin(phi), z) * length);
  }
  return kernel;
}

SsaoPass::SsaoPass()
    : occlusion_(ShaderProgram::from_embedded("fullscreen_triangle.vert", "ssao.frag")),
      blur_(ShaderProgram::from_embedded("fullscreen_triangle.vert", "ssao_blur.frag")),
      upsample_(ShaderProgram::from_embedded("fullscreen_triangle.vert", "ssao_upsample.frag")),
      fullscreen_(VertexArray::create()),
      kernel_(hemisphere_kernel(kSsaoSamples)) {}

void SsaoPass::resize(Target& target, int width, int height, const char* what) {
  if (width == target.width && height == target.height) return;
  target.texture = make_texture_2d(GL_R8, width, height);
  target.framebuffer = Framebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.texture.id(), 0);
  check_framebuffer_complete(GL_FRAMEBUFFER, what);
  target.width = width;
  target.height = height;
}

const Texture& SsaoPass::run(const GBuffer& gbuffer, const scene::Camera& camera, const SsaoSettings& settings) {
  const int step = settings.resolution_divisor;
  if (step != 1 && step != 2)
    throw std::invalid_argument("SSAO resolution divisor " + std::to_string(step) + " is not 1 or 2");
  // Rounded up: the last occlusion pixel stands for the G-buffer's last row or column.
  const int width = (gbuffer.width() + step - 1) / step, height = (gbuffer.height() + step - 1) / step;
  resize(raw_, width, height, "SSAO");
  resize(blurred_, width, height, "SSAO blur");
  if (step > 1) resize(upsampled_, gbuffer.width(), gbuffer.height(), "SSAO upsample");
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glBindVertexArray(fullscreen_.id());
  const double tan_v = std::tan(0.5 * camera.lens().vertical_fov_deg * M_PI / 180.0);
  const auto tan_half_fov = glm::vec2(static_cast<float>(tan_v * camera.lens().aspect()), static_cast<float>(tan_v));

  glBindFramebuffer(GL_FRAMEBUFFER, raw_.framebuffer.id());
  glViewport(0, 0, width, height);
  occlusion_.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, gbuffer.normal().id());
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, gbuffer.distance().id());
  occlusion_.set_int("u_normal", 0);
  occlusion_.set_int("u_distance", 1);
  occlusion_.set_int("u_packed_distance", gbuffer.packed_distance() ? 1 : 0);
  occlusion_.set_int("u_step", step);
  const std::array<float, 16> projection = to_floats(camera.projection());
  occlusion_.set_mat4("u_projection", std::span<const float, 16>(projection));
  occlusion_.set_vec2("u_tan_half_fov", tan_half_fov.x, tan_half_fov.y);
  occlusion_.set_float("u_radius_fraction", settings.radius_fraction);
  occlusion_.set_float("u_intensity", settings.intensity);
  const GLint kernel_location = occlusion_.uniform_location("u_kernel[0]");
  if (kernel_location >= 0) glUniform3fv(kernel_location, static_cast<GLsizei>(kernel_.size()), &kernel_.front().x);
  glDrawArrays(GL_TRIANGLES, 0, 3);

  glBindFramebuffer(GL_FRAMEBUFFER, blurred_.framebuffer.id());
  blur_.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, raw_.texture.id());
  blur_.set_int("u_ao", 0);
  blur_.set_int("u_distance", 1);
  blur_.set_int("u_packed_distance", gbuffer.packed_distance() ? 1 : 0);
  blur_.set_int("u_step", step);
  glDrawArrays(GL_TRIANGLES, 0, 3);

  if (step > 1) {
    glBindFramebuffer(GL_FRAMEBUFFER, upsampled_.framebuffer.id());
    glViewport(0, 0, gbuffer.width(), gbuffer.height());
    upsample_.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, blurred_.texture.id());
    upsample_.set_int("u_ao", 0);
    upsample_.set_int("u_distance", 1);
    upsample_.set_int("u_packed_distance", gbuffer.packed_distance() ? 1 : 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }

  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindVertexArray(0);
  throw_on_gl_error("ambient occlusion");
  return step > 1 ? upsampled_.texture : blurred_.texture;
}

}  // namespace trailray::render
