#pragma once
// One picture of the terrain from a camera: choose the tiles the view wants (terrain LOD
// selection), wait for them through the async loaders (with a timeout and progress), build and
// upload their meshes, render the sun's cascaded shadow maps with the tiles as casters, fill the
// G-buffer, ambient occlusion, compose with sun, shadows, sky and atmosphere, read the pixels back.
//
// The selection depends on the tiles' height ranges, which are known only once tiles are loaded,
// so it is repeated (a few rounds at most) until it no longer changes. Where the height source has
// no data (no_data tiles, holes in tiles) or there is no source at all, the neutral ground is
// drawn at SceneRenderOptions::neutral_ground_height_m (DESIGN.md "Terrain sources").

#include <glm/glm.hpp>

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scene/camera.hpp"
#include "render/passes/compose_pass.hpp"
#include "render/gl/frame_profiler.hpp"
#include "render/gl/framebuffer_readback.hpp"
#include "render/passes/gbuffer.hpp"
#include "render/gl/gpu_resource_cache.hpp"
#include "render/passes/shadow_maps.hpp"
#include "render/passes/ssao_pass.hpp"
#include "render/passes/terrain_mesh.hpp"
#include "render/passes/terrain_pass.hpp"
#include "render/passes/track_pass.hpp"
#include "terrain/tile_loader.hpp"
#include "terrain/tile_source.hpp"

namespace trailray::render {

// Vertices per side of a tile's mesh (the LOD selection's tile_samples is one less); tiles of the
// source's finest level get every sample instead (full_resolution_grid).
inline constexpr std::uint32_t kTerrainGridVertices = 65;

// GPU memory for tiles kept between frames, 512 MiB in all (as much as one TileLoader keeps
// decoded by default). A view (at most 600 tiles, lod_selection.hpp) takes 20-80 MiB of meshes
// from a DEM (a 65 x 65 mesh about 280 KiB, a full-resolution one of a 256-sample tile about
// 4 MiB) and up to 200 MiB of imagery (341 KiB a 256 x 256 image with mipmaps): several views'
// meshes and at least one view's imagery stay, so turning back costs no upload.
inline constexpr std::size_t kDefaultMeshBudgetBytes = std::size_t{256} << 20;
inline constexpr std::size_t kDefaultImageryBudgetBytes = std::size_t{256} << 20;

struct SceneSources {
  terrain::HeightSource* heights = nullptr;   // nullptr: the neutral ground everywhere
  terrain::ImagerySource* imagery = nullptr;  // nullptr: the hypsometric tint
};

struct SceneRenderOptions {
  glm::dvec3 sun_direction_ecef{0.0, 0.0, 1.0};  // unit, towards the sun (sun_position.hpp)
  // NaN: the lowest height of the terrain loaded for the view (0 where there is none).
  double neutral_ground_height_m = 0.0;
  double max_screen_error_px = 2.0;
  std::chrono::milliseconds timeout{std::chrono::seconds(120)};  // for all tiles together
  bool ssao = true;                                              // screen-space ambient occlusion (`--no-ssao`)
  bool atmosphere = true;         // aerial perspective and sky (`--no-atmosphere`: no haze, a flat sky)
  bool shadows = true;            // cascaded shadow maps of the sun (`--no-shadows`)
  SnowCover snow;                 // snow by altitude and slope (`--snow`, `--snowline M`)
  int shadow_map_size_px = 2048;  // each cascade's square depth map
  // When set, the frame's passes (shadows, tiles, ssao, compose, readback) are timed as one
  // profiler frame, begun after the tiles are loaded.
  FrameProfiler* profiler = nullptr;
  // The tracks (their buffers outlive the render) and how they are drawn: ray-traced capsules
  // in the G-buffer, ghosts where the terrain hides them, shadows (track_pass.hpp).
  std::vector<TrackDraw> tracks;
  TrackSceneSettings track_settings;
  // Called about every 100 ms while tiles load (on the calling thread).
  std::function<void(const terrain::LoadProgress&)> on_progress;
  // The viewer's mode (false): never wait. Draw what is in memory now, the nearest loaded
  // coarser tile (and imagery) standing in for tiles still loading, and leave the loaders
  // working for the next frame; coarse levels above the wanted tiles are requested first so
  // the view fills coarse-to-fine. `timeout` and `on_progress` are then unused.
  bool wait_for_tiles = true;
  // false: no glReadPixels (RenderedScene::image stays empty), for frames only shown on screen.
  bool read_back = true;
  // Copy the frame into the default framebuffer (a window's, which must be the lens's size).
  bool blit_to_default_framebuffer = false;
  // GPU memory for tile meshes and imagery textures kept between frames (estimated from buffer
  // and texture sizes). After each frame the least recently used beyond the budget are freed,
  // never those the frame drew: a view that needs more keeps them and frees them later.
  std::size_t mesh_budget_bytes = kDefaultMeshBudgetBytes;
  std::size_t imagery_budget_bytes = kDefaultImageryBudgetBytes;
};

struct SceneRenderReport {
  std::size_t tiles_drawn = 0;         // height tiles drawn (neutral ones included)
  std::size_t tiles_with_data = 0;     // of those: from the height source
  std::size_t imagery_tiles_used = 0;  // drawn tiles with imagery
  int selection_rounds = 0;
  double neutral_ground_height_m = 0.0;  // where the neutral ground was drawn
  bool timed_out = false;                // drawn with what had arrived
  bool shadows_drawn = false;            // false: switched off, or the sun below the horizon
  std::vector<std::string> failures;     // tile errors ("<source> z/x/y: ...")
  // Height and imagery tiles wanted by this frame and how many of them have arrived (a
  // loading indicator's figures; pending() > 0 only without wait_for_tiles or after a timeout).
  terrain::LoadProgress progress;
  // The GPU caches after this frame's eviction: held, used by the frame, uploaded, evicted.
  GpuCacheStats gpu_meshes;
  GpuCacheStats gpu_imagery;
};

struct RenderedScene {
  scene::RgbaImage image;  // top-down, sRGB
  SceneRenderReport report;
};

class SceneRenderer {
 public:
  // The GL context must be current and stay so for the renderer's lifetime; the sources must
  // outlive it. Throws ShaderError / RenderError from GL.
  explicit SceneRenderer(SceneSources sources, terrain::TileLoaderOptions loader_options = {});
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  // Renders the camera's view at its lens's image size. Throws RenderError from GL, and
  // std::invalid_argument for an unusable camera or a shadow map size outside 16..16384.
  RenderedScene render(const scene::Camera& camera, const SceneRenderOptions& options);

