#pragma once
// The renderer: draws a scene::Scene from a camera into a FrameTarget. It asks the scene's
// terrain view for the tiles to draw, uploads what is not on the GPU yet (tile meshes, imagery,
// track buffers by (id, revision)) and runs the frame's passes (DESIGN.md "The frame"):
//
//   shadows    the sun's cascaded shadow maps, terrain and tracks as casters; rendered only when
//              what they hold changed (shadow_cache.hpp), else those of an earlier frame serve
//   tiles      the terrain into the G-buffer (albedo, normal, distance)
//   tracks     the tracks' visible hits into the G-buffer, then their overlay (ghosts, fringe,
//              curtains)
//   ssao       ambient occlusion from the G-buffer (at half resolution, upsampled)
//   compose    sun, sky light, shadows, AO, atmosphere: the lit frame
//   overlays   the track overlay blended over it
//   volumes    airspaces and task cylinders: translucent walls, floor and ceiling outlines
//   labels     the names of waypoints, places and tracks (laid out by scene/text/label_layout.hpp)
//   output     the frame handed to its target (read back, copied into a window)
//
// Each pass runs in a KHR_debug group of its name and, with a profiler, is timed under it.

#include <glm/glm.hpp>

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "render/frame_target.hpp"
#include "render/gl/debug_group.hpp"
#include "render/gl/gpu_resource_cache.hpp"
#include "render/passes/compose_pass.hpp"
#include "render/passes/gbuffer.hpp"
#include "render/passes/label_pass.hpp"
#include "render/passes/shadow_cache.hpp"
#include "render/passes/shadow_maps.hpp"
#include "render/passes/ssao_pass.hpp"
#include "render/passes/terrain_pass.hpp"
#include "render/passes/track_pass.hpp"
#include "render/passes/volume_pass.hpp"
#include "render/pin_gpu.hpp"
#include "render/terrain_gpu.hpp"
#include "render/track_gpu.hpp"
#include "render/volume_gpu.hpp"
#include "scene/camera/camera.hpp"
#include "scene/scene.hpp"
#include "scene/terrain_view.hpp"

