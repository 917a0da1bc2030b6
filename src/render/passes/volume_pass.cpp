#include "render/passes/volume_pass.hpp"

#include <string>

#include "render/gl/render_error.hpp"

namespace trailray::render {
namespace {

void check_gl(const char* what) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) throw RenderError(std::string(what) + " failed (GL error " + std::to_string(error) + ")");
}

void set_common(const ShaderProgram& program, const GBuffer& gbuffer, const scene::Camera& camera,
                const VolumeDraw& volumes, const VolumeStyle& style) {
  program.use();
  const std::array<float, 16> view_projection = camera.view_projection_relative_to(volumes.origin);
  program.set_mat4("u_view_projection", std::span<const float, 16>(view_projection));
  const glm::vec3 offset = camera.origin_minus_camera(volumes.origin);
  program.set_vec3("u_origin_minus_camera", offset.x, offset.y, offset.z);
  program.set_int("u_distance", 0);
  program.set_int("u_packed_distance", gbuffer.packed_distance() ? 1 : 0);
  program.set_vec3("u_fade", style.fade_start_m, style.fade_end_m, style.far_alpha);
}

}  // namespace

VolumePass::VolumePass()
    : walls_(ShaderProgram::from_embedded("volume_wall.vert", "volume.frag")),
      outlines_(ShaderProgram::from_embedded("volume_outline.vert", "volume.frag")) {}

void VolumePass::draw(const GBuffer& gbuffer, const scene::Camera& camera, const VolumeDraw& volumes,
                      double pixel_ratio, const VolumeStyle& style) const {
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, gbuffer.distance().id());

  set_common(walls_, gbuffer, camera, volumes, style);
  glBindVertexArray(volumes.wall_array.id());
  glDrawArrays(GL_TRIANGLES, 0, volumes.wall_vertices);

  if (volumes.outline_vertices > 0) {
    set_common(outlines_, gbuffer, camera, volumes, style);
    outlines_.set_vec2("u_viewport_px", static_cast<float>(gbuffer.width()), static_cast<float>(gbuffer.height()));
    outlines_.set_float("u_width_px", style.outline_px * static_cast<float>(pixel_ratio));
    glBindVertexArray(volumes.outline_array.id());
    glDrawArrays(GL_TRIANGLES, 0, volumes.outline_vertices);
  }
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  check_gl("drawing the volumes");
}

}  // namespace trailray::render