  // The terrain height at a place from the finest height tile already in memory, bilinear
  // (NaN: no loaded tile there, or a hole). Never loads: for the viewer's camera, which must not
  // go below the ground and must not wait for it either.
  double height_in_memory(double lat_deg, double lon_deg) const;

  // The G-buffer's distance encoding: from the context's capabilities, queried once at
  // construction; tests force the packed path to check it against the float one.
  DistanceEncoding distance_encoding() const { return distance_encoding_; }
  void set_distance_encoding(DistanceEncoding encoding) { distance_encoding_ = encoding; }

 private:
  struct DrawnTile;
  std::vector<DrawnTile> load_height_tiles(const scene::Camera& camera, const SceneRenderOptions& options,
                                           SceneRenderReport& report);
  std::vector<TerrainImagery> load_imagery(const std::vector<DrawnTile>& tiles, const SceneRenderOptions& options,
                                           std::chrono::steady_clock::time_point deadline, SceneRenderReport& report);

  SceneSources sources_;
  std::unique_ptr<terrain::TileLoader<terrain::HeightTile>> height_loader_;
  std::unique_ptr<terrain::TileLoader<terrain::ImageTile>> imagery_loader_;
  DistanceEncoding distance_encoding_;
  TerrainPass terrain_pass_;
  SsaoPass ssao_pass_;
  ComposePass compose_pass_;
  TrackPass track_pass_;
  std::optional<ShadowMaps> shadow_maps_;  // made on first use, remade for another size
  TerrainMeshCache meshes_{kDefaultMeshBudgetBytes};
  GpuResourceCache<terrain::TileId, Texture> imagery_textures_{kDefaultImageryBudgetBytes};
};

}  // namespace trailray::render
