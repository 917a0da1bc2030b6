#include "render/renderer.hpp"

#include <algorithm>
#include <string_view>
#include <utility>

#include "render/gl/gl_capabilities.hpp"
#include "render/passes/shadow_pass.hpp"
#include "scene/text/legend_content.hpp"

namespace trailray::render {
namespace {

// Sizes in pixels are the viewer's pixels: a target of `pixel_ratio` device pixels per pixel (a
// high-DPI window, the page on a phone, `render --pixel-ratio`, the viewer's reduced frame while
// moving) draws them that many device pixels wide, as it does the labels, so a track looks as wide
// on every screen.
scene::TrackStyle in_device_pixels(scene::TrackStyle style, double pixel_ratio) {
  if (style.width.unit == scene::TrackWidth::Unit::pixels) style.width.value *= pixel_ratio;
  // Never under a device pixel: thinner, a distant track breaks into dots (the reduced frame).
  style.min_width_px = std::max(1.0, style.min_width_px * pixel_ratio);
  return style;
}
scene::PinStyle in_device_pixels(scene::PinStyle style, double pixel_ratio) {
  for (double* px : {&style.marker_px, &style.place_marker_px, &style.stem_px, &style.lift_px, &style.place_lift_px})
    *px *= pixel_ratio;
  return style;
}

// Runs a frame's passes, each in a debug group of its name, timed under that name (or another)
// when there is a profiler.
class FramePasses {
 public:
  FramePasses(const DebugGroups& groups, FrameProfiler* profiler) : groups_(groups), profiler_(profiler) {
    if (profiler_ != nullptr) profiler_->begin_frame();
  }
  ~FramePasses() {
    if (profiler_ != nullptr) profiler_->end_frame();
  }
  FramePasses(const FramePasses&) = delete;
  FramePasses& operator=(const FramePasses&) = delete;

  // `timed_as` empty: not timed.
  template <typename Run>
  void run(std::string_view name, Run&& pass, std::string_view timed_as) {
    const DebugGroup group(groups_, name);
    if (profiler_ == nullptr || timed_as.empty()) return pass();
    const FrameProfiler::Scope scope(*profiler_, timed_as);
    pass();
  }
  template <typename Run>
  void run(std::string_view name, Run&& pass) {
    run(name, std::forward<Run>(pass), name);
  }

