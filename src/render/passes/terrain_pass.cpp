#include "render/passes/terrain_pass.hpp"

#include <array>
#include <string>

#include "geo/wgs84.hpp"
#include "render/gl/render_error.hpp"

namespace trailray::render {
namespace {

void throw_on_gl_error(const char* what) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) throw RenderError(std::string(what) + " failed (GL error " + std::to_string(error) + ")");
}

}  // namespace

TerrainPass::TerrainPass() : program_(ShaderProgram::from_embedded("terrain.vert", "terrain.frag")) {}

void TerrainPass::draw(const GBuffer& gbuffer, const scene::Camera& camera, std::span<const TerrainDrawItem> tiles,
                       const scene::SnowCover& snow) const {
  gbuffer.bind_and_clear();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  // Skirts face every way and tiles are seen from below at times (a camera under a cliff): no
  // culling; depth sorts it out.
  glDisable(GL_CULL_FACE);
  program_.use();
  const glm::dmat3 to_view = camera.view_rotation();
  std::array<float, 9> rotation{};
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) rotation[static_cast<std::size_t>(c * 3 + r)] = static_cast<float>(to_view[c][r]);
  program_.set_mat3("u_view_rotation", std::span<const float, 9>(rotation));
  program_.set_vec3("u_neutral_albedo", kNeutralGroundAlbedo.r, kNeutralGroundAlbedo.g, kNeutralGroundAlbedo.b);
  program_.set_int("u_packed_distance", gbuffer.packed_distance() ? 1 : 0);
  program_.set_int("u_imagery", 0);
  program_.set_int("u_snow", snow.enabled ? 1 : 0);
  program_.set_float("u_snowline_m", static_cast<float>(snow.snowline_m));
  glActiveTexture(GL_TEXTURE0);
  for (const TerrainDrawItem& item : tiles) {
    if (item.mesh == nullptr || item.mesh->index_count == 0) continue;
    const std::array<float, 16> view_projection = camera.view_projection_relative_to(item.mesh->origin);
    program_.set_mat4("u_view_projection", std::span<const float, 16>(view_projection));
    const glm::vec3 offset = camera.origin_minus_camera(item.mesh->origin);
    program_.set_vec3("u_origin_minus_camera", offset.x, offset.y, offset.z);
    if (snow.enabled) {
      const geo::Geodetic at = geo::geodetic_from_ecef(item.mesh->origin);
      const glm::dvec3 up = to_view * scene::enu_axes_at(at.lat_deg, at.lon_deg).up;
      program_.set_vec3("u_view_up", static_cast<float>(up.x), static_cast<float>(up.y), static_cast<float>(up.z));
    }
    const bool has_imagery = item.imagery.texture != nullptr && *item.imagery.texture;
    program_.set_int("u_has_imagery", has_imagery ? 1 : 0);
    program_.set_vec4("u_imagery_transform", item.imagery.scale.x, item.imagery.scale.y, item.imagery.offset.x,
                      item.imagery.offset.y);
    glBindTexture(GL_TEXTURE_2D, has_imagery ? item.imagery.texture->id() : 0);
    glBindVertexArray(item.mesh->vertex_array.id());
    glDrawElements(GL_TRIANGLES, item.mesh->index_count, GL_UNSIGNED_INT, nullptr);
  }
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glDisable(GL_DEPTH_TEST);
  throw_on_gl_error("drawing the terrain");
}

Texture upload_imagery_texture(std::uint32_t width, std::uint32_t height, std::span<const std::uint8_t> rgba) {
  if (width == 0 || height == 0 || rgba.size() != std::size_t{width} * height * 4)
    throw RenderError("imagery texture: " + std::to_string(rgba.size()) + " bytes for " + std::to_string(width) +
                      " x " + std::to_string(height) + " RGBA pixels");
  int levels = 1;
  for (std::uint32_t s = std::max(width, height); s > 1; s /= 2) ++levels;
  Texture texture = make_texture_2d(GL_SRGB8_ALPHA8, static_cast<int>(width), static_cast<int>(height), levels);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, static_cast<GLsizei>(width), static_cast<GLsizei>(height), GL_RGBA,
                  GL_UNSIGNED_BYTE, rgba.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glBindTexture(GL_TEXTURE_2D, 0);
  throw_on_gl_error("uploading an imagery texture");
  return texture;
}

ColorDepthTarget::ColorDepthTarget(int width, int height)
    : width_(width),
      height_(height),
      color_(make_texture_2d(GL_RGBA8, width, height)),
      depth_(make_renderbuffer(GL_DEPTH_COMPONENT24, width, height)),
      framebuffer_(Framebuffer::create()) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_.id(), 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  check_framebuffer_complete(GL_FRAMEBUFFER, "frame target");
}

void ColorDepthTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, width_, height_);
}

}  // namespace trailray::render
