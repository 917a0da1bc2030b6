#include "render/passes/track_pass.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "render/gl/render_error.hpp"

namespace trailray::render {
namespace {

// Texture units of the track programs.
constexpr GLuint kPointsUnit = 0, kBlocksUnit = 1, kColormapUnit = 2, kTerrainDistanceUnit = 3, kDropsUnit = 4,
                 kTerrainNormalUnit = 5;
// The quad's margin for the anti-aliased fringe (pixels), and the shadow quad's (texels).
constexpr float kFringeMarginPx = 1.0f;  // the fringe reaches half a pixel past the silhouette
constexpr float kShadowMarginTexels = 1.0f;

void check_gl(const char* what) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) throw RenderError(std::string(what) + " failed (GL error " + std::to_string(error) + ")");
}

glm::vec3 srgb_to_linear(const glm::vec3& c) {
  const auto one = [](float v) {
    v = std::clamp(v, 0.0f, 1.0f);
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
  };
  return {one(c.r), one(c.g), one(c.b)};
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

// The camera's pixel size per metre of view depth.
float pixel_angle(const scene::Camera& camera) {
  const scene::Lens& lens = camera.lens();
  return static_cast<float>(2.0 * std::tan(0.5 * lens.vertical_fov_deg * M_PI / 180.0) / lens.height_px);
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

void set_color_uniforms(const ShaderProgram& program, const TrackDraw& draw, const TrackSceneSettings& settings) {
  program.set_int("u_by_value", draw.by_value && draw.buffer->has_values() ? 1 : 0);
  set_vec3(program, "u_color", srgb_to_linear(draw.color_srgb));
  set_vec3(program, "u_missing_color", srgb_to_linear(scene::kMissingValueColorSrgb));
  set_vec3(program, "u_category_color", srgb_to_linear(scene::kCategoryColorSrgb));
  program.set_vec2("u_value_range", settings.value_min, settings.value_max);
}

void bind_texture(GLuint unit, const Texture& texture) {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, texture.id());
}

// Capsules per draw call: the shared index buffer's 16-bit indices reach 4 * 16384 vertices.
constexpr std::int32_t kCapsulesPerDraw = 16384;

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

// Draws every segment of the track, a capsule per pair of consecutive points (a segment of one
// point is a sphere: a zero-length capsule), or per pair or point standing alone (`capsules`),
// in chunks of kCapsulesPerDraw. The quads' vertex array (with the index buffer) must be bound.
void draw_segments(const ShaderProgram& program, const TrackBuffer& buffer,
                   CapsuleShape::Capsules capsules = CapsuleShape::Capsules::polyline) {
  bind_texture(kPointsUnit, buffer.points());
  bind_texture(kBlocksUnit, buffer.blocks());
  program.set_int("u_block_shift", buffer.block_shift());
  for (const TrackBuffer::Range& range : buffer.segments()) {
    if (range.count <= 0) continue;
    program.set_int("u_first", range.first);
    program.set_int("u_first_block", range.first_block);
    program.set_int("u_last", range.first + range.count - 1);
    const std::int32_t points_per_capsule = capsules == CapsuleShape::Capsules::pairs ? 2 : 1;
    const std::int32_t total = capsules == CapsuleShape::Capsules::polyline ? std::max(range.count - 1, 1)
                               : capsules == CapsuleShape::Capsules::pairs  ? range.count / 2
                                                                            : range.count;
    for (std::int32_t done = 0; done < total; done += kCapsulesPerDraw) {
      program.set_int("u_chunk_first", range.first + done * points_per_capsule);
      const std::int32_t count = std::min(kCapsulesPerDraw, total - done);
      glDrawElements(GL_TRIANGLES, count * 6, GL_UNSIGNED_SHORT, nullptr);
    }
  }
}

bool drawable(const TrackDraw& draw) { return draw.buffer != nullptr && draw.buffer->point_count() > 0; }

}  // namespace