 private:
  const DebugGroups& groups_;
  FrameProfiler* profiler_;
};

// The height span of the terrain drawn (the neutral ground's height included).
std::pair<float, float> terrain_span(std::span<const scene::TerrainTile> tiles, float neutral_m) {
  float lowest = neutral_m, highest = neutral_m;
  for (const scene::TerrainTile& t : tiles)
    if (t.has_data) {
      lowest = std::min(lowest, t.heights->min_m);
      highest = std::max(highest, t.heights->max_m);
    }
  return {lowest, highest};
}

// What the legend's panel depends on (its text and the picture's size): measured again only when
// this changes, not every frame.
std::string legend_key(const scene::Scene& scene, const scene::Lens& lens) {
  std::string key = std::to_string(lens.width_px) + 'x' + std::to_string(lens.height_px);
  if (!scene.style.legend) return key;
  if (const auto legend = scene::color_legend_for(scene.style.tracks, scene.color_range))
    key += '\n' + legend->title + '\n' + legend->min_label + '\n' + legend->max_label + '\n' +
           std::to_string(legend->ticks.size());
  if (scene.tracks != nullptr)
    for (const scene::TrackKeyEntry& entry : scene::track_key_for(scene.style.tracks, *scene.tracks))
      key += '\n' + entry.name;
  for (const scene::TrackKeyEntry& entry : scene::airspace_key_for(scene)) key += "\nairspace " + entry.name;
  return key;
}

}  // namespace

Renderer::Renderer(RendererOptions options) : options_(options) {
  const GlCapabilities capabilities = query_gl_capabilities();
  distance_encoding_ = distance_encoding_for(capabilities);
  debug_groups_ = DebugGroups(capabilities);
}

Renderer::~Renderer() = default;

FrameReport Renderer::draw(const scene::Scene& scene, const scene::Camera& camera, FrameTarget& target,
                           const FrameOptions& frame) {
  scene::TerrainView& terrain = scene.terrain != nullptr ? *scene.terrain : neutral_terrain_;
  const scene::TerrainTiles tiles = terrain.tiles_for(camera, scene.neutral_ground_m);
  FrameContent content;
  content.terrain = &tiles;
  content.shading = scene.style.shading;
  content.sun_direction_ecef = scene::sun_direction(scene);
  const double pixel_ratio = target.pixel_ratio > 0.0 ? target.pixel_ratio : 1.0;
  const scene::TrackStyle track_style = in_device_pixels(scene.style.tracks, pixel_ratio);
  content.track_settings = track_settings_for(track_style, scene.color_range);
  track_gpu_.begin_frame();
  if (scene.tracks != nullptr)
    content.tracks = track_gpu_.draws(*scene.tracks, scene.color_range.has_value(), track_style);
  // Pins after the tracks: they are drawn by the same pass.
  for (const TrackDraw& pin : pin_gpu_.draws(scene.waypoints, in_device_pixels(scene.style.pins, pixel_ratio)))
    content.tracks.push_back(pin);
  content.labels = layout_labels(scene, camera, target.pixel_ratio);
  content.volumes = volume_gpu_.draw(scene.volumes, tiles.report.neutral_ground_m);
  if (scene.volumes != nullptr)
    for (const scene::Volume& v : scene.volumes->volumes) content.volume_count += v.visible ? 1 : 0;
  content.label_style = scene.style.labels;
  FrameReport report = draw(content, camera, target, frame);
  track_gpu_.evict(scene.tracks);
  report.gpu_tracks = track_gpu_.stats();
  return report;
}

FrameReport Renderer::draw(const FrameContent& content, const scene::Camera& camera, FrameTarget& target,
                           const FrameOptions& frame) {
  FrameReport report;
  const scene::TerrainTiles& terrain = *content.terrain;
  report.terrain = terrain.report;
  const auto neutral = static_cast<float>(terrain.report.neutral_ground_m);
  terrain_gpu_.begin_frame();
  const std::vector<TerrainDrawItem> items = terrain_gpu_.upload(terrain.tiles, neutral);
  for (const scene::TerrainTile& t : terrain.tiles) {
    ++report.tiles_drawn;
    if (t.has_data) ++report.tiles_with_data;
    if (t.image) ++report.imagery_tiles_used;
  }
  for (const TrackDraw& draw : content.tracks)
    (draw.is_pin ? report.pin_draws : report.tracks_drawn) += draw.is_pin ? 1 : draw.shown_tracks();
  report.labels_drawn = content.labels.size();
  report.volumes_drawn = content.volumes != nullptr ? content.volume_count : 0;

  // The sun and sky light of the frame: what decides the shadows and what the passes shade with.
  const SceneLighting lighting = lighting_for(content.sun_direction_ecef, camera, ComposeSettings{}.model);
  FrameShadows shadows = frame_shadows(content, camera, lighting, items, neutral, frame);
  report.shadows_drawn = shadows.cascades.has_value();
  report.shadow_maps_rendered = shadows.render_for.has_value();
  // The tracks' block origins relative to this camera (the shadow and track passes use them),
  // and what their capsules are this frame: planned with the settings the passes draw with.
  const TrackSceneSettings tracks = frame_track_settings(content);
  track_pass_.prepare(content.tracks, camera, tracks);
  run_passes(content, camera, lighting, target, items, shadows, tracks, frame);
  report.track_capsules = content.tracks.empty() ? 0 : track_pass_.visible_capsules();

  // Between frames: the draw lists above point into the caches until here.
  terrain_gpu_.end_frame(options_.mesh_budget_bytes, options_.imagery_budget_bytes);
  report.gpu_meshes = terrain_gpu_.mesh_stats();
  report.gpu_imagery = terrain_gpu_.imagery_stats();
  return report;
}

std::vector<scene::PlacedLabel> Renderer::layout_labels(const scene::Scene& scene, const scene::Camera& camera,
                                                        double pixel_ratio) {
  const std::vector<scene::LabelCandidate> candidates = scene::label_candidates(scene);
  if (candidates.empty()) return {};
  scene::LabelLayouter& layouter = label_pass_.layouter();
  scene::LabelLayoutOptions options;
  options.size_px = scene.style.labels.size_px;
  options.pixel_ratio = pixel_ratio;
  const scene::Lens& lens = camera.lens();
  options.keep_out = scene.label_keep_out;
  std::string key = legend_key(scene, lens);
  if (!legend_panel_ || legend_panel_->key != key)
    legend_panel_ = LegendPanelCache{std::move(key),
                                     scene::scene_legend_panel(lens.width_px, lens.height_px, scene, layouter.text())};
  if (!legend_panel_->panel.empty()) options.keep_out.push_back(legend_panel_->panel);
  return layouter.layout(candidates, camera, options);
}

std::optional<ShadowCascades> Renderer::shadow_cascades(const FrameContent& content, const scene::Camera& camera,
                                                        const SceneLighting& lighting, float neutral_m) {
  // The sun's disc below the horizon gives no direct light (sun_radiance is 0): nothing to shade.
  const bool sun_up = glm::dot(lighting.sun_radiance, glm::vec3(1.0f)) > 0.0f;
  if (!content.shading.shadows || !sun_up) return std::nullopt;
  ShadowCascadeSettings settings;
  settings.map_size_px = options_.shadow_map_size_px;
  // Casters reach towards the sun by the height span of what is drawn.
  const auto [lowest, highest] = terrain_span(content.terrain->tiles, neutral_m);
  settings.caster_height_span_m =
      caster_height_span_m(lowest, highest, ShadowCasters{{}, content.tracks, &content.track_settings});
  std::optional<ShadowCascades> cascades(std::in_place, camera, content.sun_direction_ecef, settings);
  if (!shadow_maps_ || shadow_maps_->map_size_px() != options_.shadow_map_size_px) {
    shadow_maps_.emplace(options_.shadow_map_size_px);
    shadow_cache_.clear();
  }
  return cascades;
}

Renderer::FrameShadows Renderer::frame_shadows(const FrameContent& content, const scene::Camera& camera,
                                               const SceneLighting& lighting, std::span<const TerrainDrawItem> items,
                                               float neutral_m, const FrameOptions& frame) {
  FrameShadows shadows;
  shadows.cascades = shadow_cascades(content, camera, lighting, neutral_m);
  if (!shadows.cascades) return shadows;
  if (frame.reuse_shadow_maps && shadow_cache_.holds_sun(content.sun_direction_ecef)) {
    shadows.cascades = shadow_cache_.cascades().seen_from(camera.position());
    return shadows;
  }
  ShadowMapKey key = shadow_map_key(*shadows.cascades, camera, {items, content.tracks, &content.track_settings});
  if (frame.render_shadow_maps || !shadow_cache_.holds(key)) shadows.render_for = std::move(key);
  return shadows;
}

TrackSceneSettings Renderer::frame_track_settings(const FrameContent& content) const {
  TrackSceneSettings tracks = content.track_settings;
  tracks.level_of_detail = tracks.level_of_detail && options_.track_level_of_detail;
  tracks.overlay_depth = options_.track_overlay_depth;
  if (options_.split_track_overlay)
    tracks.terrain_top_m =
        terrain_span(content.terrain->tiles, static_cast<float>(content.terrain->report.neutral_ground_m)).second;
  return tracks;
}

void Renderer::run_passes(const FrameContent& content, const scene::Camera& camera, const SceneLighting& lighting,
                          FrameTarget& target, std::span<const TerrainDrawItem> items, FrameShadows& shadows,
                          const TrackSceneSettings& tracks, const FrameOptions& frame) {
  const std::optional<ShadowCascades>& cascades = shadows.cascades;
  const scene::Lens& lens = camera.lens();
  const int width = static_cast<int>(lens.width_px), height = static_cast<int>(lens.height_px);
  ComposeSettings compose;
  compose.atmosphere = content.shading.atmosphere;
  FramePasses passes(debug_groups_, target.profiler);
  if (shadows.render_for)
    passes.run("shadows", [&] {
      shadow_cache_.clear();  // until rendered: a throw leaves the maps half drawn
      draw_shadow_pass(*shadow_maps_, *cascades, {items, content.tracks, &tracks}, track_pass_, camera);
      shadow_cache_.store(std::move(*shadows.render_for), *cascades);
    });
  const GBuffer gbuffer(width, height, distance_encoding_);
  passes.run("tiles", [&] { terrain_pass_.draw(gbuffer, camera, items, content.shading.snow); });
  std::optional<TrackOverlayTarget> overlay;
  if (!content.tracks.empty())
    passes.run("tracks", [&] {
      // The overlay starts from the visible tracks' depth and reads the terrain's distances as
      // draw_visible copied them.
      track_pass_.draw_visible(gbuffer, camera, content.tracks, tracks);
      overlay.emplace(width, height);
      track_pass_.draw_overlay(gbuffer, *overlay, camera, lighting, content.tracks, tracks);
    });
  const Texture* ambient_occlusion = nullptr;
  if (content.shading.ssao && frame.ssao)
    passes.run("ssao", [&] {
      SsaoSettings ssao;
      ssao.resolution_divisor = options_.ssao_resolution_divisor;
      ambient_occlusion = &ssao_pass_.run(gbuffer, camera, ssao);
    });
  const ColorDepthTarget lit(width, height);
  // The atmosphere (aerial perspective and sky) is drawn by the compose pass's one draw: its time
  // is compose's, and the profiler's "atmosphere" row stays empty.
  passes.run("compose", [&] {
    lit.bind();
    const ComposeShadows lookup{cascades ? &*shadow_maps_ : nullptr, cascades ? &*cascades : nullptr};
    compose_pass_.draw(gbuffer, ambient_occlusion, cascades ? &lookup : nullptr, camera, lighting, compose);
  });
  if (overlay) passes.run("overlays", [&] { track_pass_.blend_overlay(*overlay); });
  if (content.volumes != nullptr)
    passes.run("volumes", [&] {
      lit.bind();
      volume_pass_.draw(gbuffer, camera, *content.volumes, target.pixel_ratio);
    });
  if (!content.labels.empty())
    passes.run("labels", [&] {
      lit.bind();
      label_pass_.draw(gbuffer, content.labels, content.label_style);
    });
  passes.run(
      "output",
      [&] {
        lit.bind();
        target.receive(lit);
      },
      target.pass_name());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace trailray::render
