#include "render/passes/track_pass_draws.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "render/gl/render_error.hpp"

namespace trailray::render::track_pass_detail {
namespace {

// The camera's pixel size per metre of view depth.
float pixel_angle(const scene::Camera& camera) {
  const scene::Lens& lens = camera.lens();
  return static_cast<float>(2.0 * std::tan(0.5 * lens.vertical_fov_deg * M_PI / 180.0) / lens.height_px);
}

}  // namespace

glm::vec3 srgb_to_linear(const glm::vec3& c) {
  const auto one = [](float v) {
    v = std::clamp(v, 0.0f, 1.0f);
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
  };
  return {one(c.r), one(c.g), one(c.b)};
}

std::vector<float> style_texels(const TrackDraw& draw) {
  const bool values = draw.buffer->has_values();
  std::vector<float> out;
  const auto add = [&](const glm::vec3& srgb, bool by_value) {
    const glm::vec3 linear = srgb_to_linear(srgb);
    for (const float v : {linear.r, linear.g, linear.b, by_value && values ? 1.0f : 0.0f}) out.push_back(v);
  };
  if (draw.track_styles.empty()) {
    add(draw.color_srgb, draw.by_value);
  } else {
    out.reserve(draw.track_styles.size() * 4);
    for (const TrackDrawStyle& style : draw.track_styles) add(style.color_srgb, style.by_value);
  }
  return out;
}

void check_gl(const char* what) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) throw RenderError(std::string(what) + " failed (GL error " + std::to_string(error) + ")");
}

void set_vec3(const ShaderProgram& program, std::string_view name, const glm::vec3& v) {
  program.set_vec3(name, v.x, v.y, v.z);
}

std::array<float, 9> to_float_mat3(const glm::dmat3& m) {
  std::array<float, 9> out{};
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) out[static_cast<std::size_t>(c * 3 + r)] = static_cast<float>(m[c][r]);
  return out;
}

// Uniforms every capsule program shares: the camera's pixel size and vertical.
void set_width_uniforms(const ShaderProgram& program, const scene::Camera& camera) {
  program.set_int("u_points", static_cast<int>(kPointsUnit));
  program.set_int("u_blocks", static_cast<int>(kBlocksUnit));
  program.set_float("u_pixel_angle", pixel_angle(camera));
  const glm::vec3 forward(camera.axes().forward);
  set_vec3(program, "u_camera_forward", forward);
  const scene::GeoPosition& at = camera.geodetic();
  const glm::vec3 up(scene::enu_axes_at(at.lat_deg, at.lon_deg).up);
  set_vec3(program, "u_up", up);
}

// A draw's own shape (track_pass.hpp CapsuleShape): width, dashes, the raised last points.
void set_shape_uniforms(const ShaderProgram& program, const TrackDraw& draw, const TrackSceneSettings& settings) {
  const scene::TrackWidth width = draw.shape.width.value_or(settings.width);
  program.set_float("u_width_value", static_cast<float>(width.value));
  program.set_int("u_width_in_pixels", width.unit == scene::TrackWidth::Unit::pixels ? 1 : 0);
  program.set_float("u_min_width_px", static_cast<float>(draw.shape.min_width_px.value_or(settings.min_width_px)));
  program.set_float("u_dash_px", draw.shape.dash_px);
  program.set_vec2("u_lift", draw.shape.lift_px, draw.shape.lift_m);
  program.set_int("u_capsule_mode", static_cast<int>(draw.shape.capsules));
}

// A 24-bit depth buffer resolves about d^2 / (near * 2^24) metres at distance d (camera.hpp): k
// of the shaders' "d * d * k", doubled for the rounding of the depth written and the one tested.
float depth_step_k(const scene::Camera& camera) {
  return static_cast<float>(2.0 / (camera.depth_range().near_m * 16777216.0));
}

void set_scale_uniforms(const ShaderProgram& program, const TrackSceneSettings& settings) {
  set_vec3(program, "u_missing_color", srgb_to_linear(scene::kMissingValueColorSrgb));
  set_vec3(program, "u_category_color", srgb_to_linear(scene::kCategoryColorSrgb));
  program.set_vec2("u_value_range", settings.value_min, settings.value_max);
}

void bind_texture(GLuint unit, const Texture& texture) {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, texture.id());
}

// The index buffer every capsule draw shares: 0 1 2 2 1 3 for each quad of four vertices, so the
// vertex shader runs four times per capsule instead of six (post-transform cache), and only the
// two provoking corners fetch the neighbours.
Buffer make_quad_indices() {
  std::vector<std::uint16_t> indices;
  indices.reserve(static_cast<std::size_t>(kCapsulesPerDraw) * 6);
  for (std::int32_t q = 0; q < kCapsulesPerDraw; ++q) {
    const auto base = static_cast<std::uint16_t>(q * 4);
    for (const int corner : {0, 1, 2, 2, 1, 3}) indices.push_back(static_cast<std::uint16_t>(base + corner));
  }
  Buffer buffer = Buffer::create();
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint16_t)), indices.data(),
               GL_STATIC_DRAW);
  return buffer;
}

std::optional<TrackLod::View> lod_view_for(const scene::Camera& camera, const TrackDraw& draw,
                                           const TrackSceneSettings& settings) {
  if (!settings.level_of_detail || draw.buffer == nullptr || draw.shape.capsules != CapsuleShape::Capsules::polyline ||
      draw.shape.dash_px > 0.0f || draw.shape.lift_px > 0.0f || draw.shape.lift_m > 0.0f)
    return std::nullopt;
  TrackLod::View view;
  view.eye = camera.position();
  view.forward = camera.axes().forward;
  const scene::Lens& lens = camera.lens();
  const double tan_v = std::tan(0.5 * lens.vertical_fov_deg * M_PI / 180.0);
  const double tan_h = tan_v * lens.width_px / std::max<double>(lens.height_px, 1.0);
  view.pixel_angle = pixel_angle(camera);
  view.corner_tangent = std::hypot(tan_v, tan_h);
  view.by_value = draw.by_value && draw.buffer->has_values();
  view.value_range = std::abs(static_cast<double>(settings.value_max) - settings.value_min);
  return view;
}

void bind_buffer(const ShaderProgram& program, const TrackBuffer& buffer) {
  bind_texture(kPointsUnit, buffer.points());
  bind_texture(kBlocksUnit, buffer.blocks());
  // Always bound: an integer sampler must never see another unit's float texture.
  bind_texture(kLodUnit, buffer.lod_indices());
  program.set_int("u_lod_indices", static_cast<int>(kLodUnit));
}

bool drawable(const TrackDraw& draw) { return draw.buffer != nullptr && draw.buffer->point_count() > 0; }

}  // namespace trailray::render::track_pass_detail
