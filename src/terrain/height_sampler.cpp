#include "terrain/height_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include "geo/tile_id.hpp"
#include "terrain/tile_sampling.hpp"

namespace trailray::terrain {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Consecutive track points share tiles: the work cut into batches of at most `tiles_per_batch`
// containing tiles, so a long flight never holds all its tiles in memory at once.
std::vector<std::vector<std::size_t>> batches_by_tile(std::span<const geo::LatLon> points,
                                                      const std::vector<std::size_t>& todo, int zoom,
                                                      std::size_t tiles_per_batch) {
  std::vector<std::vector<std::size_t>> batches;
  std::unordered_set<TileId> tiles;
  for (std::size_t i : todo) {
    const auto tile = geo::tile_containing(points[i].lat, points[i].lon, zoom);
    if (!tile) continue;
    if (!tiles.contains(*tile) && tiles.size() >= tiles_per_batch) {
      tiles.clear();
      batches.emplace_back();
    }
    if (batches.empty()) batches.emplace_back();
    tiles.insert(*tile);
    batches.back().push_back(i);
  }
  return batches;
}

// The footprints of a batch's points (into `feet`) and the tiles their samples lie in.
std::unordered_set<TileId> footprints(std::span<const geo::LatLon> points, const std::vector<std::size_t>& batch,
                                      int zoom, const SampleGrid& grid, std::vector<SampleFootprint>& feet) {
  feet.reserve(batch.size());
  std::unordered_set<TileId> needed;
  for (std::size_t i : batch) {
    const auto c = geo::fractional_tile_coord(points[i].lat, points[i].lon, zoom);
    feet.push_back(sample_footprint(*c, zoom, grid));
    for (auto col : feet.back().col)
      for (auto row : feet.back().row) needed.insert(locate_sample(col, row, zoom, grid).tile);
  }
  return needed;
}

}  // namespace

HeightSampler::HeightSampler(HeightSource& source, HeightSamplerOptions options) : source_(source), options_(options) {}

double HeightSampler::sample(double lat, double lon) {
  const geo::LatLon p{lat, lon};
  return sample(std::span<const geo::LatLon>(&p, 1)).front();
}

std::vector<double> HeightSampler::sample(std::span<const geo::LatLon> points, const ProgressFunction& on_progress) {
  report_ = {};
  report_.points = points.size();
  std::vector<double> out(points.size(), kNaN);
  if (points.empty()) return out;

  if (source_.sample_native(points.front().lat, points.front().lon).has_value()) {
    for (std::size_t i = 0; i < points.size(); ++i) out[i] = *source_.sample_native(points[i].lat, points[i].lon);
  } else {
    std::vector<std::size_t> todo;
    for (std::size_t i = 0; i < points.size(); ++i)
      if (std::isfinite(points[i].lat) && std::isfinite(points[i].lon)) todo.push_back(i);
    const SourceInfo& info = source_.info();
    const int finest = options_.zoom >= 0 ? options_.zoom : info.max_zoom;
    for (int zoom = std::min(finest, geo::kMaxTileZoom); zoom >= std::max(0, info.min_zoom) && !todo.empty(); --zoom)
      sample_level(points, todo, zoom, out, on_progress);
  }
  for (double h : out) report_.with_height += std::isnan(h) ? 0 : 1;
  return out;
}

bool HeightSampler::wait(TileLoader<HeightTile>& loader, const ProgressFunction& on_progress, std::size_t batch,
                         std::size_t batches) {
  // A source's own timeouts bound each tile; this only guards against a wedged source.
  return loader.wait_until_done(std::chrono::hours(24), [&](const LoadProgress& p) {
    if (on_progress) on_progress(p, batch, batches);
  });
}

void HeightSampler::sample_level(std::span<const geo::LatLon> points, std::vector<std::size_t>& todo, int zoom,
                                 std::vector<double>& out, const ProgressFunction& on_progress) {
  const std::vector<std::vector<std::size_t>> batches = batches_by_tile(points, todo, zoom, options_.tiles_per_batch);
  TileLoaderOptions loader_options;
  loader_options.threads = options_.threads;
  // Room for a batch with its seam neighbours, at 256 x 256 floats a tile.
  loader_options.memory_budget_bytes = options_.tiles_per_batch * 4 * (256u * 256u * sizeof(float) + 1024u);
  TileLoader<HeightTile> loader([this](const TileId& id, StopToken stop) { return source_.load(id, stop); },
                                loader_options);

  std::unordered_map<TileId, TileState> seen;
  std::unordered_set<std::string> errors;
  auto collect_errors = [&] {
    for (auto& e : loader.failures()) errors.insert(std::move(e));
  };
  std::vector<std::size_t> left;  // points this level could not answer
  for (std::size_t b = 0; b < batches.size(); ++b) {
    const auto& batch = batches[b];
    // The containing tiles first: they tell the grid's size and layout.
    std::vector<TileRequest> requests;
    for (std::size_t i : batch) requests.push_back({*geo::tile_containing(points[i].lat, points[i].lon, zoom), 1.0});
    loader.request(requests);
    wait(loader, on_progress, b, batches.size());
    if (grid_.width == 0) {
      for (const auto& r : requests)
        if (auto tile = loader.get(r.id); tile && tile->width >= 2 && tile->width == tile->height) {
          grid_ = {tile->width, tile->layout};
          break;
        }
    }
    if (grid_.width == 0) {
      collect_errors();
      for (const auto& r : requests) seen[r.id] = loader.state(r.id);
      left.insert(left.end(), batch.begin(), batch.end());
      continue;
    }
    // Then the neighbours across seams that the four samples around each point need.
    std::vector<SampleFootprint> feet;
    const std::unordered_set<TileId> needed = footprints(points, batch, zoom, grid_, feet);
    requests.clear();
    for (const auto& id : needed) requests.push_back({id, 1.0});
    loader.request(requests);
    wait(loader, on_progress, b, batches.size());
    collect_errors();
    std::unordered_map<TileId, std::shared_ptr<const HeightTile>> tiles;
    for (const auto& id : needed) {
      seen[id] = loader.state(id);
      if (auto tile = loader.get(id)) tiles.emplace(id, std::move(tile));
    }

    const TileLookup tile_of = [&](const TileId& id) -> const HeightTile* {
      const auto it = tiles.find(id);
      return it == tiles.end() ? nullptr : it->second.get();
    };
    for (std::size_t k = 0; k < batch.size(); ++k) {
      const double h = bilinear_height(feet[k], zoom, grid_, tile_of);
      if (std::isnan(h))
        left.push_back(batch[k]);
      else
        out[batch[k]] = h;
    }
  }
  for (const auto& [id, state] : seen) {
    if (state == TileState::loaded) ++report_.tiles_loaded;
    if (state == TileState::no_data) ++report_.tiles_no_data;
    if (state == TileState::failed) ++report_.tiles_failed;
  }
  report_.errors.insert(report_.errors.end(), errors.begin(), errors.end());
  todo = std::move(left);
}

}  // namespace trailray::terrain
