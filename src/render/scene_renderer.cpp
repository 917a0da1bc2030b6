#include "render/scene_renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "geo/wgs84.hpp"
#include "render/gl/gl_capabilities.hpp"
#include "render/passes/shadow_cascades.hpp"
#include "terrain/lod_selection.hpp"

namespace trailray::render {
namespace {

using Clock = std::chrono::steady_clock;

// The finest level to split to when there is no height source: the neutral ground is flat, so
// only the Earth's curvature asks for detail, and a zoom-12 tile (10 km) bends by under 2 m.
constexpr int kNeutralMaxZoom = 12;
constexpr int kMaxSelectionRounds = 4;
// Vertices per side of a neutral ground tile: the LOD splits it until its geometric error (a
// 64th of its width) is 2 px, so 16 cells keep its curvature's sag within a pixel or so.
constexpr std::uint32_t kNeutralGridVertices = 17;

std::chrono::milliseconds remaining(Clock::time_point deadline) {
  return std::max(std::chrono::milliseconds(0),
                  std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()));
}

// A tile of the neutral ground: a hole everywhere, which the mesh fills at the neutral height.
std::shared_ptr<const terrain::HeightTile> neutral_tile(const terrain::TileId& id) {
  auto tile = std::make_shared<terrain::HeightTile>();
  tile->id = id;
  tile->width = tile->height = 2;
  tile->layout = terrain::SampleLayout::pixel_is_point;
  tile->heights.assign(4, terrain::kNoHeight);
  return tile;
}

// Times `run` as the profiler's pass `name` (when there is a profiler).
template <typename Run>
void timed(FrameProfiler* profiler, std::string_view name, Run&& run) {
  if (profiler == nullptr) return run();
  const FrameProfiler::Scope scope(*profiler, name);
  run();
}

// Adds the ancestors of the requested tiles down to `min_zoom`, coarsest first (higher
// priority than any wanted tile): without waiting, they stand in while their children load.
void add_ancestors(std::vector<terrain::TileRequest>& requests, int min_zoom) {
  constexpr double kAncestorPriority = 1.0e12;
  std::unordered_map<terrain::TileId, bool> seen;
  for (const auto& r : requests) seen.emplace(r.id, true);
  const std::size_t wanted = requests.size();
  for (std::size_t i = 0; i < wanted; ++i)
    for (auto up = geo::parent(requests[i].id); up && up->zoom >= min_zoom; up = geo::parent(*up)) {
      if (!seen.emplace(*up, true).second) break;  // its ancestors are in already
      requests.push_back({*up, kAncestorPriority - up->zoom});
    }
}

// An RGBA8 texture with its full mipmap chain (upload_imagery_texture).
std::size_t imagery_texture_bytes(std::uint32_t width, std::uint32_t height) {
  std::size_t bytes = 0;
  for (;;) {
    bytes += std::size_t{width} * height * 4;
    if (width == 1 && height == 1) return bytes;
    width = std::max(1u, width / 2);
    height = std::max(1u, height / 2);
  }
}

void add_progress(terrain::LoadProgress& total, const terrain::LoadProgress& p) {
  total.wanted += p.wanted;
  total.loaded += p.loaded;
  total.no_data += p.no_data;
  total.failed += p.failed;
}

}  // namespace

struct SceneRenderer::DrawnTile {
  terrain::TileId id;
  std::shared_ptr<const terrain::HeightTile> tile;
  bool has_data = false;
};

SceneRenderer::SceneRenderer(SceneSources sources, terrain::TileLoaderOptions loader_options)
    : sources_(sources), distance_encoding_(distance_encoding_for(query_gl_capabilities())) {
  if (sources_.heights != nullptr) {
    height_loader_ = std::make_unique<terrain::TileLoader<terrain::HeightTile>>(
        [source = sources_.heights](const terrain::TileId& id, std::stop_token stop) { return source->load(id, stop); },
        loader_options);
  }
  if (sources_.imagery != nullptr) {
    imagery_loader_ = std::make_unique<terrain::TileLoader<terrain::ImageTile>>(
        [source = sources_.imagery](const terrain::TileId& id, std::stop_token stop) { return source->load(id, stop); },
        loader_options);
  }
}

