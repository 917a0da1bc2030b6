#include "scene/terrain_view.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_map>
#include <utility>

#include "geo/tile_id.hpp"
#include "terrain/lod/lod_selection.hpp"
#include "terrain/tile_sampling.hpp"

namespace trailray::scene {
namespace {

using Clock = std::chrono::steady_clock;

// The finest level to split to when there is no height source: the neutral ground is flat, so
// only the Earth's curvature asks for detail, and a zoom-12 tile (10 km) bends by under 2 m.
constexpr int kNeutralMaxZoom = 12;
constexpr int kMaxSelectionRounds = 4;

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

void add_progress(terrain::LoadProgress& total, const terrain::LoadProgress& p) {
  total.wanted += p.wanted;
  total.loaded += p.loaded;
  total.no_data += p.no_data;
  total.failed += p.failed;
}

template <class Tile, class Source>
std::unique_ptr<terrain::TileLoader<Tile>> make_loader(Source* source, const terrain::TileLoaderOptions& options) {
  if (source == nullptr) return nullptr;
  return std::make_unique<terrain::TileLoader<Tile>>(
      [source](const terrain::TileId& id, terrain::StopToken stop) { return source->load(id, stop); }, options);
}

}  // namespace

// The outcome of the selection rounds: the wanted tiles and the neutral ground's height.
struct TerrainView::Selected {
  terrain::LodSelection selection;
  float neutral = 0.0f;
};

TerrainView::TerrainView(terrain::HeightSource* heights, terrain::ImagerySource* imagery,
                         terrain::TileLoaderOptions loader_options)
    : heights_(heights),
      imagery_(imagery),
      height_loader_(make_loader<terrain::HeightTile>(heights, loader_options)),
      imagery_loader_(make_loader<terrain::ImageTile>(imagery, loader_options)) {}

TerrainView::~TerrainView() = default;

TerrainTiles TerrainView::tiles_for(const Camera& camera, double neutral_ground_m) {
  TerrainTiles out;
  const Clock::time_point deadline = Clock::now() + policy_.timeout;
  const Selected selected = select(camera, neutral_ground_m, deadline, out.report);
  out.tiles = height_tiles(selected, out.report);
  add_imagery(out.tiles, deadline, out.report);
  return out;
}

TerrainView::Selected TerrainView::select(const Camera& camera, double neutral_ground_m, Clock::time_point deadline,
                                          TerrainReport& report) {
  // NaN asks for the lowest loaded terrain in view (so the ground around a DEM does not stand
  // above its valleys), refined after each round; sea level until something is loaded.
  const bool lowest_in_view = std::isnan(neutral_ground_m);
  Selected s;
  s.neutral = lowest_in_view ? 0.0f : static_cast<float>(neutral_ground_m);
  terrain::LodSettings settings;
  settings.max_screen_error_px = policy_.max_screen_error_px;
  settings.tile_samples = kTerrainGridVertices - 1;
  settings.max_zoom = heights_ != nullptr ? heights_->info().max_zoom : kNeutralMaxZoom;
  if (heights_ != nullptr) settings.min_zoom = heights_->info().min_zoom;
  const terrain::HeightRange height_range = [&](const terrain::TileId& id) -> std::optional<std::pair<float, float>> {
    if (!height_loader_) return std::pair{s.neutral, s.neutral};
    if (const auto tile = height_loader_->get(id); tile && tile->has_data()) {
      // Holes are drawn at the neutral height: the volume must hold them too.
      if (std::any_of(tile->heights.begin(), tile->heights.end(), [](float h) { return std::isnan(h); }))
        return std::pair{std::min(tile->min_m, s.neutral), std::max(tile->max_m, s.neutral)};
      return std::pair{tile->min_m, tile->max_m};
    }
    if (height_loader_->state(id) == terrain::TileState::no_data) return std::pair{s.neutral, s.neutral};
    return std::nullopt;
  };
  const auto update_lowest = [&] {
    if (!lowest_in_view) return;
    float lowest = INFINITY;
    for (const auto& t : s.selection.tiles)
      if (const auto tile = height_loader_->get(t.id); tile && tile->has_data()) lowest = std::min(lowest, tile->min_m);
    if (std::isfinite(lowest)) s.neutral = lowest;
  };
  const terrain::LodCamera lod_camera = to_lod_camera(camera);
  std::vector<terrain::TileId> previous;
  for (int round = 0; round < kMaxSelectionRounds; ++round) {
    s.selection = terrain::select_tiles(lod_camera, settings, height_range);
    report.selection_rounds = round + 1;
    std::vector<terrain::TileId> ids;
    for (const auto& t : s.selection.tiles) ids.push_back(t.id);
    if (!height_loader_ || ids == previous) break;
    std::vector<terrain::TileRequest> requests;
    for (const auto& t : s.selection.tiles) requests.push_back({t.id, t.priority});
    if (!policy_.wait) {
      // One round: the next call selects again with whatever heights have arrived.
      add_ancestors(requests, settings.min_zoom);
      height_loader_->request(requests);
      update_lowest();
      break;
    }
    height_loader_->request(requests);
    if (!height_loader_->wait_until_done(remaining(deadline), policy_.on_progress)) {
      report.timed_out = true;
      break;
    }
    update_lowest();
    previous = std::move(ids);
  }
  return s;
}

std::vector<TerrainTile> TerrainView::height_tiles(const Selected& selected, TerrainReport& report) const {
  report.neutral_ground_m = selected.neutral;
  std::vector<TerrainTile> drawn;
  const auto neutral = [](const terrain::TileId& id) {
    TerrainTile t;
    t.heights = neutral_tile(id);
    return t;
  };
  if (!height_loader_) {
    for (const auto& t : selected.selection.tiles) drawn.push_back(neutral(t.id));
    return drawn;
  }
  add_progress(report.progress, height_loader_->progress());
  report.failures = height_loader_->failures();
  // A tile the source has nothing for (or failed on) is drawn as the neutral ground, so the view
  // never shows the sky through the ground.
  const auto settled = [&](const terrain::TileId& id) {
    const terrain::TileState state = height_loader_->state(id);
    return state == terrain::TileState::loaded || state == terrain::TileState::no_data ||
           state == terrain::TileState::failed;
  };
  const int finest = heights_->info().max_zoom;
  for (const terrain::TileId& id : terrain::tiles_to_draw(selected.selection, settled)) {
    auto tile = height_loader_->get(id);
    if (!tile || !tile->has_data()) {
      drawn.push_back(neutral(id));
      continue;
    }
    TerrainTile t;
    t.heights = std::move(tile);
    t.has_data = true;
    t.finest = id.zoom >= finest;
    drawn.push_back(std::move(t));
  }
  return drawn;
}

void TerrainView::add_imagery(std::vector<TerrainTile>& tiles, Clock::time_point deadline, TerrainReport& report) {
  if (!imagery_loader_) return;
  const int max_zoom = imagery_->info().max_zoom;
  const int min_zoom = imagery_->info().min_zoom;
  // Each height tile wants the imagery tile of its own id, or of its ancestor at the imagery's
  // finest level.
  std::vector<std::optional<terrain::TileId>> wanted(tiles.size());
  std::vector<terrain::TileRequest> requests;
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    std::optional<terrain::TileId> id = tiles[i].heights->id;
    while (id && id->zoom > max_zoom) id = geo::parent(*id);
    if (!id || id->zoom < min_zoom) continue;
    wanted[i] = id;
    requests.push_back({*id, static_cast<double>(tiles.size() - i)});
  }
  if (policy_.wait) {
    imagery_loader_->request(requests);
    if (!imagery_loader_->wait_until_done(remaining(deadline), policy_.on_progress)) report.timed_out = true;
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
    while (!policy_.wait && !image && wanted[i]->zoom > min_zoom) {
      wanted[i] = geo::parent(*wanted[i]);
      if (!wanted[i]) break;
      image = imagery_loader_->get(*wanted[i]);
    }
    if (!wanted[i] || !image || image->width == 0 || image->height == 0) continue;
    TerrainTile& t = tiles[i];
    const terrain::TileId& id = t.heights->id;
    const int levels_up = id.zoom - wanted[i]->zoom;
    const double scale = std::ldexp(1.0, -levels_up);
    const std::uint32_t mask = (1u << levels_up) - 1u;
    t.image = std::move(image);
    t.image_id = *wanted[i];
    t.image_scale = glm::vec2(static_cast<float>(scale));
    t.image_offset = glm::vec2(static_cast<float>((id.x & mask) * scale), static_cast<float>((id.y & mask) * scale));
  }
}

