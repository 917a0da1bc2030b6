#pragma once
// The heatmap's own exchange format, what `trailray heatmap` writes beside its coloured tiles so
// that partial heatmaps add up exactly later (app/pictures/heatmap_output puts it into an MBTiles file or a
// folder): a description (JSON: the cell, the measure, how many tracks, the largest count, the
// tiles' colours) and the grid's 256 x 256-cell tiles of counts (zlib-compressed little-endian
// UInt32), each named "COL/ROW" (or "COL_ROW" as a file name). Read from files anyone may hand
// over: every reader refuses bad input with std::invalid_argument saying what is wrong, never
// more (fuzz/fuzz_heatmap.cpp).

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "track/heatmap.hpp"

namespace trailray::track {

struct HeatmapDescription {
  double cell_m = 50.0;
  HeatmapMeasure measure = HeatmapMeasure::tracks;
  std::uint64_t tracks = 0;
  std::uint32_t max_count = 0;
  std::string colormap = "warm", scale = "log";  // the tiles' colours, by name (scene/pictures/heatmap_colors)
};

std::string heatmap_description_json(const HeatmapDescription& description);
// {"format": "trailray-heatmap", "version": 1, "cell_m", "of", "tracks", "max", "colormap", "scale"}.
HeatmapDescription parse_heatmap_description(std::string_view json);

std::vector<unsigned char> pack_heatmap_tile(const HeatmapCounts::Tile& tile);
HeatmapCounts::Tile unpack_heatmap_tile(std::span<const unsigned char> packed);

// "COL/ROW" or "COL_ROW" of a tile inside a grid of `tiles_per_side` tiles.
std::pair<std::int64_t, std::int64_t> parse_heatmap_tile_key(std::string_view key, std::int64_t tiles_per_side);

// The grid's tiles per side for a cell size.
std::int64_t heatmap_tiles_per_side(const HeatmapCounts& counts);

}  // namespace trailray::track
