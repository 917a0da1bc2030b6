#pragma once
// GOING AWAY: the renderer's former entry point, kept only until the front ends in src/app
// (render_command, the viewer) draw through render::Renderer::draw(scene, camera, target). A thin
// wrapper: a scene::TerrainView for the sources and a Renderer fed with the caller's own track
// buffers. New code uses renderer.hpp and scene/terrain_view.hpp.

#include <glm/glm.hpp>

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "render/gl/frame_profiler.hpp"
#include "render/gl/gpu_resource_cache.hpp"
#include "render/passes/track_pass.hpp"
#include "render/renderer.hpp"
#include "scene/camera.hpp"
#include "scene/rgba_image.hpp"
#include "scene/style.hpp"
#include "scene/terrain_view.hpp"
#include "terrain/tile_loader.hpp"
#include "terrain/tile_source.hpp"

namespace trailray::render {

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
  bool ssao = true;
  bool atmosphere = true;
  bool shadows = true;
  scene::SnowCover snow;
  int shadow_map_size_px = 2048;
  FrameProfiler* profiler = nullptr;  // times the frame's passes
  // The tracks (their buffers outlive the render) and how they are drawn.
  std::vector<TrackDraw> tracks;
  TrackSceneSettings track_settings;
  std::function<void(const terrain::LoadProgress&)> on_progress;  // while waiting for tiles
  bool wait_for_tiles = true;                                     // false: the viewer's mode (TileLoadPolicy::wait)
  bool read_back = true;                                          // false: RenderedScene::image stays empty
  bool blit_to_default_framebuffer = false;                       // copy the frame into the window's framebuffer
  std::size_t mesh_budget_bytes = kDefaultMeshBudgetBytes;
  std::size_t imagery_budget_bytes = kDefaultImageryBudgetBytes;
};

struct SceneRenderReport {
  std::size_t tiles_drawn = 0;
  std::size_t tiles_with_data = 0;
  std::size_t imagery_tiles_used = 0;
  int selection_rounds = 0;
  double neutral_ground_height_m = 0.0;
  bool timed_out = false;
  bool shadows_drawn = false;
  std::vector<std::string> failures;
  terrain::LoadProgress progress;
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
  // outlive it.
  explicit SceneRenderer(SceneSources sources, terrain::TileLoaderOptions loader_options = {});

  RenderedScene render(const scene::Camera& camera, const SceneRenderOptions& options);
  double height_in_memory(double lat_deg, double lon_deg) const { return terrain_.height_in_memory(lat_deg, lon_deg); }

 private:
  scene::TerrainView terrain_;
  Renderer renderer_;
};

}  // namespace trailray::render
