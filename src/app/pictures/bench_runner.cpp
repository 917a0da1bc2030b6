#include "app/pictures/bench_runner.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <numbers>
#include <span>
#include <stdexcept>
#include <vector>

#include "geo/tile_id.hpp"
#include "render/gl/frame_profiler.hpp"
#include "render/gl/gl_api.hpp"
#include "render/passes/gbuffer.hpp"
#include "render/passes/reference/reference_track.hpp"
#include "render/passes/reference/ribbon_pass.hpp"
#include "render/passes/reference/tube_pass.hpp"
#include "render/passes/terrain_mesh.hpp"
#include "render/passes/terrain_pass.hpp"
#include "render/passes/track_buffer.hpp"
#include "render/passes/track_pass.hpp"
#include "render/platform/gl_context.hpp"
#include "scene/camera/framing.hpp"
#include "terrain/tile.hpp"

namespace trailray::app {
namespace {

const glm::vec3 kTrackColorSrgb{0.9f, 0.1f, 0.1f};
constexpr double kMetresPerDegree = 111320.0;
constexpr std::uint32_t kGroundGridVertices = 17;
constexpr std::size_t kMaxGroundTiles = 64;

// A flat ground at `height_m` under the points and as far again around them (at least 3 km):
// the terrain depth the track passes test against, as on a real scene. A few Web Mercator tiles
// of one zoom, each a 2x2 grid of one height (the mesh follows the Earth's curvature).
std::vector<render::TerrainTileGpu> flat_ground(const std::vector<scene::GeoPosition>& points, double height_m) {
  double min_lat = 90.0, max_lat = -90.0, min_lon = 180.0, max_lon = -180.0;
  for (const scene::GeoPosition& p : points) {
    min_lat = std::min(min_lat, p.lat_deg), max_lat = std::max(max_lat, p.lat_deg);
    min_lon = std::min(min_lon, p.lon_deg), max_lon = std::max(max_lon, p.lon_deg);
  }
  const double cos_lat = std::max(std::cos(0.5 * (min_lat + max_lat) * std::numbers::pi / 180.0), 0.05);
  const double extent_m =
      std::max((max_lat - min_lat) * kMetresPerDegree, (max_lon - min_lon) * kMetresPerDegree * cos_lat);
  const double margin_m = std::max(extent_m, 3000.0);
  const double span_m = extent_m + 2.0 * margin_m;
  // Tiles about half the span wide: 3 to 4 a side.
  const int zoom = std::clamp(static_cast<int>(std::floor(std::log2(40075016.7 * cos_lat / (0.5 * span_m)))), 1, 18);
  const double margin_lat = margin_m / kMetresPerDegree, margin_lon = margin_m / (kMetresPerDegree * cos_lat);
  const auto north_west =
      geo::tile_containing(std::min(max_lat + margin_lat, 85.0), std::max(min_lon - margin_lon, -180.0), zoom);
  const auto south_east =
      geo::tile_containing(std::max(min_lat - margin_lat, -85.0), std::min(max_lon + margin_lon, 179.999), zoom);
  std::vector<render::TerrainTileGpu> tiles;
  if (!north_west || !south_east) return tiles;
  const auto h = static_cast<float>(height_m);
  for (std::uint32_t y = north_west->y; y <= south_east->y; ++y)
    for (std::uint32_t x = north_west->x; x <= south_east->x && tiles.size() < kMaxGroundTiles; ++x) {
      terrain::HeightTile tile;
      tile.id = geo::TileId{zoom, x, y};
      tile.width = tile.height = 2;
      tile.layout = terrain::SampleLayout::pixel_is_point;
      tile.heights.assign(4, h);
      tile.min_m = tile.max_m = h;
      tiles.push_back(render::upload_terrain_mesh(render::build_terrain_mesh(tile, kGroundGridVertices, h)));
    }
  return tiles;
}

// A pass to time: drawn once per frame, after the ground, in the order given.
struct TimedPass {
  std::string name;
  std::function<void()> draw;
};

struct PassMedians {
  std::map<std::string, double> ms;
  bool gpu = true;  // every median from GPU queries
};

}  // namespace

struct TrackBench::State {
  BenchSettings settings;
  render::GlContext gl;
  render::GBuffer gbuffer;
  render::TrackOverlayTarget overlay;
  render::TerrainPass terrain;
  render::TrackPass capsules;
  render::reference::RibbonPass ribbon;
  render::reference::TubePass tube;