SceneRenderer::~SceneRenderer() = default;

std::vector<SceneRenderer::DrawnTile> SceneRenderer::load_height_tiles(const scene::Camera& camera,
                                                                       const SceneRenderOptions& options,
                                                                       SceneRenderReport& report) {
  const Clock::time_point deadline = Clock::now() + options.timeout;
  // NaN asks for the lowest loaded terrain in view (so the ground around a DEM does not stand
  // above its valleys), refined after each round; sea level until something is loaded.
  const bool lowest_in_view = std::isnan(options.neutral_ground_height_m);
  float neutral = lowest_in_view ? 0.0f : static_cast<float>(options.neutral_ground_height_m);
  terrain::LodSettings settings;
  settings.max_screen_error_px = options.max_screen_error_px;
  settings.tile_samples = kTerrainGridVertices - 1;
  settings.max_zoom = kNeutralMaxZoom;
  if (sources_.heights != nullptr) {
    settings.min_zoom = sources_.heights->info().min_zoom;
    settings.max_zoom = sources_.heights->info().max_zoom;
  }
  terrain::HeightRange height_range = [&](const terrain::TileId& id) -> std::optional<std::pair<float, float>> {
    if (!height_loader_) return std::pair{neutral, neutral};
    if (const auto tile = height_loader_->get(id); tile && tile->has_data()) {
      // Holes are drawn at the neutral height: the volume must hold them too.
      if (std::any_of(tile->heights.begin(), tile->heights.end(), [](float h) { return std::isnan(h); }))
        return std::pair{std::min(tile->min_m, neutral), std::max(tile->max_m, neutral)};
      return std::pair{tile->min_m, tile->max_m};
    }
    if (height_loader_->state(id) == terrain::TileState::no_data) return std::pair{neutral, neutral};
    return std::nullopt;
  };

  const terrain::LodCamera lod_camera = scene::to_lod_camera(camera);
  terrain::LodSelection selection;
  std::vector<terrain::TileId> previous;
  const auto update_lowest = [&] {
    if (!lowest_in_view) return;
    float lowest = INFINITY;
    for (const auto& t : selection.tiles)
      if (const auto tile = height_loader_->get(t.id); tile && tile->has_data()) lowest = std::min(lowest, tile->min_m);
    if (std::isfinite(lowest)) neutral = lowest;
  };
  for (int round = 0; round < kMaxSelectionRounds; ++round) {
    selection = terrain::select_tiles(lod_camera, settings, height_range);
    report.selection_rounds = round + 1;
    std::vector<terrain::TileId> ids;
    for (const auto& t : selection.tiles) ids.push_back(t.id);
    if (!height_loader_ || ids == previous) break;
    std::vector<terrain::TileRequest> requests;
    for (const auto& t : selection.tiles) requests.push_back({t.id, t.priority});
    if (!options.wait_for_tiles) {
      // One round: the next frame selects again with whatever heights have arrived.
      add_ancestors(requests, settings.min_zoom);
      height_loader_->request(requests);
      update_lowest();
      break;
    }
    height_loader_->request(requests);
    if (!height_loader_->wait_until_done(remaining(deadline), options.on_progress)) {
      report.timed_out = true;
      break;
    }
    update_lowest();
    previous = std::move(ids);
  }
  if (height_loader_) add_progress(report.progress, height_loader_->progress());
  report.neutral_ground_height_m = neutral;

  std::vector<DrawnTile> drawn;
  report.neutral_ground_height_m = neutral;
  if (!height_loader_) {
    for (const auto& t : selection.tiles) drawn.push_back({t.id, neutral_tile(t.id), false});
    return drawn;
  }
  report.failures = height_loader_->failures();
  // A tile the source has nothing for (or failed on) is drawn as the neutral ground, so the view
  // never shows the sky through the ground.
  const auto settled = [&](const terrain::TileId& id) {
    const terrain::TileState state = height_loader_->state(id);
    return state == terrain::TileState::loaded || state == terrain::TileState::no_data ||
           state == terrain::TileState::failed;
  };
  for (const terrain::TileId& id : terrain::tiles_to_draw(selection, settled)) {
    auto tile = height_loader_->get(id);
    if (tile && tile->has_data())
      drawn.push_back({id, std::move(tile), true});
    else
      drawn.push_back({id, neutral_tile(id), false});
  }
  return drawn;
}