TrackSceneSettings track_settings_for(const scene::TrackStyle& style, const std::optional<track::ValueRange>& range) {
  TrackSceneSettings s;
  s.width = style.width;
  s.min_width_px = style.min_width_px;
  s.occlusion = style.occlusion;
  s.curtain = style.curtain;
  s.curtain_alpha = style.curtain_alpha;
  s.colormap = style.colormap;
  s.cast_shadows = style.cast_shadows;
  if (range) {
    s.value_min = static_cast<float>(range->min);
    s.value_max = static_cast<float>(range->max);
  }
  return s;
}

TrackOverlayTarget::TrackOverlayTarget(int width, int height) : frame_(width, height) {}

void TrackOverlayTarget::bind_and_clear() const {
  frame_.bind();
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClearDepthf(1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

TrackPass::TrackPass()
    : visible_(ShaderProgram::from_embedded("track.vert", "track_visible.frag")),
      overlay_(ShaderProgram::from_embedded("track.vert", "track_overlay.frag")),
      shadow_(ShaderProgram::from_embedded("track.vert", "track_shadow.frag")),
      curtain_(ShaderProgram::from_embedded("track_curtain.vert", "track_curtain.frag")),
      blend_(ShaderProgram::from_embedded("fullscreen_triangle.vert", "overlay_blend.frag")),
      empty_(VertexArray::create()),
      quads_(VertexArray::create()) {
  // The element buffer binding is vertex array state: the quads' array keeps it.
  glBindVertexArray(quads_.id());
  quad_indices_ = make_quad_indices();
  glBindVertexArray(0);
}

void TrackPass::bind_colormap(scene::Colormap map, GLuint unit) const {
  // Making the texture binds it to the active unit: make that unit the colormap's own, so the
  // textures already bound to other units stay.
  glActiveTexture(GL_TEXTURE0 + unit);
  if (!colormap_ || colormap_loaded_ != map) {
    const scene::ColormapTable& table = scene::colormap_table(map);
    std::vector<std::uint8_t> rgba;
    rgba.reserve(scene::kColormapSize * 4);
    for (const glm::u8vec3& c : table) rgba.insert(rgba.end(), {c.r, c.g, c.b, 255});
    Texture texture = make_texture_2d(GL_SRGB8_ALPHA8, static_cast<int>(scene::kColormapSize), 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, static_cast<GLsizei>(scene::kColormapSize), 1, GL_RGBA, GL_UNSIGNED_BYTE,
                    rgba.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    colormap_ = std::move(texture);
    colormap_loaded_ = map;
  }
  bind_texture(unit, colormap_);
}

void TrackPass::prepare(std::span<const TrackDraw> tracks, const scene::Camera& camera) {
  for (const TrackDraw& draw : tracks)
    if (draw.buffer != nullptr) const_cast<TrackBuffer*>(draw.buffer)->set_eye(camera.position());
}

void TrackPass::copy_terrain(const GBuffer& gbuffer) const {
  TerrainCopy& copy = terrain_copy_;
  const int width = gbuffer.width(), height = gbuffer.height();
  if (!copy.target || copy.width != width || copy.height != height || copy.packed != gbuffer.packed_distance()) {
    copy = TerrainCopy{};
    copy.distance = make_texture_2d(gbuffer.packed_distance() ? GL_RGBA8 : GL_R32F, width, height);
    copy.normal = make_texture_2d(GL_RGB10_A2, width, height);
    copy.source = Framebuffer::create();
    copy.target = Framebuffer::create();
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, copy.target.id());
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, copy.distance.id(), 0);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, copy.normal.id(), 0);
    check_framebuffer_complete(GL_DRAW_FRAMEBUFFER, "track pass terrain copy");
    copy.width = width;
    copy.height = height;
    copy.packed = gbuffer.packed_distance();
  }
  // The G-buffer's textures are attached anew each frame: the renderer may hand a different one.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, copy.source.id());
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, gbuffer.distance().id(), 0);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, gbuffer.normal().id(), 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, copy.target.id());
  // One attachment at a time: a blit copies its read buffer into every draw buffer.
  for (const GLenum attachment : {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1}) {
    glReadBuffer(attachment);
    const std::array<GLenum, 2> draw{attachment == GL_COLOR_ATTACHMENT0 ? attachment : GL_NONE,
                                     attachment == GL_COLOR_ATTACHMENT1 ? attachment : GL_NONE};
    glDrawBuffers(static_cast<GLsizei>(draw.size()), draw.data());
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  // Detach the G-buffer's textures, so no framebuffer but the G-buffer's own keeps them.
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, 0, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("copying the terrain's distance and normal for the track pass");
}

