#include "terrain/tile_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace trailray::terrain {

SampleFootprint sample_footprint(const geo::TileCoord& c, int zoom, const SampleGrid& grid) {
  const bool area = grid.layout == SampleLayout::pixel_is_area;
  const std::uint64_t tiles = std::uint64_t{1} << zoom;
  const std::uint64_t step = area ? grid.width : grid.width - 1;
  // Samples per axis: area layout n * W (cell centres); point layout n * (W - 1) + 1 (shared edges).
  const std::uint64_t count = area ? tiles * step : tiles * step + 1;
  const std::uint64_t wrap = tiles * step;  // x repeats around the globe
  const double half = area ? 0.5 : 0.0;
  const double gx = c.x * static_cast<double>(step) - half;
  const double gy = std::clamp(c.y * static_cast<double>(step) - half, 0.0, static_cast<double>(count - 1));
  SampleFootprint f;
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

TileSample locate_sample(std::uint64_t col, std::uint64_t row, int zoom, const SampleGrid& grid) {
  const std::uint64_t tiles = std::uint64_t{1} << zoom;
  const std::uint64_t step = grid.layout == SampleLayout::pixel_is_area ? grid.width : grid.width - 1;
  const std::uint64_t tx = std::min(col / step, tiles - 1), ty = std::min(row / step, tiles - 1);
  return {TileId{zoom, static_cast<std::uint32_t>(tx), static_cast<std::uint32_t>(ty)},
          static_cast<std::uint32_t>(col - tx * step), static_cast<std::uint32_t>(row - ty * step)};
}

namespace {

// The four samples' weighted mean, nodata samples (and those of no weight) left out.
class WeightedHeights {
 public:
  void add(float h, double w) {
    if (std::isnan(h) || w <= 0.0) return;
    sum_ += w * h;
    weight_ += w;
  }
  double mean() const { return weight_ > 0.0 ? sum_ / weight_ : std::numeric_limits<double>::quiet_NaN(); }

 private:
  double sum_ = 0.0, weight_ = 0.0;
};

}  // namespace

double bilinear_height(const SampleFootprint& f, int zoom, const SampleGrid& grid, const TileLookup& tile_of) {
  WeightedHeights heights;
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) {
      const TileSample s = locate_sample(f.col[c], f.row[r], zoom, grid);
      const HeightTile* tile = tile_of(s.tile);
      if (tile == nullptr || s.col >= tile->width || s.row >= tile->height) continue;
      heights.add(tile->at(s.col, s.row), (c ? f.tx : 1.0 - f.tx) * (r ? f.ty : 1.0 - f.ty));
    }
  return heights.mean();
}

double bilinear_in_tile(const HeightTile& t, double col, double row) {
  if (t.width == 0 || t.height == 0) return std::numeric_limits<double>::quiet_NaN();
  col = std::clamp(col, 0.0, double(t.width - 1));
  row = std::clamp(row, 0.0, double(t.height - 1));
  const auto c0 = static_cast<std::uint32_t>(std::floor(col)), r0 = static_cast<std::uint32_t>(std::floor(row));
  const std::uint32_t c1 = std::min(c0 + 1, t.width - 1), r1 = std::min(r0 + 1, t.height - 1);
  const double fx = col - c0, fy = row - r0;
  WeightedHeights heights;
  heights.add(t.at(c0, r0), (1 - fx) * (1 - fy));
  heights.add(t.at(c1, r0), fx * (1 - fy));
  heights.add(t.at(c0, r1), (1 - fx) * fy);
  heights.add(t.at(c1, r1), fx * fy);
  return heights.mean();
}

}  // namespace trailray::terrain
