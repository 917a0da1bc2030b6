#pragma once
// Heatmaps of many tracks: for each cell of a Web Mercator grid, how many tracks passed through it
// (`trailray heatmap`, trailray.heatmap in Python), or what else is counted there (HeatmapMeasure:
// flights that climbed in a thermal there, seconds spent there). A track counts once per cell whatever its
// points; the line between two consecutive points counts for every cell it crosses (a track
// sampled every 100 m still fills the 50 m cells between its fixes). A step longer than 10 km on
// the ground is a gap (where the track went in between is unknown): its two ends count, not the
// cells between. Segments are never joined.
//
// The grid is global and fixed by the cell size alone: cell (col, row) spans Mercator x from
// -H + col * cell to -H + (col + 1) * cell and y from H - (row + 1) * cell to H - row * cell
// (H = geo::kMercatorHalfExtentM; rows from the north, as rasters are), so counts made on different
// machines from different files add up cell for cell. The cell is in Mercator metres: "50 m" is
// 50 m on the equator and 34 m on the ground at 47 N, as web maps' pixels are.
//
// Counts are kept sparse, in tiles of 256 x 256 cells made when a track first reaches them, so
// memory follows the area covered, not the number of tracks.

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string_view>
#include <vector>

#include "track/model.hpp"

namespace trailray::track {

inline constexpr int kHeatmapTileCells = 256;

// What a cell counts (`--of`):
//   tracks   - tracks that passed through it (once per track);
//   thermals - flights that climbed in a thermal there (the thermals `trailray flight` finds, from
//              entry to exit; once per flight);
//   time     - seconds spent there: each step's time shared among the cells its line crosses in
//              proportion to the length in each, rounded to whole seconds per track and cell (a gap
//              step, over 10 km, and steps without times count nothing).
enum class HeatmapMeasure { tracks, thermals, time };
std::string_view heatmap_measure_name(HeatmapMeasure measure);                 // "tracks", "thermals", "time"
std::optional<HeatmapMeasure> parse_heatmap_measure(std::string_view name);  // exact names

struct HeatmapCell {
  std::int64_t col = 0, row = 0;
  bool operator==(const HeatmapCell&) const = default;
};

struct HeatmapCellCount {
  HeatmapCell cell;
  std::uint32_t count = 0;
};

// A rectangle of cells: columns [col0, col1), rows [row0, row1).
struct HeatmapWindow {
  std::int64_t col0 = 0, row0 = 0, col1 = 0, row1 = 0;
  std::int64_t width() const { return col1 - col0; }
  std::int64_t height() const { return row1 - row0; }
  bool empty() const { return width() <= 0 || height() <= 0; }
};

class HeatmapCounts {
 public:
  using Tile = std::array<std::uint32_t, kHeatmapTileCells * kHeatmapTileCells>;

  // Throws std::invalid_argument unless 1 <= cell_m <= 100000.
  explicit HeatmapCounts(double cell_m = 50.0, HeatmapMeasure measure = HeatmapMeasure::tracks);

  double cell_m() const { return cell_m_; }
  HeatmapMeasure measure() const { return measure_; }
  // The grid's cells per side (the world's square).
  std::int64_t cells_per_side() const { return cells_per_side_; }

  // Adds one track: what track_counts gives.
  void add_track(const Track& track);
  // The same from its counts (track_counts, worked out elsewhere: another thread); counts a track.
  void add_counts(const std::vector<HeatmapCellCount>& counts);
  // What one track adds to each cell by the measure, sorted by cell, no zeros.
  std::vector<HeatmapCellCount> track_counts(const Track& track) const;
  // The cells a track passes through, each once, sorted (what the tracks measure counts).
  std::vector<HeatmapCell> track_cells(const Track& track) const;

  // Adds `other` cell for cell (the same cell size and measure, else std::invalid_argument).
  void merge(const HeatmapCounts& other);

  std::uint32_t at(HeatmapCell cell) const;
  std::uint64_t tracks() const { return tracks_; }
  // The smallest window holding every non-zero cell (empty when nothing was counted).
  HeatmapWindow extent() const;
  // The window of cells covering a lat/lon box (degrees), clamped to the world.
  HeatmapWindow window_of(double min_lat, double min_lon, double max_lat, double max_lon) const;
  // The counts of a window, row by row from the north-west corner.
  std::vector<std::uint32_t> raster(const HeatmapWindow& window) const;
  // The window's geotransform in EPSG:3857 (GDAL's order: x0, dx, 0, y0, 0, -dy).
  std::array<double, 6> geotransform(const HeatmapWindow& window) const;

  // Only the cells inside `window` (a --bbox): the same grid, the rest dropped.
  HeatmapCounts cropped(const HeatmapWindow& window) const;

  // The tiles, for handing counts between processes: (tile column, tile row) -> counts.
  const std::map<std::pair<std::int64_t, std::int64_t>, Tile>& tiles() const { return tiles_; }
  void add_tile(std::int64_t tile_col, std::int64_t tile_row, const Tile& counts);
  void set_tracks(std::uint64_t n) { tracks_ = n; }

 private:
  double cell_m_;
  HeatmapMeasure measure_;
  std::int64_t cells_per_side_;
  std::map<std::pair<std::int64_t, std::int64_t>, Tile> tiles_;
  std::uint64_t tracks_ = 0;
};

}  // namespace trailray::track