namespace trailray::render {

struct RendererOptions {
  int shadow_map_size_px = 2048;  // each cascade's square depth map (16..16384)
  // GPU memory for tile meshes and imagery textures kept between frames (estimated from buffer
  // and texture sizes). After each frame the least recently used beyond the budget are freed,
  // never those the frame drew: a view that needs more keeps them and frees them later.
  std::size_t mesh_budget_bytes = kDefaultMeshBudgetBytes;
  std::size_t imagery_budget_bytes = kDefaultImageryBudgetBytes;
  // The track overlay traces only the capsules the terrain may hide (TrackSceneSettings::
  // terrain_top_m); false: every capsule, as a reference for tests.
  bool split_track_overlay = true;
  // How the split overlay drops what lies behind a visible track (TrackSceneSettings::
  // overlay_depth): chosen per frame, or one way for tests and the bench.
  OverlayDepth track_overlay_depth = OverlayDepth::chosen;
  // Level of detail for the tracks' capsules (TrackSceneSettings::level_of_detail); false: every
  // capsule, as a reference for tests.
  bool track_level_of_detail = true;
  // Ambient occlusion at half resolution each way (2, upsampled) or full (1: the reference).
  int ssao_resolution_divisor = 2;
};

struct FrameReport {
  scene::TerrainReport terrain;        // selection rounds, timeout, failures, progress, neutral ground
  std::size_t tiles_drawn = 0;         // height tiles drawn (neutral ones included)
  std::size_t tiles_with_data = 0;     // of those: from the height source
  std::size_t imagery_tiles_used = 0;  // drawn tiles with imagery
  std::size_t tracks_drawn = 0;        // visible tracks
  std::size_t track_capsules = 0;      // capsules the tracks' visible pass drew (fewer with LOD)
  std::size_t pin_draws = 0;           // the waypoints' stems and balls (a draw per kind and part)
  std::size_t labels_drawn = 0;        // labels placed (those whose point is hidden included)
  std::size_t volumes_drawn = 0;       // visible airspaces and task cylinders
  bool shadows_drawn = false;          // false: switched off, or the sun below the horizon
  bool shadow_maps_rendered = false;   // false: none, or the maps of an earlier frame reused
  // The GPU caches after this frame's eviction: held, used by the frame, uploaded, evicted.
  GpuCacheStats gpu_meshes;
  GpuCacheStats gpu_imagery;
  GpuCacheStats gpu_tracks;
};

// How much of a frame is drawn afresh. The default is the full frame; its shadow maps are still
// reused when nothing they depend on changed (shadow_cache.hpp), which gives the same picture.
struct FrameOptions {
  // A frame drawn while the camera moves (the viewer): the shadow maps last rendered are reused
  // even for another camera or other tiles (their cascades stay where they were: shadows end
  // early or are cut off where the view left them); only a new sun, or none yet, renders them.
  bool reuse_shadow_maps = false;
  // false: no ambient occlusion this frame, whatever the shading asks.
  bool ssao = true;
  // true: the shadow maps are rendered even when those of the last frame would serve (`render
  // --profile` times every pass of the frame as drawn the first time).
  bool render_shadow_maps = false;
};

// A frame's content once resolved from a scene: the terrain's tiles, the tracks' buffers, the
// light and the style.
struct FrameContent {
  const scene::TerrainTiles* terrain = nullptr;
  std::vector<TrackDraw> tracks;
  TrackSceneSettings track_settings;
  scene::Shading shading;
  glm::dvec3 sun_direction_ecef{0.0, 0.0, 1.0};  // unit, towards the sun
  std::vector<scene::PlacedLabel> labels;        // laid out for the frame's camera and size
  const VolumeDraw* volumes = nullptr;           // airspaces and task cylinders (nullptr: none)
  std::size_t volume_count = 0;                  // how many volumes `volumes` holds
  scene::LabelStyle label_style;
};

class Renderer {
 public:
  // The GL context must be current and stay so for the renderer's lifetime. Throws ShaderError /
  // RenderError from GL.
  explicit Renderer(RendererOptions options = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Draws the scene from the camera at its lens's image size into `target`. The scene's terrain
  // view hands out the tiles by its loading policy (waiting for them, or not: the viewer); a
  // scene without one is the neutral ground everywhere. Throws RenderError from GL, and
  // std::invalid_argument for an unusable camera or a shadow map size outside 16..16384.
  FrameReport draw(const scene::Scene& scene, const scene::Camera& camera, FrameTarget& target,
                   const FrameOptions& frame = {});

  // Draws resolved content: the tracks' buffers are the caller's (they must outlive the call).
  FrameReport draw(const FrameContent& content, const scene::Camera& camera, FrameTarget& target,
                   const FrameOptions& frame = {});

  // The labels the scene calls for, laid out for a camera and a target's pixel ratio, clear of
  // the legend the picture gets and of scene.label_keep_out.
  std::vector<scene::PlacedLabel> layout_labels(const scene::Scene& scene, const scene::Camera& camera,
                                                double pixel_ratio);

  const RendererOptions& options() const { return options_; }
  void set_options(const RendererOptions& options) { options_ = options; }

  // The G-buffer's distance encoding: from the context's capabilities, queried once at
  // construction; tests force the packed path to check it against the float one.
  DistanceEncoding distance_encoding() const { return distance_encoding_; }
  void set_distance_encoding(DistanceEncoding encoding) { distance_encoding_ = encoding; }

 private:
  // The sun's cascades when the frame has shadows (and the maps for them), else nullopt.
  std::optional<ShadowCascades> shadow_cascades(const FrameContent& content, const scene::Camera& camera,
                                                const SceneLighting& lighting, float neutral_m);
  // The cascades the frame looks its shadows up in (those the cache's maps hold, or new ones)
  // and the key to render the maps for (nullopt: the cache's maps serve).
  struct FrameShadows {
    std::optional<ShadowCascades> cascades;
    std::optional<ShadowMapKey> render_for;
  };
  FrameShadows frame_shadows(const FrameContent& content, const scene::Camera& camera, const SceneLighting& lighting,
                             std::span<const TerrainDrawItem> items, float neutral_m, const FrameOptions& frame);
  // The track pass's settings for a frame: the content's, with the renderer's options applied.
  TrackSceneSettings frame_track_settings(const FrameContent& content) const;
  void run_passes(const FrameContent& content, const scene::Camera& camera, const SceneLighting& lighting,
                  FrameTarget& target, std::span<const TerrainDrawItem> items, FrameShadows& shadows,
                  const TrackSceneSettings& tracks, const FrameOptions& frame);

  RendererOptions options_;
  DistanceEncoding distance_encoding_;
  DebugGroups debug_groups_;
  TerrainPass terrain_pass_;
  SsaoPass ssao_pass_;
  ComposePass compose_pass_;
  TrackPass track_pass_;
  LabelPass label_pass_;
  VolumePass volume_pass_;
  struct LegendPanelCache {
    std::string key;
    scene::PixelRect panel;
  };
  std::optional<LegendPanelCache> legend_panel_;  // the legend labels keep out of
  std::optional<ShadowMaps> shadow_maps_;         // made on first use, remade for another size
  ShadowMapCache shadow_cache_;                   // what shadow_maps_ hold
  TerrainGpu terrain_gpu_;
  TrackGpu track_gpu_;
  PinGpu pin_gpu_;
  VolumeGpu volume_gpu_;
  scene::TerrainView neutral_terrain_{nullptr, nullptr};  // for scenes without terrain
};

}  // namespace trailray::render
