#include "track/heatmap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "geo/web_mercator.hpp"
#include "track/flight/flight_analysis.hpp"

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

// Visits every cell the straight line from a to b crosses (Amanatides and Woo's traversal), in
// order, with the part of the line inside it: visit(col, row, t_enter, t_exit), t from 0 at a to 1
// at b.
template <typename Visit>
void visit_line(GridPoint a, GridPoint b, std::int64_t n, Visit&& visit) {
  std::int64_t col = clamp_cell(a.x, n), row = clamp_cell(a.y, n);
  const std::int64_t end_col = clamp_cell(b.x, n), end_row = clamp_cell(b.y, n);
  const double dx = b.x - a.x, dy = b.y - a.y;
  const int step_col = dx > 0 ? 1 : -1, step_row = dy > 0 ? 1 : -1;
  const double inf = std::numeric_limits<double>::infinity();
  // Parameter t along the line (0 at a, 1 at b) where it crosses the next column / row border.
  double t_col = dx == 0 ? inf : ((dx > 0 ? std::floor(a.x) + 1.0 : std::floor(a.x)) - a.x) / dx;
  double t_row = dy == 0 ? inf : ((dy > 0 ? std::floor(a.y) + 1.0 : std::floor(a.y)) - a.y) / dy;
  const double dt_col = dx == 0 ? inf : std::fabs(1.0 / dx), dt_row = dy == 0 ? inf : std::fabs(1.0 / dy);
  double t_enter = 0.0;
  // At most the cells between the ends, however the floating point rounds.
  std::int64_t left = std::llabs(end_col - col) + std::llabs(end_row - row);
  while (left-- > 0 && (col != end_col || row != end_row)) {
    const double t_exit = std::clamp(std::min(t_col, t_row), t_enter, 1.0);
    visit(col, row, t_enter, t_exit);
    t_enter = t_exit;
    if (t_col < t_row) {
      col += step_col;
      t_col += dt_col;
    } else {
      row += step_row;
      t_row += dt_row;
    }
    col = std::clamp<std::int64_t>(col, 0, n - 1);
    row = std::clamp<std::int64_t>(row, 0, n - 1);
  }
  visit(col, row, t_enter, 1.0);
}

std::uint64_t key_of(std::int64_t col, std::int64_t row) {
  return (static_cast<std::uint64_t>(col) << 32) | static_cast<std::uint64_t>(row);
}

HeatmapCell cell_of(std::uint64_t key) {
  return {static_cast<std::int64_t>(key >> 32), static_cast<std::int64_t>(key & 0xffffffffu)};
}

// The steps of a run of points (one segment, or a thermal's part of one): visit(a, b, grid a,
// grid b, joined) for each pair of consecutive valid points, joined false where the step is a gap
// (over 10 km on the ground, or across the antimeridian: where the track went is unknown), and
// visit(p, p, g, g, true) for a run's first point.
template <typename Visit>
void visit_steps(const TrackPoint* begin, const TrackPoint* end, double cell, Visit&& visit) {
  const TrackPoint* last = nullptr;
  GridPoint last_grid;
  for (const TrackPoint* p = begin; p != end; ++p) {
    if (!valid(*p)) continue;
    const GridPoint g = grid_point(*p, cell);
    if (last == nullptr) {
      visit(*p, *p, g, g, true);
    } else {
      // The ground length of the step, from the Mercator one and the scale at its middle.
      const double mx = (g.x - last_grid.x) * cell, my = (g.y - last_grid.y) * cell;
      const double ground = std::hypot(mx, my) / geo::mercator_scale_factor(0.5 * (p->lat + last->lat));
      // Across the antimeridian the short way round is off the grid's square: ends only.
      const bool joined = ground <= kGapGroundM && std::fabs(p->lon - last->lon) <= 180.0;
      visit(*last, *p, last_grid, g, joined);
    }
    last = p;
    last_grid = g;
  }
}