std::vector<TerrainImagery> SceneRenderer::load_imagery(const std::vector<DrawnTile>& tiles,
                                                        const SceneRenderOptions& options, Clock::time_point deadline,
                                                        SceneRenderReport& report) {
  std::vector<TerrainImagery> imagery(tiles.size());
  if (!imagery_loader_) return imagery;
  const int max_zoom = sources_.imagery->info().max_zoom;
  const int min_zoom = sources_.imagery->info().min_zoom;
  // Each height tile wants the imagery tile of its own id, or of its ancestor at the imagery's
  // finest level.
  std::vector<std::optional<terrain::TileId>> wanted(tiles.size());
  std::vector<terrain::TileRequest> requests;
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    std::optional<terrain::TileId> id = tiles[i].id;
    while (id && id->zoom > max_zoom) id = geo::parent(*id);
    if (!id || id->zoom < min_zoom) continue;
    wanted[i] = id;
    requests.push_back({*id, static_cast<double>(tiles.size() - i)});
  }
  if (options.wait_for_tiles) {
    imagery_loader_->request(requests);
    if (!imagery_loader_->wait_until_done(remaining(deadline), options.on_progress)) report.timed_out = true;
  } else {
    add_ancestors(requests, min_zoom);
    imagery_loader_->request(requests);
  }
  add_progress(report.progress, imagery_loader_->progress());
  for (const auto& f : imagery_loader_->failures()) report.failures.push_back(f);

  for (std::size_t i = 0; i < tiles.size(); ++i) {
    if (!wanted[i]) continue;
    auto image = imagery_loader_->get(*wanted[i]);
    // Still loading: the nearest coarser image in memory stands in (only when not waiting).
    while (!options.wait_for_tiles && !image && wanted[i]->zoom > min_zoom) {
      wanted[i] = geo::parent(*wanted[i]);
      if (!wanted[i]) break;
      image = imagery_loader_->get(*wanted[i]);
    }
    if (!wanted[i] || !image || image->width == 0 || image->height == 0) continue;
    const Texture* texture = imagery_textures_.find(*wanted[i]);
    if (texture == nullptr)
      texture = &imagery_textures_.insert(*wanted[i], upload_imagery_texture(image->width, image->height, image->rgba),
                                          imagery_texture_bytes(image->width, image->height));
    const int levels_up = tiles[i].id.zoom - wanted[i]->zoom;
    const double scale = std::ldexp(1.0, -levels_up);
    const std::uint32_t mask = (1u << levels_up) - 1u;
    TerrainImagery& t = imagery[i];
    t.texture = texture;
    t.scale = glm::vec2(static_cast<float>(scale));
    t.offset = glm::vec2(static_cast<float>((tiles[i].id.x & mask) * scale),
                         static_cast<float>((tiles[i].id.y & mask) * scale));
    ++report.imagery_tiles_used;
  }
  return imagery;
}

double SceneRenderer::height_in_memory(double lat_deg, double lon_deg) const {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (!height_loader_) return kNaN;
  const terrain::SourceInfo& info = sources_.heights->info();
  for (int zoom = info.max_zoom; zoom >= info.min_zoom; --zoom) {
    const auto id = geo::tile_containing(lat_deg, lon_deg, zoom);
    const auto where = geo::fractional_tile_coord(lat_deg, lon_deg, zoom);
    if (!id || !where) return kNaN;
    const auto tile = height_loader_->get(*id);
    if (!tile || !tile->has_data() || tile->width < 2 || tile->height < 2) continue;
    // The sample grid: corners on the tile's edges (pixel is point) or on cell centres (area).
    const bool point = tile->layout == terrain::SampleLayout::pixel_is_point;
    const double fx = where->x - id->x, fy = where->y - id->y;
    const double gx = point ? fx * (tile->width - 1) : fx * tile->width - 0.5;
    const double gy = point ? fy * (tile->height - 1) : fy * tile->height - 0.5;
    const double cx = std::clamp(gx, 0.0, tile->width - 1.0), cy = std::clamp(gy, 0.0, tile->height - 1.0);
    const auto c0 = static_cast<std::uint32_t>(std::min(cx, tile->width - 2.0));
    const auto r0 = static_cast<std::uint32_t>(std::min(cy, tile->height - 2.0));
    const double tx = cx - c0, ty = cy - r0;
    const double h = (1 - ty) * ((1 - tx) * tile->at(c0, r0) + tx * tile->at(c0 + 1, r0)) +
                     ty * ((1 - tx) * tile->at(c0, r0 + 1) + tx * tile->at(c0 + 1, r0 + 1));
    if (!std::isnan(h)) return h;
  }
  return kNaN;
}