void TrackPass::draw_visible(const GBuffer& gbuffer, const scene::Camera& camera, std::span<const TrackDraw> tracks,
                             const TrackSceneSettings& settings) const {
  copy_terrain(gbuffer);
  gbuffer.bind();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  visible_.use();
  const std::array<float, 16> view_projection = camera.view_projection_relative_to(camera.position());
  visible_.set_mat4("u_view_projection", std::span<const float, 16>(view_projection));
  const std::array<float, 9> rotation = to_float_mat3(camera.view_rotation());
  visible_.set_mat3("u_view_rotation", std::span<const float, 9>(rotation));
  visible_.set_int("u_packed_distance", gbuffer.packed_distance() ? 1 : 0);
  visible_.set_int("u_terrain_distance", static_cast<int>(kTerrainDistanceUnit));
  visible_.set_int("u_terrain_normal", static_cast<int>(kTerrainNormalUnit));
  visible_.set_float("u_depth_step_k", depth_step_k(camera));
  bind_texture(kTerrainDistanceUnit, terrain_copy_.distance);
  bind_texture(kTerrainNormalUnit, terrain_copy_.normal);
  visible_.set_int("u_orthographic", 0);
  visible_.set_float("u_margin_px", 0.0f);
  visible_.set_int("u_colormap", static_cast<int>(kColormapUnit));
  set_width_uniforms(visible_, camera);
  bind_colormap(settings.colormap, kColormapUnit);
  glBindVertexArray(quads_.id());
  for (const TrackDraw& draw : tracks) {
    if (!drawable(draw)) continue;
    set_color_uniforms(visible_, draw, settings);
    set_shape_uniforms(visible_, draw, settings);
    draw_segments(visible_, *draw.buffer, draw.shape.capsules);
  }
  glBindVertexArray(0);
  glDisable(GL_DEPTH_TEST);
  glActiveTexture(GL_TEXTURE0);
  check_gl("drawing the tracks into the G-buffer");
}

void TrackPass::draw_curtains(const GBuffer& gbuffer, const scene::Camera& camera, const SceneLighting& lighting,
                              std::span<const TrackDraw> tracks, const TrackSceneSettings& settings,
                              const std::array<float, 16>& view_projection) const {
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  curtain_.use();
  curtain_.set_mat4("u_view_projection", std::span<const float, 16>(view_projection));
  curtain_.set_int("u_points", static_cast<int>(kPointsUnit));
  curtain_.set_int("u_blocks", static_cast<int>(kBlocksUnit));
  curtain_.set_int("u_drops", static_cast<int>(kDropsUnit));
  curtain_.set_int("u_colormap", static_cast<int>(kColormapUnit));
  curtain_.set_int("u_terrain_distance", static_cast<int>(kTerrainDistanceUnit));
  curtain_.set_int("u_packed_distance", gbuffer.packed_distance() ? 1 : 0);
  curtain_.set_float("u_curtain_alpha", settings.curtain_alpha);
  const glm::vec3 eye(camera.position());
  set_vec3(curtain_, "u_eye_ecef", eye);
  set_vec3(curtain_, "u_sun_radiance", lighting.sun_radiance);
  set_vec3(curtain_, "u_sky_radiance", lighting.sky_radiance);
  for (const TrackDraw& draw : tracks) {
    if (!drawable(draw) || !draw.buffer->has_drops()) continue;
    set_color_uniforms(curtain_, draw, settings);
    bind_texture(kDropsUnit, draw.buffer->drops());
    draw_segments(curtain_, *draw.buffer);
  }
  glDisable(GL_BLEND);
}

