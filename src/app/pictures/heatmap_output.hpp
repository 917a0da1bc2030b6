#pragma once
// Where a heatmap goes and comes back from (`trailray heatmap -o`, trailray.Heatmap.write):
//   X.tif     - the counts: one band, UInt32, EPSG:3857, a window of the grid (terrain/writers/count_geotiff);
//   X.mbtiles - coloured XYZ tiles (PNG with alpha, zoom levels of the caller's choice), and the
//   folder/     counts themselves beside them, exactly, so partial heatmaps merge without loss:
//               MBTiles: the table `trailray_counts` (key "COL/ROW" of the grid's 256-cell tiles,
//               data the 65,536 counts as zlib-compressed little-endian UInt32) and the metadata
//               key `trailray_heatmap` (JSON: cell, measure, tracks, the largest count, colours);
//               folder: {z}/{x}/{y}.png, metadata.json (the same key) and counts/COL_ROW.u32.zlib.
// The tile outputs are also what --overlay reads, and what `trailray heatmap` takes as inputs to
// add to (is_heatmap_tiles, read_heatmap_counts).

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "scene/pictures/heatmap_colors.hpp"
#include "track/heatmap.hpp"
#include "track/heatmap_exchange.hpp"

namespace trailray::app {

enum class HeatmapOutputKind { geotiff, mbtiles, folder };

// From the name: .tif/.tiff, .mbtiles, or a folder (a name ending in '/' or an existing folder).
// Throws std::invalid_argument naming `path` for anything else.
HeatmapOutputKind heatmap_output_kind(const std::string& path);

struct HeatmapTileOptions {
  int min_zoom = 0;
  std::optional<int> max_zoom;  // default: the cell's native zoom (track::heatmap_native_zoom)
  scene::HeatmapPalette palette;  // its max_count is set from the counts
};

struct HeatmapWritten {
  std::size_t tiles = 0;      // coloured tiles written (tile outputs)
  int min_zoom = 0, max_zoom = 0;
  std::uint32_t max_count = 0;
};

// Writes the counts' tiles to `path` (mbtiles or folder): atomically (a temporary file or folder
// renamed into place; an existing one is replaced only when `force`). `progress(zoom)` is called
// as each zoom level starts. Throws std::runtime_error naming `path`.
HeatmapWritten write_heatmap_tiles(const track::HeatmapCounts& counts, const std::string& path,
                                   HeatmapOutputKind kind, HeatmapTileOptions options, bool force,
                                   const std::function<void(int)>& progress = {});

// An .mbtiles file or a folder that a heatmap was written to (it carries the counts).
bool is_heatmap_tiles(const std::string& path);

// The counts a heatmap tile output carries. Throws std::runtime_error naming `path` and what is
// wrong (not a heatmap, a damaged counts tile).
track::HeatmapCounts read_heatmap_counts(const std::string& path);

// What a heatmap's tile output says of itself (for the legend of --overlay): nullopt when `path`
// is not one; std::runtime_error naming it when its description is damaged.
std::optional<track::HeatmapDescription> describe_heatmap_tiles(const std::string& path);

// The legend's words for a measure: "Tracks", "Thermal flights", "Seconds".
std::string heatmap_measure_title(track::HeatmapMeasure measure);

}  // namespace trailray::app
