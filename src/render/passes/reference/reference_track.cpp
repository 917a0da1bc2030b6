#include "render/passes/reference/reference_track.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <string>

#include "render/gl/render_error.hpp"

namespace trailray::render::reference {

glm::dvec3 geometry_origin(const scene::TrackGeometry& geometry) {
  glm::dvec3 sum(0.0);
  std::size_t count = 0;
  for (const scene::TrackPolyline& segment : geometry.segments)
    for (const glm::dvec3& p : segment.points_ecef) {
      sum += p;
      ++count;
    }
  if (count == 0) return {};
  return sum / static_cast<double>(count);
}

std::size_t geometry_point_count(const scene::TrackGeometry& geometry) {
  std::size_t count = 0;
  for (const scene::TrackPolyline& segment : geometry.segments) count += segment.points_ecef.size();
  return count;
}

double radius_for_pixel_width(const scene::Camera& camera, double distance_m, double width_px) {
  const double half_fov = camera.lens().vertical_fov_deg * std::numbers::pi / 360.0;
  const double focal_px = 0.5 * static_cast<double>(camera.lens().height_px) / std::tan(half_fov);
  return 0.5 * width_px * distance_m / focal_px;
}

void begin_reference_draw(const ShaderProgram& program, const GBuffer& gbuffer, const scene::Camera& camera,
                          const glm::dvec3& origin, const glm::vec3& color_srgb) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  program.use();
  const std::array<float, 16> view_projection = camera.view_projection_relative_to(origin);
  program.set_mat4("u_view_projection", std::span<const float, 16>(view_projection));
  const glm::vec3 offset = camera.origin_minus_camera(origin);
  program.set_vec3("u_origin_minus_camera", offset.x, offset.y, offset.z);
  const glm::dmat3 to_view = camera.view_rotation();
  std::array<float, 9> rotation{};
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) rotation[static_cast<std::size_t>(c * 3 + r)] = static_cast<float>(to_view[c][r]);
  program.set_mat3("u_view_rotation", std::span<const float, 9>(rotation));
  program.set_vec3("u_color_srgb", color_srgb.r, color_srgb.g, color_srgb.b);
  program.set_int("u_packed_distance", gbuffer.packed_distance() ? 1 : 0);
}

void end_reference_draw(const char* what) {
  glBindVertexArray(0);
  glDisable(GL_DEPTH_TEST);
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) throw RenderError(std::string(what) + " failed (GL error " + std::to_string(error) + ")");
}

}  // namespace trailray::render::reference
