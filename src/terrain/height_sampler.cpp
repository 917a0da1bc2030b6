#include "terrain/height_sampler.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include "geo/tile_id.hpp"

namespace trailray::terrain {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Where a point falls in a level's global sample grid: the four samples around it and the
// bilinear weights. Sample indices run over the whole world (tile x * step + column).
struct Footprint {
  std::array<std::uint64_t, 2> col{}, row{};
  double tx = 0.0, ty = 0.0;  // fractions between col[0]..col[1] and row[0]..row[1]
};

Footprint footprint(const geo::TileCoord& c, int zoom, std::uint32_t width, SampleLayout layout) {
  const bool area = layout == SampleLayout::pixel_is_area;
  const std::uint64_t tiles = std::uint64_t{1} << zoom;
  const std::uint64_t step = area ? width : width - 1;
  // Samples per axis: area layout n * W (cell centres); point layout n * (W - 1) + 1 (shared edges).
  const std::uint64_t count = area ? tiles * step : tiles * step + 1;
  const std::uint64_t wrap = tiles * step;  // x repeats around the globe
  const double half = area ? 0.5 : 0.0;
  const double gx = c.x * static_cast<double>(step) - half;
  const double gy = std::clamp(c.y * static_cast<double>(step) - half, 0.0, static_cast<double>(count - 1));
  Footprint f;
  const double fx = std::floor(gx), fy = std::floor(gy);
  f.tx = gx - fx;
  f.ty = gy - fy;
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
  const auto w = static_cast<std::int64_t>(wrap);
  f.col[0] = static_cast<std::uint64_t>(((ix % w) + w) % w);
  f.col[1] = static_cast<std::uint64_t>((((ix + 1) % w) + w) % w);
  f.row[0] = static_cast<std::uint64_t>(iy);
  f.row[1] = std::min<std::uint64_t>(static_cast<std::uint64_t>(iy) + 1, count - 1);
  return f;
}

// The tile holding a global sample, and the sample's column/row inside it.
struct TileSample {
  TileId tile;
  std::uint32_t col = 0, row = 0;
};

TileSample locate(std::uint64_t col, std::uint64_t row, int zoom, std::uint32_t width, SampleLayout layout) {
  const std::uint64_t tiles = std::uint64_t{1} << zoom;
  const std::uint64_t step = layout == SampleLayout::pixel_is_area ? width : width - 1;
  const std::uint64_t tx = std::min(col / step, tiles - 1), ty = std::min(row / step, tiles - 1);
  return {TileId{zoom, static_cast<std::uint32_t>(tx), static_cast<std::uint32_t>(ty)},
          static_cast<std::uint32_t>(col - tx * step), static_cast<std::uint32_t>(row - ty * step)};
}

}  // namespace

HeightSampler::HeightSampler(HeightSource& source, HeightSamplerOptions options)
    : source_(source), options_(options) {}

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
  // Consecutive track points share tiles: cut the work into batches of at most tiles_per_batch
  // containing tiles, so a long flight never holds all its tiles in memory at once.
  std::vector<std::vector<std::size_t>> batches;
  {
    std::unordered_set<TileId> tiles;
    for (std::size_t i : todo) {
      const auto tile = geo::tile_containing(points[i].lat, points[i].lon, zoom);
      if (!tile) continue;
      if (!tiles.contains(*tile) && tiles.size() >= options_.tiles_per_batch) {
        tiles.clear();
        batches.emplace_back();
      }
      if (batches.empty()) batches.emplace_back();
      tiles.insert(*tile);
      batches.back().push_back(i);
    }
  }
  TileLoaderOptions loader_options;
  loader_options.threads = options_.threads;
  // Room for a batch with its seam neighbours, at 256 x 256 floats a tile.
  loader_options.memory_budget_bytes = options_.tiles_per_batch * 4 * (256u * 256u * sizeof(float) + 1024u);
  TileLoader<HeightTile> loader([this](const TileId& id, std::stop_token stop) { return source_.load(id, stop); },
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
    std::vector<Footprint> feet;
    feet.reserve(batch.size());
    std::unordered_set<TileId> needed;
    for (std::size_t i : batch) {
      const auto c = geo::fractional_tile_coord(points[i].lat, points[i].lon, zoom);
      feet.push_back(footprint(*c, zoom, grid_.width, grid_.layout));
      for (auto col : feet.back().col)
        for (auto row : feet.back().row) needed.insert(locate(col, row, zoom, grid_.width, grid_.layout).tile);
    }
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

    for (std::size_t k = 0; k < batch.size(); ++k) {
      const Footprint& f = feet[k];
      double sum = 0.0, weight = 0.0;
      for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 2; ++c) {
          const double w = (c ? f.tx : 1.0 - f.tx) * (r ? f.ty : 1.0 - f.ty);
          const TileSample s = locate(f.col[c], f.row[r], zoom, grid_.width, grid_.layout);
          auto it = tiles.find(s.tile);
          if (it == tiles.end() || s.col >= it->second->width || s.row >= it->second->height) continue;
          const float h = it->second->at(s.col, s.row);
          if (std::isnan(h) || w <= 0.0) continue;
          sum += w * h;
          weight += w;
        }
      if (weight > 0.0)
        out[batch[k]] = sum / weight;
      else
        left.push_back(batch[k]);
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