// The cells a run of points passes through (a gap step: its end only), appended as keys.
void append_run_cells(const TrackPoint* begin, const TrackPoint* end, double cell, std::int64_t n,
                      std::vector<std::uint64_t>& keys) {
  const auto add = [&](std::int64_t col, std::int64_t row, double, double) { keys.push_back(key_of(col, row)); };
  visit_steps(begin, end, cell, [&](const TrackPoint&, const TrackPoint&, GridPoint a, GridPoint b, bool joined) {
    visit_line(joined ? a : b, b, n, add);
  });
}

// Sorted unique keys -> cells counted once.
std::vector<HeatmapCellCount> once_each(std::vector<std::uint64_t>& keys) {
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  std::vector<HeatmapCellCount> out;
  out.reserve(keys.size());
  for (std::uint64_t k : keys) out.push_back({cell_of(k), 1});
  return out;
}

}  // namespace

std::string_view heatmap_measure_name(HeatmapMeasure measure) {
  switch (measure) {
    case HeatmapMeasure::tracks: return "tracks";
    case HeatmapMeasure::thermals: return "thermals";
    case HeatmapMeasure::time: return "time";
  }
  return "tracks";
}

std::optional<HeatmapMeasure> parse_heatmap_measure(std::string_view name) {
  for (HeatmapMeasure m : {HeatmapMeasure::tracks, HeatmapMeasure::thermals, HeatmapMeasure::time})
    if (name == heatmap_measure_name(m)) return m;
  return std::nullopt;
}

HeatmapCounts::HeatmapCounts(double cell_m, HeatmapMeasure measure) : cell_m_(cell_m), measure_(measure) {
  if (!(cell_m >= 1.0 && cell_m <= 100000.0))
    throw std::invalid_argument("heatmap cell " + std::to_string(cell_m) + " m is not in 1..100000");
  cells_per_side_ = static_cast<std::int64_t>(std::ceil(2.0 * kH / cell_m));
}

std::vector<HeatmapCell> HeatmapCounts::track_cells(const Track& track) const {
  std::vector<std::uint64_t> keys;
  for (const Segment& s : track.segments)
    append_run_cells(s.points.data(), s.points.data() + s.points.size(), cell_m_, cells_per_side_, keys);
  std::vector<HeatmapCell> cells;
  for (const HeatmapCellCount& c : once_each(keys)) cells.push_back(c.cell);
  return cells;
}

namespace {

// Each flight's thermals, entry to exit, along the segments they lie in: once per flight and cell.
std::vector<HeatmapCellCount> thermal_counts(const Track& track, double cell, std::int64_t n) {
  const flight::FlightAnalysis analysis = flight::analyse_flights(track);
  std::map<std::uint64_t, std::uint32_t> counts;
  for (const flight::Flight& f : analysis.flights) {
    std::vector<std::uint64_t> keys;
    for (const flight::Thermal& th : f.thermals) {
      // Place::point counts across segments: walk each segment's part of [start, end].
      std::size_t first = 0;
      for (const Segment& s : track.segments) {
        const std::size_t from = std::max(th.start.point, first), to = std::min(th.end.point + 1, first + s.points.size());
        if (from < to) append_run_cells(s.points.data() + (from - first), s.points.data() + (to - first), cell, n, keys);
        first += s.points.size();
      }
    }
    for (const HeatmapCellCount& c : once_each(keys)) ++counts[key_of(c.cell.col, c.cell.row)];
  }
  std::vector<HeatmapCellCount> out;
  for (const auto& [key, count] : counts) out.push_back({cell_of(key), count});
  return out;
}

// Each step's seconds shared among its cells by length; whole seconds per cell.
std::vector<HeatmapCellCount> time_counts(const Track& track, double cell, std::int64_t n) {
  std::map<std::uint64_t, double> seconds;
  for (const Segment& s : track.segments)
    visit_steps(s.points.data(), s.points.data() + s.points.size(), cell,
                [&](const TrackPoint& p, const TrackPoint& q, GridPoint a, GridPoint b, bool joined) {
                  const double dt = q.time - p.time;
                  if (!joined || !(dt > 0.0)) return;  // no time, a gap, or time going back
                  visit_line(a, b, n, [&](std::int64_t col, std::int64_t row, double t0, double t1) {
                    seconds[key_of(col, row)] += dt * (t1 - t0);
                  });
                });
  std::vector<HeatmapCellCount> out;
  for (const auto& [key, s] : seconds) {
    const double rounded = std::round(s);
    if (rounded >= 1.0)
      out.push_back({cell_of(key), static_cast<std::uint32_t>(std::min(rounded, 4294967295.0))});
  }
  return out;
}

}  // namespace

