#include "render/passes/track_pass.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "render/gl/render_error.hpp"
#include "render/passes/texel_table.hpp"
#include "render/passes/track_pass_draws.hpp"

namespace trailray::render {
using namespace track_pass_detail;  // NOLINT: this file is the pass's own

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

TrackPass::TrackPass()
    : visible_(ShaderProgram::from_embedded("track.vert", "track_visible.frag")),
      overlay_(ShaderProgram::from_embedded("track.vert", "track_overlay.frag")),
      fringe_(ShaderProgram::from_embedded("track.vert", "track_fringe.frag")),
      prefill_(ShaderProgram::from_embedded("fullscreen_triangle.vert", "overlay_prefill.frag")),
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

namespace {

Texture upload_pieces(const CapsulePieces& pieces) {
  std::vector<std::int32_t> table = pieces.texels();
  return texel_table::upload(table, 4, texel_table::width_for(table.size() / 4), GL_RGBA32I, GL_RGBA_INTEGER, GL_INT);
}

}  // namespace

bool TrackDraw::shows_track(std::int32_t track) const {
  if (track_styles.empty()) return true;
  return track >= 0 && static_cast<std::size_t>(track) < track_styles.size() &&
         track_styles[static_cast<std::size_t>(track)].visible;
}

std::size_t TrackDraw::shown_tracks() const {
  if (track_styles.empty()) return 1;
  return static_cast<std::size_t>(
      std::count_if(track_styles.begin(), track_styles.end(), [](const TrackDrawStyle& s) { return s.visible; }));
}

void TrackPass::prepare(std::span<const TrackDraw> tracks, const scene::Camera& camera,
                        const TrackSceneSettings& settings) {
  frame_pieces_.clear();
  for (const TrackDraw& draw : tracks) {
    if (!drawable(draw)) continue;
    const_cast<TrackBuffer*>(draw.buffer)->set_eye(camera.position());
    const PiecesKey key{draw.buffer, static_cast<int>(draw.shape.capsules)};
    if (frame_pieces_.contains(key)) continue;
    std::function<bool(std::int32_t)> shown;
    if (!draw.track_styles.empty()) shown = [&draw](std::int32_t track) { return draw.shows_track(track); };
    CapsulePieces pieces =
        plan_capsule_pieces(*draw.buffer, draw.shape.capsules, lod_view_for(camera, draw, settings), shown);
    FramePieces frame;
    frame.table = upload_pieces(pieces);
    frame.pieces = std::move(pieces);
    std::vector<float> styles = style_texels(draw);
    frame.styles =
        texel_table::upload(styles, 4, texel_table::width_for(styles.size() / 4), GL_RGBA32F, GL_RGBA, GL_FLOAT);
    frame_pieces_.emplace(key, std::move(frame));
  }
  check_gl("uploading the tracks' pieces for the frame");
}

// The quads' vertex array (with the index buffer) must be bound: each size class of pieces is one
// instanced draw, an instance per piece (track.vert reads its texels by gl_InstanceID).
std::size_t TrackPass::draw_pieces(const ShaderProgram& program, const TrackDraw& draw,
                                   const std::pair<const CapsulePieces*, const Texture*>& only) const {
  const FramePieces& frame = prepared(draw);
  const CapsulePieces& pieces = only.first != nullptr ? *only.first : frame.pieces;
  bind_buffer(program, *draw.buffer);
  bind_texture(kPiecesUnit, only.second != nullptr ? *only.second : frame.table);
  bind_texture(kStylesUnit, frame.styles);
  program.set_int("u_pieces", static_cast<int>(kPiecesUnit));
  program.set_int("u_track_styles", static_cast<int>(kStylesUnit));
  for (const CapsulePieces::Class& c : pieces.classes) {
    if (c.count == 0) continue;
    program.set_int("u_piece_base", c.first);
    glDrawElementsInstanced(GL_TRIANGLES, c.capsules * 6, GL_UNSIGNED_SHORT, nullptr, c.count);
  }
  return pieces.capsule_count;
}

const TrackPass::FramePieces& TrackPass::prepared(const TrackDraw& draw) const {
  const auto found = frame_pieces_.find(PiecesKey{draw.buffer, static_cast<int>(draw.shape.capsules)});
  if (found == frame_pieces_.end()) throw RenderError("track pass: a draw was not prepared for this frame");
  return found->second;
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
  set_scale_uniforms(visible_, settings);
  bind_colormap(settings.colormap, kColormapUnit);
  glBindVertexArray(quads_.id());
  visible_capsules_ = 0;
  for (const TrackDraw& draw : tracks) {
    if (!drawable(draw)) continue;
    set_shape_uniforms(visible_, draw, settings);
    visible_capsules_ += draw_pieces(visible_, draw);
  }
  glBindVertexArray(0);
  glDisable(GL_DEPTH_TEST);
  glActiveTexture(GL_TEXTURE0);
  check_gl("drawing the tracks into the G-buffer");
}

void TrackPass::draw_shadow_casters(const std::array<float, 16>& light_view_projection,
                                    const glm::dvec3& towards_sun_ecef, double texel_m, const scene::Camera& camera,
                                    std::span<const TrackDraw> tracks, const TrackSceneSettings& settings,
                                    const SphereTest& may_hold) const {
  shadow_.use();
  shadow_.set_mat4("u_view_projection", std::span<const float, 16>(light_view_projection));
  shadow_.set_int("u_orthographic", 1);
  const glm::vec3 towards(glm::normalize(towards_sun_ecef));
  set_vec3(shadow_, "u_towards_light", towards);
  shadow_.set_float("u_margin_px", kShadowMarginTexels);
  shadow_.set_float("u_texel_m", static_cast<float>(texel_m));
  set_width_uniforms(shadow_, camera);
  glBindVertexArray(quads_.id());
  for (const TrackDraw& draw : tracks) {
    if (!drawable(draw)) continue;
    set_shape_uniforms(shadow_, draw, settings);
    // The camera's levels (prepare): a shadow is at most as sharp as the tube that casts it.
    const std::vector<TrackBuffer::Sphere>& spheres = draw.buffer->track_spheres();
    if (!may_hold || spheres.size() < 2) {
      draw_pieces(shadow_, draw);
      continue;
    }
    // Many tracks: only the pieces of those that can reach this cascade.
    std::vector<std::uint8_t> reaches(spheres.size());
    bool all = true;
    for (std::size_t t = 0; t < spheres.size(); ++t) {
      reaches[t] = may_hold(spheres[t].centre, spheres[t].radius) ? 1 : 0;
      all = all && reaches[t] != 0;
    }
    if (all) {
      draw_pieces(shadow_, draw);
      continue;
    }
    const CapsulePieces kept = prepared(draw).pieces.filtered(
        [&](const CapsulePiece& p) { return reaches[static_cast<std::size_t>(p.track)] != 0; });
    if (kept.pieces.empty()) continue;
    const Texture table = upload_pieces(kept);
    draw_pieces(shadow_, draw, {&kept, &table});
  }
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE0);
  check_gl("drawing the tracks into the shadow maps");
}

}  // namespace trailray::render