void TrackPass::draw_overlay(const GBuffer& gbuffer, const TrackOverlayTarget& target, const scene::Camera& camera,
                             const SceneLighting& lighting, std::span<const TrackDraw> tracks,
                             const TrackSceneSettings& settings) const {
  target.bind_and_clear();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  const std::array<float, 16> view_projection = camera.view_projection_relative_to(camera.position());
  const scene::GeoPosition& at = camera.geodetic();
  const glm::vec3 up(scene::enu_axes_at(at.lat_deg, at.lon_deg).up);
  const glm::vec3 sun(glm::normalize(lighting.sun_direction_ecef));
  bind_texture(kTerrainDistanceUnit, gbuffer.distance());
  bind_texture(kTerrainNormalUnit, gbuffer.normal());
  bind_colormap(settings.colormap, kColormapUnit);
  glBindVertexArray(quads_.id());

  // Curtains first, blended, so that a tube in front of a wall replaces it and one behind is
  // hidden by its depth.
  if (settings.curtain) draw_curtains(gbuffer, camera, lighting, tracks, settings, view_projection);

  overlay_.use();
  overlay_.set_mat4("u_view_projection", std::span<const float, 16>(view_projection));
  overlay_.set_int("u_orthographic", 0);
  overlay_.set_float("u_margin_px", kFringeMarginPx);
  overlay_.set_int("u_colormap", static_cast<int>(kColormapUnit));
  overlay_.set_int("u_terrain_distance", static_cast<int>(kTerrainDistanceUnit));
  overlay_.set_int("u_packed_distance", gbuffer.packed_distance() ? 1 : 0);
  overlay_.set_int("u_terrain_normal", static_cast<int>(kTerrainNormalUnit));
  const std::array<float, 9> rotation = to_float_mat3(camera.view_rotation());
  overlay_.set_mat3("u_view_rotation", std::span<const float, 9>(rotation));
  overlay_.set_int("u_show_occluded", settings.occlusion.enabled ? 1 : 0);
  overlay_.set_float("u_occluded_alpha", settings.occlusion.alpha);
  overlay_.set_vec2("u_fade", settings.occlusion.fade_near_m, settings.occlusion.fade_far_m);
  overlay_.set_float("u_depth_step_k", depth_step_k(camera));
  set_vec3(overlay_, "u_sun", sun);
  set_vec3(overlay_, "u_up", up);
  set_vec3(overlay_, "u_sun_radiance", lighting.sun_radiance);
  set_vec3(overlay_, "u_sky_radiance", lighting.sky_radiance);
  set_width_uniforms(overlay_, camera);
  for (const TrackDraw& draw : tracks) {
    if (!drawable(draw)) continue;
    set_color_uniforms(overlay_, draw, settings);
    set_shape_uniforms(overlay_, draw, settings);
    draw_segments(overlay_, *draw.buffer, draw.shape.capsules);
  }
  glBindVertexArray(0);
  glDisable(GL_DEPTH_TEST);
  glActiveTexture(GL_TEXTURE0);
  check_gl("drawing the track overlay");
}

void TrackPass::blend_overlay(const TrackOverlayTarget& target) const {
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  blend_.use();
  blend_.set_int("u_overlay", 0);
  bind_texture(0, target.color());
  glBindVertexArray(empty_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glDisable(GL_BLEND);
  check_gl("blending the track overlay");
}

void TrackPass::draw_shadow_casters(const std::array<float, 16>& light_view_projection,
                                    const glm::dvec3& towards_sun_ecef, double texel_m, const scene::Camera& camera,
                                    std::span<const TrackDraw> tracks, const TrackSceneSettings& settings) const {
  shadow_.use();
  shadow_.set_mat4("u_view_projection", std::span<const float, 16>(light_view_projection));
  shadow_.set_int("u_orthographic", 1);
  const glm::vec3 towards(glm::normalize(towards_sun_ecef));
  set_vec3(shadow_, "u_towards_light", towards);
  shadow_.set_float("u_margin_px", kShadowMarginTexels);
  shadow_.set_float("u_texel_m", static_cast<float>(texel_m));
  set_width_uniforms(shadow_, camera);
  glBindVertexArray(quads_.id());
  for (const TrackDraw& draw : tracks)
    if (drawable(draw)) {
      set_shape_uniforms(shadow_, draw, settings);
      draw_segments(shadow_, *draw.buffer, draw.shape.capsules);
    }
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE0);
  check_gl("drawing the tracks into the shadow maps");
}

}  // namespace trailray::render
