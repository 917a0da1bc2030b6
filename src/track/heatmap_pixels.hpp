#pragma once
// A heatmap seen as XYZ map tiles (256 x 256 pixels, Web Mercator, rows from the north): each
// pixel holds the largest count of the cells under it (its centre's cell when a pixel is smaller
// than a cell). The largest, not the sum: a pixel four cells wide crossed by one track along its
// four cells still says one track, so the picture reads the same at every zoom.

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "track/heatmap.hpp"

namespace trailray::track {

inline constexpr int kHeatmapTilePixels = 256;

// 256 x 256 counts, row by row from the north-west corner.
using HeatmapPixels = std::vector<std::uint32_t>;

// The zoom whose pixels are first no larger than a cell: the finest zoom worth drawing.
int heatmap_native_zoom(double cell_m);

// Every tile of `zoom` (0..24) with a non-zero pixel: (x, y) -> pixels.
std::map<std::pair<std::int64_t, std::int64_t>, HeatmapPixels> heatmap_tile_pixels(const HeatmapCounts& counts,
                                                                                   int zoom);

// The largest count of any cell.
std::uint32_t heatmap_max(const HeatmapCounts& counts);

}  // namespace trailray::track
