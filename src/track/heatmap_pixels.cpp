#include "track/heatmap_pixels.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geo/web_mercator.hpp"

namespace trailray::track {
namespace {

constexpr double kWorld = 2.0 * geo::kMercatorHalfExtentM;
constexpr std::size_t kPixels = std::size_t{kHeatmapTilePixels} * kHeatmapTilePixels;

double pixel_m(int zoom) { return kWorld / (kHeatmapTilePixels * std::ldexp(1.0, zoom)); }

void check_zoom(int zoom) {
  if (zoom < 0 || zoom > 24) throw std::invalid_argument("heatmap tile zoom " + std::to_string(zoom) + " is not in 0..24");
}

// Pixels smaller than a cell: each pixel takes its centre's cell.
void gather(const HeatmapCounts& counts, int zoom, std::int64_t x, std::int64_t y, HeatmapPixels& out) {
  const double p = pixel_m(zoom), cell = counts.cell_m();
  const std::int64_t n = counts.cells_per_side();
  // The cell of each column and row of pixels (Mercator metres from the north-west corner / cell).
  std::vector<std::int64_t> cols(kHeatmapTilePixels), rows(kHeatmapTilePixels);
  for (int i = 0; i < kHeatmapTilePixels; ++i) {
    cols[static_cast<std::size_t>(i)] = std::min<std::int64_t>(
        n - 1, static_cast<std::int64_t>(std::floor((static_cast<double>(x * kHeatmapTilePixels + i) + 0.5) * p / cell)));
    rows[static_cast<std::size_t>(i)] = std::min<std::int64_t>(
        n - 1, static_cast<std::int64_t>(std::floor((static_cast<double>(y * kHeatmapTilePixels + i) + 0.5) * p / cell)));
  }
  for (int r = 0; r < kHeatmapTilePixels; ++r)
    for (int c = 0; c < kHeatmapTilePixels; ++c)
      out[static_cast<std::size_t>(r * kHeatmapTilePixels + c)] =
          counts.at({cols[static_cast<std::size_t>(c)], rows[static_cast<std::size_t>(r)]});
}

}  // namespace

int heatmap_native_zoom(double cell_m) {
  for (int z = 0; z < 24; ++z)
    if (pixel_m(z) <= cell_m) return z;
  return 24;
}

std::uint32_t heatmap_max(const HeatmapCounts& counts) {
  std::uint32_t most = 0;
  for (const auto& [key, tile] : counts.tiles()) most = std::max(most, *std::max_element(tile.begin(), tile.end()));
  return most;
}

std::map<std::pair<std::int64_t, std::int64_t>, HeatmapPixels> heatmap_tile_pixels(const HeatmapCounts& counts,
                                                                                   int zoom) {
  check_zoom(zoom);
  std::map<std::pair<std::int64_t, std::int64_t>, HeatmapPixels> out;
  const double p = pixel_m(zoom), cell = counts.cell_m();
  const std::int64_t tiles_per_side = std::int64_t{1} << zoom;
  if (p >= cell) {
    // Pixels at least a cell wide: every counted cell puts its count into the pixel of its centre.
    for (const auto& [key, tile] : counts.tiles())
      for (int r = 0; r < kHeatmapTileCells; ++r)
        for (int c = 0; c < kHeatmapTileCells; ++c) {
          const std::uint32_t v = tile[static_cast<std::size_t>(r * kHeatmapTileCells + c)];
          if (v == 0) continue;
          const double cx = (static_cast<double>(key.first * kHeatmapTileCells + c) + 0.5) * cell / p;
          const double cy = (static_cast<double>(key.second * kHeatmapTileCells + r) + 0.5) * cell / p;
          const auto gx = std::clamp<std::int64_t>(static_cast<std::int64_t>(cx), 0, tiles_per_side * kHeatmapTilePixels - 1);
          const auto gy = std::clamp<std::int64_t>(static_cast<std::int64_t>(cy), 0, tiles_per_side * kHeatmapTilePixels - 1);
          HeatmapPixels& pixels = out[{gx / kHeatmapTilePixels, gy / kHeatmapTilePixels}];
          if (pixels.empty()) pixels.assign(kPixels, 0);
          std::uint32_t& px = pixels[static_cast<std::size_t>((gy % kHeatmapTilePixels) * kHeatmapTilePixels +
                                                              gx % kHeatmapTilePixels)];
          px = std::max(px, v);
        }
    return out;
  }
  // Pixels smaller than a cell: the XYZ tiles each counts tile overlaps, gathered once each.
  const double tile_m = p * kHeatmapTilePixels, counts_tile_m = cell * kHeatmapTileCells;
  for (const auto& [key, tile] : counts.tiles()) {
    const auto x0 = static_cast<std::int64_t>(std::floor(static_cast<double>(key.first) * counts_tile_m / tile_m));
    const auto x1 = static_cast<std::int64_t>(std::floor(static_cast<double>(key.first + 1) * counts_tile_m / tile_m));
    const auto y0 = static_cast<std::int64_t>(std::floor(static_cast<double>(key.second) * counts_tile_m / tile_m));
    const auto y1 = static_cast<std::int64_t>(std::floor(static_cast<double>(key.second + 1) * counts_tile_m / tile_m));
    for (std::int64_t y = std::max<std::int64_t>(y0, 0); y <= std::min(y1, tiles_per_side - 1); ++y)
      for (std::int64_t x = std::max<std::int64_t>(x0, 0); x <= std::min(x1, tiles_per_side - 1); ++x) {
        if (out.find({x, y}) != out.end()) continue;
        HeatmapPixels pixels(kPixels, 0);
        gather(counts, zoom, x, y, pixels);
        if (std::any_of(pixels.begin(), pixels.end(), [](std::uint32_t v) { return v != 0; }))
          out.emplace(std::pair{x, y}, std::move(pixels));
      }
  }
  return out;
}

}  // namespace trailray::track
