#include "render/legacy_scene_renderer.hpp"

#include <utility>

#include "render/gl/framebuffer_readback.hpp"

namespace trailray::render {
namespace {

// Read back, copied into the window, or both.
class LegacyTarget : public FrameTarget {
 public:
  LegacyTarget(bool read_back, bool blit) : read_back_(read_back), blit_(blit) {}
  void receive(const ColorDepthTarget& frame) override {
    if (read_back_) image = read_rgba8(0, 0, frame.width(), frame.height());
    if (blit_) DefaultFramebufferTarget().receive(frame);
  }
  std::string_view pass_name() const override { return read_back_ ? "readback" : ""; }
  scene::RgbaImage image;

 private:
  bool read_back_, blit_;
};

SceneRenderReport legacy_report(const FrameReport& r) {
  SceneRenderReport out;
  out.tiles_drawn = r.tiles_drawn;
  out.tiles_with_data = r.tiles_with_data;
  out.imagery_tiles_used = r.imagery_tiles_used;
  out.selection_rounds = r.terrain.selection_rounds;
  out.neutral_ground_height_m = r.terrain.neutral_ground_m;
  out.timed_out = r.terrain.timed_out;
  out.shadows_drawn = r.shadows_drawn;
  out.failures = r.terrain.failures;
  out.progress = r.terrain.progress;
  out.gpu_meshes = r.gpu_meshes;
  out.gpu_imagery = r.gpu_imagery;
  return out;
}

}  // namespace

SceneRenderer::SceneRenderer(SceneSources sources, terrain::TileLoaderOptions loader_options)
    : terrain_(sources.heights, sources.imagery, loader_options) {}

RenderedScene SceneRenderer::render(const scene::Camera& camera, const SceneRenderOptions& options) {
  scene::TileLoadPolicy policy;
  policy.wait = options.wait_for_tiles;
  policy.timeout = options.timeout;
  policy.on_progress = options.on_progress;
  policy.max_screen_error_px = options.max_screen_error_px;
  terrain_.set_policy(std::move(policy));
  const scene::TerrainTiles tiles = terrain_.tiles_for(camera, options.neutral_ground_height_m);

  FrameContent content;
  content.terrain = &tiles;
  content.tracks = options.tracks;
  content.track_settings = options.track_settings;
  content.shading = {options.shadows, options.ssao, options.atmosphere, options.snow};
  content.sun_direction_ecef = options.sun_direction_ecef;
  renderer_.set_options({options.shadow_map_size_px, options.mesh_budget_bytes, options.imagery_budget_bytes});
  LegacyTarget target(options.read_back, options.blit_to_default_framebuffer);
  target.profiler = options.profiler;
  const FrameReport report = renderer_.draw(content, camera, target);
  return {std::move(target.image), legacy_report(report)};
}

}  // namespace trailray::render