std::vector<HeatmapCellCount> HeatmapCounts::track_counts(const Track& track) const {
  switch (measure_) {
    case HeatmapMeasure::thermals: return thermal_counts(track, cell_m_, cells_per_side_);
    case HeatmapMeasure::time: return time_counts(track, cell_m_, cells_per_side_);
    case HeatmapMeasure::tracks: break;
  }
  std::vector<HeatmapCellCount> out;
  for (const HeatmapCell& c : track_cells(track)) out.push_back({c, 1});
  return out;
}

void HeatmapCounts::add_track(const Track& track) { add_counts(track_counts(track)); }

void HeatmapCounts::add_counts(const std::vector<HeatmapCellCount>& counts) {
  for (const HeatmapCellCount& c : counts) {
    // operator[] value-initialises a new tile: all zeros.
    Tile& tile = tiles_[{c.cell.col / kHeatmapTileCells, c.cell.row / kHeatmapTileCells}];
    std::uint32_t& v = tile[static_cast<std::size_t>((c.cell.row % kHeatmapTileCells) * kHeatmapTileCells +
                                                     c.cell.col % kHeatmapTileCells)];
    v = v > UINT32_MAX - c.count ? UINT32_MAX : v + c.count;  // saturates rather than wraps
  }
  ++tracks_;
}

void HeatmapCounts::add_tile(std::int64_t tile_col, std::int64_t tile_row, const Tile& counts) {
  Tile& tile = tiles_[{tile_col, tile_row}];
  for (std::size_t i = 0; i < counts.size(); ++i)
    tile[i] = tile[i] > UINT32_MAX - counts[i] ? UINT32_MAX : tile[i] + counts[i];
}

void HeatmapCounts::merge(const HeatmapCounts& other) {
  if (other.cell_m_ != cell_m_) throw std::invalid_argument("heatmaps of different cell sizes do not add up");
  if (other.measure_ != measure_)
    throw std::invalid_argument("a heatmap of " + std::string(heatmap_measure_name(other.measure_)) +
                                " does not add to one of " + std::string(heatmap_measure_name(measure_)));
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

HeatmapCounts HeatmapCounts::cropped(const HeatmapWindow& w) const {
  HeatmapCounts out(cell_m_, measure_);
  out.tracks_ = tracks_;
  for (const auto& [key, counts] : tiles_) {
    const std::int64_t c0 = key.first * kHeatmapTileCells, r0 = key.second * kHeatmapTileCells;
    if (c0 >= w.col1 || r0 >= w.row1 || c0 + kHeatmapTileCells <= w.col0 || r0 + kHeatmapTileCells <= w.row0) continue;
    Tile kept{};
    bool any = false;
    for (std::int64_t r = std::max(r0, w.row0); r < std::min(r0 + kHeatmapTileCells, w.row1); ++r)
      for (std::int64_t c = std::max(c0, w.col0); c < std::min(c0 + kHeatmapTileCells, w.col1); ++c) {
        const auto i = static_cast<std::size_t>((r - r0) * kHeatmapTileCells + (c - c0));
        kept[i] = counts[i];
        any = any || counts[i] != 0;
      }
    if (any) out.tiles_.emplace(key, kept);
  }
  return out;
}

std::array<double, 6> HeatmapCounts::geotransform(const HeatmapWindow& w) const {
  return {-kH + static_cast<double>(w.col0) * cell_m_, cell_m_, 0.0, kH - static_cast<double>(w.row0) * cell_m_,
          0.0, -cell_m_};
}

}  // namespace trailray::track