  explicit State(const BenchSettings& s)
      : settings(s),
        gl(render::GlContext::create_headless()),
        gbuffer(static_cast<int>(s.lens.width_px), static_cast<int>(s.lens.height_px),
                render::distance_encoding_for(gl.capabilities())),
        overlay(static_cast<int>(s.lens.width_px), static_cast<int>(s.lens.height_px)) {}

  // Warm-up frames, then the timed ones: the ground (untimed), then each pass under its name.
  PassMedians time_passes(const scene::Camera& camera, const std::vector<render::TerrainDrawItem>& ground,
                          const std::vector<TimedPass>& passes, const std::function<void()>& before_frame) {
    render::FrameProfiler profiler(gl.capabilities(), static_cast<std::size_t>(settings.frames));
    for (int frame = 0; frame < settings.warmup_frames + settings.frames; ++frame) {
      const bool timed = frame >= settings.warmup_frames;
      if (timed) profiler.begin_frame();
      before_frame();
      terrain.draw(gbuffer, camera, ground);
      render::wait_for_gpu();  // the ground is done before any clock starts
      for (const TimedPass& pass : passes) {
        if (timed) profiler.begin_pass(pass.name);
        pass.draw();
        render::wait_for_gpu();  // CPU time then covers the GPU's work (a no-op for the GPU clock)
        if (timed) profiler.end_pass(pass.name);
      }
      if (timed) profiler.end_frame();
    }
    profiler.finish();
    PassMedians medians;
    for (const render::PassTimes& t : profiler.times()) {
      if (t.gpu_samples > 0 && t.gpu_median_ms) {
        medians.ms[t.name] = *t.gpu_median_ms;
      } else if (t.cpu_median_ms) {
        medians.ms[t.name] = *t.cpu_median_ms;
        medians.gpu = false;
      }
    }
    return medians;
  }
};

TrackBench::TrackBench(const BenchSettings& settings) : state_(std::make_unique<State>(settings)) {}
TrackBench::~TrackBench() = default;

std::string TrackBench::renderer() const { return state_->gl.capabilities().renderer; }
bool TrackBench::gpu_timing() const { return state_->gl.capabilities().disjoint_timer_query; }

// Colours for the many-track scenario's tracks (each its own, as a season is drawn).
constexpr std::array<glm::vec3, 4> kManyColorsSrgb{glm::vec3{0.9f, 0.1f, 0.1f}, glm::vec3{0.1f, 0.4f, 0.9f},
                                                   glm::vec3{0.1f, 0.7f, 0.2f}, glm::vec3{0.9f, 0.6f, 0.1f}};

BenchRow TrackBench::run(const BenchDataset& dataset, const std::function<void(const std::string&)>& progress) {
  State& s = *state_;
  BenchRow row;
  row.name = dataset.name;
  row.kind = dataset.kind;
  row.points = dataset.point_count();
  row.segments = dataset.geometry.segments.size();

  scene::FramingOptions framing_options;
  framing_options.lens = s.settings.lens;
  framing_options.ground_height_m = dataset.ground_height_m;
  const scene::Result<scene::Framing> framed = scene::frame_points(dataset.positions, framing_options);
  if (!framed.ok()) throw std::runtime_error(dataset.name + ": cannot frame it: " + framed.error);
  const scene::Camera& camera = framed.value->camera;
  row.view_distance_m = framed.value->look_at.distance_m;

  const std::vector<render::TerrainTileGpu> ground_tiles = flat_ground(dataset.positions, dataset.ground_height_m);
  std::vector<render::TerrainDrawItem> ground;
  for (const render::TerrainTileGpu& tile : ground_tiles) ground.push_back({&tile, {}});
  bool gpu = true;

  // Many walks are many tracks: one buffer whose segments name their track, each track in its
  // own colour (as the renderer draws a scene's tracks), and, to compare, a buffer per track.
  const bool many = dataset.kind == "many_walks";
  std::vector<scene::TrackGeometry> per_track;
  std::vector<const scene::TrackGeometry*> track_pointers;
  std::vector<render::TrackDrawStyle> styles;
  if (many) {
    per_track.reserve(dataset.geometry.segments.size());
    for (const scene::TrackPolyline& line : dataset.geometry.segments) per_track.push_back({{line}});
    for (std::size_t t = 0; t < per_track.size(); ++t) {
      track_pointers.push_back(&per_track[t]);
      styles.push_back({kManyColorsSrgb[t % kManyColorsSrgb.size()], false, true});
    }
  }
  render::TrackSceneSettings settings;
  settings.level_of_detail = s.settings.level_of_detail;
  settings.width = {s.settings.width_px, scene::TrackWidth::Unit::pixels};
  if (s.settings.split_overlay) settings.terrain_top_m = dataset.ground_height_m;  // the flat ground
  const render::SceneLighting lighting;
  // In the renderer's order: the overlay starts from the visible pass's depth.
  const auto time_capsules = [&](std::span<const render::TrackDraw> draws) {
    return s.time_passes(camera, ground,
                         {{"capsule_visible", [&] { s.capsules.draw_visible(s.gbuffer, camera, draws, settings); }},
                          {"capsule_overlay",
                           [&] { s.capsules.draw_overlay(s.gbuffer, s.overlay, camera, lighting, draws, settings); }}},
                         [&] { s.capsules.prepare(draws, camera, settings); });
  };
  {
    progress("capsule");
    const auto upload_start = std::chrono::steady_clock::now();
    const render::TrackBuffer buffer =
        many ? render::TrackBuffer(std::span<const scene::TrackGeometry* const>(track_pointers))
             : render::TrackBuffer(dataset.geometry);
    render::wait_for_gpu();
    row.capsule_upload_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - upload_start).count();
    row.capsule_bytes = buffer.gpu_bytes();
    render::TrackDraw draw{&buffer, kTrackColorSrgb, false, {}, false, {}};
    if (many) draw.track_styles = styles;
    const PassMedians m = time_capsules(std::span<const render::TrackDraw>(&draw, 1));
    row.capsule_ms = m.ms.at("capsule_visible");
    row.capsule_overlay_ms = m.ms.at("capsule_overlay");
    row.capsule_total_ms = row.capsule_ms + row.capsule_overlay_ms;
    row.capsules_drawn = s.capsules.visible_capsules();
    gpu = gpu && m.gpu;
  }
  if (many) {
    progress("capsule, a buffer per track");
    std::vector<render::TrackBuffer> buffers;
    buffers.reserve(per_track.size());
    for (const scene::TrackGeometry& g : per_track) buffers.emplace_back(g);
    std::vector<render::TrackDraw> draws;
    for (std::size_t t = 0; t < buffers.size(); ++t)
      draws.push_back({&buffers[t], styles[t].color_srgb, false, {}, false, {}});
    const PassMedians m = time_capsules(draws);
    row.capsule_per_track_total_ms = m.ms.at("capsule_visible") + m.ms.at("capsule_overlay");
    gpu = gpu && m.gpu;
  }
  {
    progress("ribbon");
    const render::reference::RibbonBuffer buffer(dataset.geometry);
    row.ribbon_bytes = buffer.gpu_bytes();
    const PassMedians m = s.time_passes(
        camera, ground,
        {{"ribbon", [&] { s.ribbon.draw(s.gbuffer, camera, buffer, kTrackColorSrgb, s.settings.width_px); }}}, [] {});
    row.ribbon_ms = m.ms.at("ribbon");
    gpu = gpu && m.gpu;
  }
  if (dataset.point_count() > s.settings.max_tube_points) {
    row.tube_ms = std::numeric_limits<double>::quiet_NaN();
  } else {
    progress("tube");
    row.tube_radius_m = render::reference::radius_for_pixel_width(camera, row.view_distance_m, s.settings.width_px);
    const render::reference::TubeBuffer buffer(dataset.geometry, row.tube_radius_m);
    row.tube_bytes = buffer.gpu_bytes();
    const PassMedians m = s.time_passes(
        camera, ground, {{"tube", [&] { s.tube.draw(s.gbuffer, camera, buffer, kTrackColorSrgb); }}}, [] {});
    row.tube_ms = m.ms.at("tube");
    gpu = gpu && m.gpu;
  }
  row.gpu_timed = gpu;
  return row;
}

}  // namespace trailray::app
