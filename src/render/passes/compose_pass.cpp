#include "render/passes/compose_pass.hpp"

#include <array>
#include <cmath>
#include <span>
#include <string>

#include "render/gl/render_error.hpp"

namespace trailray::render {
namespace {

void throw_on_gl_error(const char* what) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) throw RenderError(std::string(what) + " failed (GL error " + std::to_string(error) + ")");
}

// Units 0..3 hold the G-buffer and the ambient occlusion.
constexpr GLuint kShadowUnit = 4;

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

void set_vec3(const ShaderProgram& program, std::string_view name, const glm::vec3& v) {
  program.set_vec3(name, v.x, v.y, v.z);
}

}  // namespace

SceneLighting lighting_for(const glm::dvec3& sun_direction_ecef, const scene::Camera& camera,
                           const AtmosphereModel& model) {
  const scene::GeoPosition& at = camera.geodetic();
  const double elevation = elevation_deg(sun_direction_ecef, scene::enu_axes_at(at.lat_deg, at.lon_deg).up);
  SceneLighting lighting;
  lighting.sun_direction_ecef = glm::normalize(sun_direction_ecef);
  lighting.sun_radiance = sun_radiance(elevation, model);
  lighting.sky_radiance = sky_radiance(elevation);
  return lighting;
}

namespace {

// The atmosphere's switch, its model and the camera's height in it.
void set_atmosphere_uniforms(const ShaderProgram& program, const ComposeSettings& settings, double camera_height_m) {
  program.set_int("u_atmosphere", settings.atmosphere ? 1 : 0);
  const AtmosphereModel& m = settings.model;
  set_vec3(program, "u_rayleigh_per_m", m.rayleigh_per_m);
  program.set_float("u_rayleigh_scale_height", m.rayleigh_scale_height_m);
  program.set_float("u_mie_per_m", m.mie_per_m);
  program.set_float("u_mie_scale_height", m.mie_scale_height_m);
  program.set_float("u_mie_g", m.mie_asymmetry);
  program.set_float("u_inscatter_scale", m.inscatter_scale);
  program.set_float("u_camera_height", static_cast<float>(camera_height_m));
}

}  // namespace

ComposePass::ComposePass()
    : program_(ShaderProgram::from_embedded("fullscreen_triangle.vert", "compose.frag")),
      fullscreen_(VertexArray::create()) {}

void ComposePass::draw(const GBuffer& gbuffer, const Texture* ambient_occlusion, const ComposeShadows* shadows,
                       const scene::Camera& camera, const SceneLighting& lighting,
                       const ComposeSettings& settings) const {
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  program_.use();
  const glm::dmat3 to_view = camera.view_rotation();
  const scene::GeoPosition& at = camera.geodetic();
  const glm::vec3 sun_view = glm::vec3(glm::normalize(to_view * lighting.sun_direction_ecef));
  const glm::vec3 up_view = glm::vec3(to_view * scene::enu_axes_at(at.lat_deg, at.lon_deg).up);
  const double tan_v = std::tan(0.5 * camera.lens().vertical_fov_deg * M_PI / 180.0);
  program_.set_vec2("u_tan_half_fov", static_cast<float>(tan_v * camera.lens().aspect()), static_cast<float>(tan_v));
  set_vec3(program_, "u_sun_view", sun_view);
  set_vec3(program_, "u_up_view", up_view);
  set_vec3(program_, "u_sun_radiance", lighting.sun_radiance);
  set_vec3(program_, "u_sky_radiance", lighting.sky_radiance);
  set_vec3(
      program_, "u_flat_sky",
      glm::vec3(srgb_to_linear(kSkyColorSrgb.r), srgb_to_linear(kSkyColorSrgb.g), srgb_to_linear(kSkyColorSrgb.b)));
  set_atmosphere_uniforms(program_, settings, at.height_m);
  program_.set_int("u_packed_distance", gbuffer.packed_distance() ? 1 : 0);
  const bool has_ao = ambient_occlusion != nullptr && *ambient_occlusion;
  program_.set_int("u_has_ao", has_ao ? 1 : 0);
  // The shadow lookup works in camera-relative ECEF (the cascades' matrices); the G-buffer is in
  // view space: the shader turns its positions and normals back with the view rotation's inverse.
  const glm::dmat3 to_ecef = glm::transpose(to_view);
  std::array<float, 9> view_to_ecef{};
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) view_to_ecef[static_cast<std::size_t>(c * 3 + r)] = static_cast<float>(to_ecef[c][r]);
  program_.set_mat3("u_view_to_ecef", std::span<const float, 9>(view_to_ecef));
  const bool has_shadows = shadows != nullptr && shadows->maps != nullptr && shadows->cascades != nullptr;
  program_.set_int("u_has_shadows", has_shadows ? 1 : 0);
  // The array sampler always gets its own unit: two sampler types on one unit is a GL error at
  // the draw even when the shader never samples it.
  program_.set_int("u_shadow_maps", kShadowUnit);
  if (has_shadows) shadows->maps->bind_for_lookup(program_, *shadows->cascades, kShadowUnit);

  const GLuint textures[] = {gbuffer.albedo().id(), gbuffer.normal().id(), gbuffer.distance().id(),
                             has_ao ? ambient_occlusion->id() : 0u};
  const char* names[] = {"u_albedo", "u_normal", "u_distance", "u_ao"};
  for (int unit = 0; unit < 4; ++unit) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, textures[unit]);
    program_.set_int(names[unit], unit);
  }
  glBindVertexArray(fullscreen_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  for (int unit = 3; unit >= 0; --unit) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  if (has_shadows) {
    glActiveTexture(GL_TEXTURE0 + kShadowUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    glActiveTexture(GL_TEXTURE0);
  }
  throw_on_gl_error("composing the frame");
}

}  // namespace trailray::render