double TerrainView::height_in_memory(double lat_deg, double lon_deg) const {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (!height_loader_) return kNaN;
  const terrain::SourceInfo& info = heights_->info();
  for (int zoom = info.max_zoom; zoom >= info.min_zoom; --zoom) {
    const auto id = geo::tile_containing(lat_deg, lon_deg, zoom);
    const auto where = geo::fractional_tile_coord(lat_deg, lon_deg, zoom);
    if (!id || !where) return kNaN;
    const auto tile = height_loader_->get(*id);
    if (!tile || !tile->has_data() || tile->width < 2 || tile->height < 2) continue;
    // Neighbours across a seam count when they are in memory too.
    std::unordered_map<terrain::TileId, std::shared_ptr<const terrain::HeightTile>> held{{*id, tile}};
    const terrain::TileLookup tile_of = [&](const terrain::TileId& t) -> const terrain::HeightTile* {
      auto it = held.find(t);
      if (it == held.end()) it = held.emplace(t, height_loader_->get(t)).first;
      return it->second && it->second->has_data() ? it->second.get() : nullptr;
    };
    const terrain::SampleGrid grid{tile->width, tile->layout};
    const double h = terrain::bilinear_height(terrain::sample_footprint(*where, zoom, grid), zoom, grid, tile_of);
    if (!std::isnan(h)) return h;
  }
  return kNaN;
}

}  // namespace trailray::scene
