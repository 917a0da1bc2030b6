#include "track/heatmap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "geo/web_mercator.hpp"

namespace trailray::track {
namespace {

constexpr double kH = geo::kMercatorHalfExtentM;
constexpr double kGapGroundM = 10000.0;  // a longer step is a gap: its ends count, not between

bool valid(const TrackPoint& p) {
  return std::isfinite(p.lat) && std::isfinite(p.lon) && p.lat >= -90.0 && p.lat <= 90.0 && p.lon >= -180.0 &&
         p.lon <= 180.0;
}

// Grid coordinates: cell units from the world's north-west corner (x east, y south).
struct GridPoint {
  double x = 0.0, y = 0.0;
};

GridPoint grid_point(const TrackPoint& p, double cell) {
  const geo::MercatorPoint m = geo::mercator_from_latlon(p.lat, p.lon);
  return {(m.x + kH) / cell, (kH - m.y) / cell};
}

std::int64_t clamp_cell(double v, std::int64_t n) {
  const auto c = static_cast<std::int64_t>(std::floor(v));
  return std::clamp<std::int64_t>(c, 0, n - 1);
}

// Every cell the straight line from a to b crosses (Amanatides and Woo's traversal), appended.
void cells_on_line(GridPoint a, GridPoint b, std::int64_t n, std::vector<std::uint64_t>& out) {
  std::int64_t col = clamp_cell(a.x, n), row = clamp_cell(a.y, n);
  const std::int64_t end_col = clamp_cell(b.x, n), end_row = clamp_cell(b.y, n);
  const double dx = b.x - a.x, dy = b.y - a.y;
  const int step_col = dx > 0 ? 1 : -1, step_row = dy > 0 ? 1 : -1;
  const double inf = std::numeric_limits<double>::infinity();
  // Parameter t along the line (0 at a, 1 at b) where it crosses the next column / row border.
  double t_col = dx == 0 ? inf : ((dx > 0 ? std::floor(a.x) + 1.0 : std::floor(a.x)) - a.x) / dx;
  double t_row = dy == 0 ? inf : ((dy > 0 ? std::floor(a.y) + 1.0 : std::floor(a.y)) - a.y) / dy;
  const double dt_col = dx == 0 ? inf : std::fabs(1.0 / dx), dt_row = dy == 0 ? inf : std::fabs(1.0 / dy);
  out.push_back((static_cast<std::uint64_t>(col) << 32) | static_cast<std::uint64_t>(row));
  // At most the cells between the ends, however the floating point rounds.
  std::int64_t left = std::llabs(end_col - col) + std::llabs(end_row - row);
  while (left-- > 0 && (col != end_col || row != end_row)) {
    if (t_col < t_row) {
      col += step_col;
      t_col += dt_col;
    } else {
      row += step_row;
      t_row += dt_row;
    }
    col = std::clamp<std::int64_t>(col, 0, n - 1);
    row = std::clamp<std::int64_t>(row, 0, n - 1);
    out.push_back((static_cast<std::uint64_t>(col) << 32) | static_cast<std::uint64_t>(row));
  }
}

}  // namespace

HeatmapCounts::HeatmapCounts(double cell_m) : cell_m_(cell_m) {
  if (!(cell_m >= 1.0 && cell_m <= 100000.0))
    throw std::invalid_argument("heatmap cell " + std::to_string(cell_m) + " m is not in 1..100000");
  cells_per_side_ = static_cast<std::int64_t>(std::ceil(2.0 * kH / cell_m));
}

std::vector<HeatmapCell> HeatmapCounts::track_cells(const Track& track) const {
  std::vector<std::uint64_t> keys;
  for (const Segment& s : track.segments) {
    const TrackPoint* last = nullptr;
    GridPoint last_grid;
    for (const TrackPoint& p : s.points) {
      if (!valid(p)) continue;
      const GridPoint g = grid_point(p, cell_m_);
      if (last == nullptr) {
        cells_on_line(g, g, cells_per_side_, keys);
      } else {
        // The ground length of the step, from the Mercator one and the scale at its middle.
        const double mx = (g.x - last_grid.x) * cell_m_, my = (g.y - last_grid.y) * cell_m_;
        const double ground = std::hypot(mx, my) / geo::mercator_scale_factor(0.5 * (p.lat + last->lat));
        // Across the antimeridian the short way round is off the grid's square: ends only.
        if (ground > kGapGroundM || std::fabs(p.lon - last->lon) > 180.0)
          cells_on_line(g, g, cells_per_side_, keys);
        else
          cells_on_line(last_grid, g, cells_per_side_, keys);
      }
      last = &p;
      last_grid = g;
    }
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  std::vector<HeatmapCell> cells;
  cells.reserve(keys.size());
  for (std::uint64_t k : keys)
    cells.push_back({static_cast<std::int64_t>(k >> 32), static_cast<std::int64_t>(k & 0xffffffffu)});
  return cells;
}

void HeatmapCounts::add_track(const Track& track) { add_cells(track_cells(track)); }

void HeatmapCounts::add_cells(const std::vector<HeatmapCell>& cells) {
  for (const HeatmapCell& c : cells) {
    // operator[] value-initialises a new tile: all zeros.
    Tile& tile = tiles_[{c.col / kHeatmapTileCells, c.row / kHeatmapTileCells}];
    ++tile[static_cast<std::size_t>((c.row % kHeatmapTileCells) * kHeatmapTileCells + c.col % kHeatmapTileCells)];
  }
  ++tracks_;
}

void HeatmapCounts::add_tile(std::int64_t tile_col, std::int64_t tile_row, const Tile& counts) {
  Tile& tile = tiles_[{tile_col, tile_row}];
  for (std::size_t i = 0; i < counts.size(); ++i) tile[i] += counts[i];
}

void HeatmapCounts::merge(const HeatmapCounts& other) {
  if (other.cell_m_ != cell_m_) throw std::invalid_argument("heatmaps of different cell sizes do not add up");
  for (const auto& [key, counts] : other.tiles_) add_tile(key.first, key.second, counts);
  tracks_ += other.tracks_;
}

std::uint32_t HeatmapCounts::at(HeatmapCell c) const {
  if (c.col < 0 || c.row < 0) return 0;
  auto it = tiles_.find({c.col / kHeatmapTileCells, c.row / kHeatmapTileCells});
  if (it == tiles_.end()) return 0;
  return it->second[static_cast<std::size_t>((c.row % kHeatmapTileCells) * kHeatmapTileCells +
                                             c.col % kHeatmapTileCells)];
}

HeatmapWindow HeatmapCounts::extent() const {
  HeatmapWindow w{std::numeric_limits<std::int64_t>::max(), std::numeric_limits<std::int64_t>::max(), 0, 0};
  bool any = false;
  for (const auto& [key, counts] : tiles_)
    for (int r = 0; r < kHeatmapTileCells; ++r)
      for (int c = 0; c < kHeatmapTileCells; ++c) {
        if (counts[static_cast<std::size_t>(r * kHeatmapTileCells + c)] == 0) continue;
        const std::int64_t col = key.first * kHeatmapTileCells + c, row = key.second * kHeatmapTileCells + r;
        w.col0 = std::min(w.col0, col);
        w.row0 = std::min(w.row0, row);
        w.col1 = std::max(w.col1, col + 1);
        w.row1 = std::max(w.row1, row + 1);
        any = true;
      }
  return any ? w : HeatmapWindow{};
}

HeatmapWindow HeatmapCounts::window_of(double min_lat, double min_lon, double max_lat, double max_lon) const {
  const geo::MercatorPoint sw = geo::mercator_from_latlon(min_lat, min_lon);
  const geo::MercatorPoint ne = geo::mercator_from_latlon(max_lat, max_lon);
  const auto n = cells_per_side_;
  return {clamp_cell((sw.x + kH) / cell_m_, n), clamp_cell((kH - ne.y) / cell_m_, n),
          clamp_cell((ne.x + kH) / cell_m_, n) + 1, clamp_cell((kH - sw.y) / cell_m_, n) + 1};
}

std::vector<std::uint32_t> HeatmapCounts::raster(const HeatmapWindow& w) const {
  std::vector<std::uint32_t> out(static_cast<std::size_t>(std::max<std::int64_t>(w.width(), 0) *
                                                          std::max<std::int64_t>(w.height(), 0)),
                                 0);
  for (const auto& [key, counts] : tiles_) {
    const std::int64_t c0 = key.first * kHeatmapTileCells, r0 = key.second * kHeatmapTileCells;
    if (c0 >= w.col1 || r0 >= w.row1 || c0 + kHeatmapTileCells <= w.col0 || r0 + kHeatmapTileCells <= w.row0) continue;
    for (std::int64_t r = std::max(r0, w.row0); r < std::min(r0 + kHeatmapTileCells, w.row1); ++r)
      for (std::int64_t c = std::max(c0, w.col0); c < std::min(c0 + kHeatmapTileCells, w.col1); ++c)
        out[static_cast<std::size_t>((r - w.row0) * w.width() + (c - w.col0))] =
            counts[static_cast<std::size_t>((r - r0) * kHeatmapTileCells + (c - c0))];
  }
  return out;
}

std::array<double, 6> HeatmapCounts::geotransform(const HeatmapWindow& w) const {
  return {-kH + static_cast<double>(w.col0) * cell_m_, cell_m_, 0.0, kH - static_cast<double>(w.row0) * cell_m_,
          0.0, -cell_m_};
}

}  // namespace trailray::track
