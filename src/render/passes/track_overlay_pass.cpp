// The track pass's overlay (track_pass.hpp): its target, the curtains, the hits the terrain
// hides and the fringe, drawn after the visible tracks from their depth; blended over the frame.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "render/passes/track_pass.hpp"
#include "render/passes/track_pass_draws.hpp"

namespace trailray::render {
using namespace track_pass_detail;  // NOLINT: this file is the pass's own

namespace {

// The pixels the tracks' capsules can cover, as GL's scissor box (x, y from the bottom left, width,
// height): the union of the images of a cube around each track's bounding sphere, grown by the
// tube's radius in metres and, in pixels, by its width, a pin's lift and the fringe. Nullopt: all
// of the frame (a cube reaching behind the camera).
std::optional<std::array<int, 4>> tracks_scissor(std::span<const TrackDraw> tracks, const scene::Camera& camera,
                                                 const TrackSceneSettings& settings) {
  const scene::Lens& lens = camera.lens();
  double min_x = lens.width_px, min_y = lens.height_px, max_x = 0.0, max_y = 0.0;
  const scene::CameraAxes& axes = camera.axes();
  for (const TrackDraw& draw : tracks) {
    if (!drawable(draw)) continue;
    const scene::TrackWidth width = draw.shape.width.value_or(settings.width);
    const bool in_pixels = width.unit == scene::TrackWidth::Unit::pixels;
    const double reach_m = draw.buffer->bounding_radius_m() + (in_pixels ? 0.0 : width.value) + draw.shape.lift_m;
    const double reach_px = (in_pixels ? width.value : 0.0) + draw.shape.min_width_px.value_or(settings.min_width_px) +
                            draw.shape.lift_px + 4.0;
    for (int corner = 0; corner < 8; ++corner) {
      const glm::dvec3 p = draw.buffer->bounding_centre_ecef() +
                           reach_m * ((corner & 1 ? 1.0 : -1.0) * axes.forward +
                                      (corner & 2 ? 1.0 : -1.0) * axes.right + (corner & 4 ? 1.0 : -1.0) * axes.up);
      const auto at = camera.project(p);
      if (!at || at->depth_m <= camera.depth_range().near_m) return std::nullopt;
      min_x = std::min(min_x, at->x_px - reach_px), max_x = std::max(max_x, at->x_px + reach_px);
      min_y = std::min(min_y, at->y_px - reach_px), max_y = std::max(max_y, at->y_px + reach_px);
    }
  }
  const auto clamp_to = [](double v, double limit) { return static_cast<int>(std::clamp(v, 0.0, limit)); };
  const int x0 = clamp_to(std::floor(min_x), lens.width_px), x1 = clamp_to(std::ceil(max_x), lens.width_px);
  const int y0 = clamp_to(std::floor(min_y), lens.height_px), y1 = clamp_to(std::ceil(max_y), lens.height_px);
  // Image rows run down, GL's window rows up.
  return std::array<int, 4>{x0, static_cast<int>(lens.height_px) - y1, std::max(x1 - x0, 0), std::max(y1 - y0, 0)};
}

}  // namespace

TrackOverlayTarget::TrackOverlayTarget(int width, int height) : frame_(width, height) {}

void TrackOverlayTarget::bind_with_depth_of(const GBuffer& gbuffer) const {
  bind_and_clear();
  glBindFramebuffer(GL_READ_FRAMEBUFFER, gbuffer.framebuffer_id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, frame_.framebuffer_id());
  glBlitFramebuffer(0, 0, gbuffer.width(), gbuffer.height(), 0, 0, width(), height(), GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  frame_.bind();
}

void TrackOverlayTarget::bind_and_clear() const {
  frame_.bind();
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClearDepthf(1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
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
  set_scale_uniforms(curtain_, settings);
  for (const TrackDraw& draw : tracks) {
    if (!drawable(draw) || !draw.buffer->has_drops()) continue;
    bind_buffer(curtain_, *draw.buffer);
    bind_texture(kDropsUnit, draw.buffer->drops());
    const std::vector<float> styles = style_texels(draw);
    // Segment by segment in its track's colour (a wall per segment: curtains are few).
    for (const TrackBuffer::Range& range : draw.buffer->segments()) {
      if (range.count < 2 || !draw.shows_track(range.track)) continue;
      const auto style = static_cast<std::size_t>(draw.track_styles.empty() ? 0 : range.track);
      set_vec3(curtain_, "u_color", {styles[style * 4], styles[style * 4 + 1], styles[style * 4 + 2]});
      curtain_.set_int("u_by_value", styles[style * 4 + 3] > 0.0f ? 1 : 0);
      curtain_.set_int("u_first", range.first);
      curtain_.set_int("u_last", range.first + range.count - 1);
      curtain_.set_int("u_first_block", range.first_block);
      curtain_.set_int("u_block_shift", range.block_shift);
      for (std::int32_t done = 0; done < range.count - 1; done += kCapsulesPerDraw) {
        curtain_.set_int("u_chunk_first", range.first + done);
        glDrawElements(GL_TRIANGLES, std::min(kCapsulesPerDraw, range.count - 1 - done) * 6, GL_UNSIGNED_SHORT,
                       nullptr);
      }
    }
  }
  glDisable(GL_BLEND);
}

void TrackPass::prefill_overlay_depth(const GBuffer& gbuffer, const TrackOverlayTarget& target,
                                      const scene::Camera& camera, std::span<const TrackDraw> tracks,
                                      const TrackSceneSettings& settings) const {
  target.bind_with_depth_of(gbuffer);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_TRUE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  prefill_.use();
  prefill_.set_int("u_distance", static_cast<int>(kFrameDistanceUnit));
  prefill_.set_int("u_terrain_distance", static_cast<int>(kTerrainDistanceUnit));
  prefill_.set_int("u_packed_distance", gbuffer.packed_distance() ? 1 : 0);
  prefill_.set_float("u_depth_step_k", depth_step_k(camera));
  bind_texture(kFrameDistanceUnit, gbuffer.distance());
  bind_texture(kTerrainDistanceUnit, terrain_copy_.distance);
  glBindVertexArray(empty_.id());
  glDepthRangef(1.0f, 1.0f);  // the triangle's depth: far
  // Only where capsules can be (a fullscreen pass costs a CPU rasterizer milliseconds): elsewhere
  // the copy keeps the terrain's depth, which no capsule fragment is tested against.
  const auto scissor = tracks_scissor(tracks, camera, settings);
  if (scissor) {
    glEnable(GL_SCISSOR_TEST);
    glScissor((*scissor)[0], (*scissor)[1], (*scissor)[2], (*scissor)[3]);
  }
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_SCISSOR_TEST);
  glDepthRangef(0.0f, 1.0f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthFunc(GL_LESS);
  check_gl("copying the visible tracks' depth into the track overlay");
}

bool TrackPass::prefills_overlay_depth(const GBuffer& gbuffer, const TrackSceneSettings& settings) const {
  switch (settings.overlay_depth) {
    case OverlayDepth::prefilled:
      return true;
    case OverlayDepth::tested_in_shaders:
      return false;
    case OverlayDepth::chosen:
      break;
  }
  // A capsule's quad covers some tens of pixels (5 px wide, a few long, with its margin): the
  // prefill pays once the capsules' quads could cover the frame about once.
  constexpr double kQuadPixels = 64.0;
  return static_cast<double>(visible_capsules_) * kQuadPixels >
         static_cast<double>(gbuffer.width()) * static_cast<double>(gbuffer.height());
}

void TrackPass::set_overlay_uniforms(const ShaderProgram& program, const GBuffer& gbuffer, const scene::Camera& camera,
                                     const SceneLighting& lighting, const TrackSceneSettings& settings,
                                     const std::array<float, 16>& view_projection) const {
  const scene::GeoPosition& at = camera.geodetic();
  const glm::vec3 up(scene::enu_axes_at(at.lat_deg, at.lon_deg).up);
  const glm::vec3 sun(glm::normalize(lighting.sun_direction_ecef));
  program.use();
  program.set_mat4("u_view_projection", std::span<const float, 16>(view_projection));
  program.set_int("u_orthographic", 0);
  program.set_float("u_margin_px", kFringeMarginPx);
  program.set_int("u_colormap", static_cast<int>(kColormapUnit));
  program.set_int("u_terrain_distance", static_cast<int>(kTerrainDistanceUnit));
  program.set_int("u_packed_distance", gbuffer.packed_distance() ? 1 : 0);
  program.set_int("u_terrain_normal", static_cast<int>(kTerrainNormalUnit));
  const std::array<float, 9> rotation = to_float_mat3(camera.view_rotation());
  program.set_mat3("u_view_rotation", std::span<const float, 9>(rotation));
  program.set_int("u_show_occluded", settings.occlusion.enabled ? 1 : 0);
  program.set_float("u_occluded_alpha", settings.occlusion.alpha);
  program.set_vec2("u_fade", settings.occlusion.fade_near_m, settings.occlusion.fade_far_m);
  program.set_float("u_depth_step_k", depth_step_k(camera));
  program.set_float("u_camera_height_m", static_cast<float>(at.height_m));
  program.set_float("u_terrain_top_m", static_cast<float>(settings.terrain_top_m.value_or(0.0)));
  set_vec3(program, "u_sun", sun);
  set_vec3(program, "u_up", up);
  set_vec3(program, "u_sun_radiance", lighting.sun_radiance);
  set_vec3(program, "u_sky_radiance", lighting.sky_radiance);
  set_width_uniforms(program, camera);
  set_scale_uniforms(program, settings);
}

void TrackPass::draw_overlay(const GBuffer& gbuffer, const TrackOverlayTarget& target, const scene::Camera& camera,
                             const SceneLighting& lighting, std::span<const TrackDraw> tracks,
                             const TrackSceneSettings& settings) const {
  // Split (track_pass.hpp), the capsules above all the terrain add only their fringe and do not
  // trace their hits here, so what lies behind a visible track is dropped otherwise: either the
  // overlay's depth starts as the visible tracks' (the prefill: a pass over the tracks' screen
  // rectangle, about 15 ms at 1920x1080 on llvmpipe, after which the depth test rejects those
  // fragments before any shader), or its shaders test each fragment against the G-buffer's
  // distance (behind_visible_track.glsl: a texel and a comparison per fragment). The prefill pays
  // where many capsules overlap.
  const bool split = settings.terrain_top_m.has_value();
  const bool prefill = split && prefills_overlay_depth(gbuffer, settings);
  if (prefill) {
    prefill_overlay_depth(gbuffer, target, camera, tracks, settings);
  } else {
    target.bind_and_clear();
  }
  bind_texture(kFrameDistanceUnit, gbuffer.distance());
  const auto set_visible_track_uniforms = [&](const ShaderProgram& program) {
    program.use();
    program.set_int("u_frame_distance", static_cast<int>(kFrameDistanceUnit));
    program.set_int("u_test_visible_tracks", split && !prefill ? 1 : 0);
  };
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  const std::array<float, 16> view_projection = camera.view_projection_relative_to(camera.position());
  // The terrain alone: draw_visible's copies (the G-buffer holds the tracks by now).
  bind_texture(kTerrainDistanceUnit, terrain_copy_.distance);
  bind_texture(kTerrainNormalUnit, terrain_copy_.normal);
  bind_colormap(settings.colormap, kColormapUnit);
  glBindVertexArray(quads_.id());

  // Curtains first, blended, so that a tube in front of a wall replaces it and one behind is
  // hidden by its depth.
  if (settings.curtain) {
    set_visible_track_uniforms(curtain_);
    curtain_.set_float("u_depth_step_k", depth_step_k(camera));
    draw_curtains(gbuffer, camera, lighting, tracks, settings, view_projection);
  }

  // A dashed draw's gaps show what is behind them: its capsules are all traced.
  const auto split_of = [&](const TrackDraw& draw) { return split && draw.shape.dash_px <= 0.0f; };
  set_overlay_uniforms(overlay_, gbuffer, camera, lighting, settings, view_projection);
  set_visible_track_uniforms(overlay_);
  for (const TrackDraw& draw : tracks) {
    if (!drawable(draw)) continue;
    overlay_.set_int("u_overlay_split", split_of(draw) ? 1 : 0);
    set_shape_uniforms(overlay_, draw, settings);
    draw_pieces(overlay_, draw);
  }
  if (split) {
    set_overlay_uniforms(fringe_, gbuffer, camera, lighting, settings, view_projection);
    set_visible_track_uniforms(fringe_);
    fringe_.set_int("u_overlay_split", 2);
    for (const TrackDraw& draw : tracks) {
      if (!drawable(draw) || !split_of(draw)) continue;
      set_shape_uniforms(fringe_, draw, settings);
      draw_pieces(fringe_, draw);
    }
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

}  // namespace trailray::render