RenderedScene SceneRenderer::render(const scene::Camera& camera, const SceneRenderOptions& options) {
  RenderedScene scene;
  meshes_.begin_frame();
  imagery_textures_.begin_frame();
  const Clock::time_point deadline = Clock::now() + options.timeout;
  const std::vector<DrawnTile> tiles = load_height_tiles(camera, options, scene.report);
  const std::vector<TerrainImagery> imagery = load_imagery(tiles, options, deadline, scene.report);

  const auto neutral = static_cast<float>(scene.report.neutral_ground_height_m);
  const int max_zoom = sources_.heights != nullptr ? sources_.heights->info().max_zoom : kNeutralMaxZoom;
  std::vector<TerrainDrawItem> items;
  items.reserve(tiles.size());
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const terrain::HeightTile& tile = *tiles[i].tile;
    // The finest level carries every sample the source has; coarser levels the LOD grid; the flat
    // neutral ground only bends with the Earth, which a few vertices follow.
    std::uint32_t grid = kTerrainGridVertices;
    if (!tiles[i].has_data)
      grid = kNeutralGridVertices;
    else if (tile.id.zoom >= max_zoom)
      grid = std::max(kTerrainGridVertices, full_resolution_grid(tile));
    const TerrainTileGpu& mesh = meshes_.get_or_upload(tile, grid, neutral);
    items.push_back({&mesh, imagery[i]});
    ++scene.report.tiles_drawn;
    if (tiles[i].has_data) ++scene.report.tiles_with_data;
  }

  const scene::Lens& lens = camera.lens();
  const int width = static_cast<int>(lens.width_px), height = static_cast<int>(lens.height_px);
  ComposeSettings compose;
  compose.atmosphere = options.atmosphere;
  const SceneLighting lighting = lighting_for(options.sun_direction_ecef, camera, compose.model);
  // The sun's disc below the horizon gives no direct light (sun_radiance is 0): nothing to shade.
  const bool sun_up = glm::dot(lighting.sun_radiance, glm::vec3(1.0f)) > 0.0f;
  std::optional<ShadowCascades> cascades;
  if (options.shadows && sun_up) {
    ShadowCascadeSettings shadow_settings;
    shadow_settings.map_size_px = options.shadow_map_size_px;
    // Casters reach towards the sun by the height span of what is drawn.
    float lowest = neutral, highest = neutral;
    for (const auto& t : tiles)
      if (t.has_data) {
        lowest = std::min(lowest, t.tile->min_m);
        highest = std::max(highest, t.tile->max_m);
      }
    // Tracks (a flight kilometres above the ground) cast shadows too.
    double track_top = highest;
    if (options.track_settings.cast_shadows)
      for (const TrackDraw& draw : options.tracks)
        if (draw.buffer != nullptr && draw.buffer->point_count() > 0) {
          const glm::dvec3 c = draw.buffer->bounding_centre_ecef();
          const double centre_height = geo::geodetic_from_ecef(c).height_m;
          track_top = std::max(track_top, centre_height + draw.buffer->bounding_radius_m());
        }
    shadow_settings.caster_height_span_m = std::max(0.0, track_top - lowest);
    cascades.emplace(camera, options.sun_direction_ecef, shadow_settings);
    if (!shadow_maps_ || shadow_maps_->map_size_px() != options.shadow_map_size_px)
      shadow_maps_.emplace(options.shadow_map_size_px);
  }

  // The tracks' block origins relative to this camera (the shadow and track passes use them).
  TrackPass::prepare(options.tracks, camera);
  FrameProfiler* profiler = options.profiler;
  if (profiler != nullptr) profiler->begin_frame();
  if (cascades) {
    timed(profiler, "shadows", [&] {
      const ShaderProgram& casters = shadow_maps_->caster_program();
      std::size_t cascade = 0;
      // Each tile with its own origin: the cascade's matrix relative to it, taken in double.
      shadow_maps_->render(*cascades, [&](const std::array<float, 16>&) {
        casters.use();
        const ShadowCascade& light = (*cascades)[cascade];
        for (const TerrainDrawItem& item : items) {
          if (item.mesh == nullptr || item.mesh->index_count == 0) continue;
          // The near cascades cover a few km: most tiles of the view fall outside them.
          if (!light.may_hold(item.mesh->origin, item.mesh->bounding_radius_m)) continue;
          const std::array<float, 16> matrix = light.view_projection_relative_to(item.mesh->origin);
          casters.set_mat4("u_light_view_projection", std::span<const float, 16>(matrix));
          glBindVertexArray(item.mesh->vertex_array.id());
          glDrawElements(GL_TRIANGLES, item.mesh->index_count, GL_UNSIGNED_INT, nullptr);
        }
        glBindVertexArray(0);
        if (options.track_settings.cast_shadows) {
          // Only the tracks that reach into this cascade (a flight far from the camera casts
          // into the far cascades only).
          std::vector<TrackDraw> casting;
          for (const TrackDraw& draw : options.tracks)
            if (draw.buffer != nullptr &&
                light.may_hold(draw.buffer->bounding_centre_ecef(), draw.buffer->bounding_radius_m()))
              casting.push_back(draw);
          if (!casting.empty()) {
            const std::array<float, 16> relative = light.view_projection_relative_to(camera.position());
            track_pass_.draw_shadow_casters(relative, options.sun_direction_ecef,
                                            2.0 * light.radius_m / options.shadow_map_size_px, camera, casting,
                                            options.track_settings);
          }
        }
        ++cascade;
      });
    });
    scene.report.shadows_drawn = true;
  }
  const GBuffer gbuffer(width, height, distance_encoding_);
  timed(profiler, "tiles", [&] { terrain_pass_.draw(gbuffer, camera, items, options.snow); });
  std::optional<TrackOverlayTarget> track_overlay;
  if (!options.tracks.empty()) {
    timed(profiler, "tracks", [&] {
      // The overlay reads the terrain's distances, so it goes before the tracks enter the G-buffer.
      track_overlay.emplace(width, height);
      track_pass_.draw_overlay(gbuffer, *track_overlay, camera, lighting, options.tracks, options.track_settings);
      track_pass_.draw_visible(gbuffer, camera, options.tracks, options.track_settings);
    });
  }
  const Texture* ambient_occlusion = nullptr;
  if (options.ssao) timed(profiler, "ssao", [&] { ambient_occlusion = &ssao_pass_.run(gbuffer, camera); });
  FrameTarget target(width, height);
  // The atmosphere (aerial perspective and sky) is drawn by the compose pass's one draw: its time
  // is compose's, and the profiler's "atmosphere" row stays empty.
  timed(profiler, "compose", [&] {
    target.bind();
    const ComposeShadows shadows{cascades ? &*shadow_maps_ : nullptr, cascades ? &*cascades : nullptr};
    compose_pass_.draw(gbuffer, ambient_occlusion, cascades ? &shadows : nullptr, camera, lighting, compose);
  });
  if (track_overlay) timed(profiler, "overlays", [&] { track_pass_.blend_overlay(*track_overlay); });
  if (options.read_back)
    timed(profiler, "readback", [&] { scene.image = read_rgba8(0, 0, target.width(), target.height()); });
  if (options.blit_to_default_framebuffer) {
    target.bind();
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (profiler != nullptr) profiler->end_frame();
  // Between frames: the draw lists above point into the caches until here.
  meshes_.evict_to_budget(options.mesh_budget_bytes);
  imagery_textures_.set_budget(options.imagery_budget_bytes);
  imagery_textures_.evict_to_budget();
  scene.report.gpu_meshes = meshes_.stats();
  scene.report.gpu_imagery = imagery_textures_.stats();
  return scene;
}

}  // namespace trailray::render
