#include "track/density.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "geo/wgs84.hpp"

namespace trailray::track {
namespace {

constexpr std::uint32_t kNoCell = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint64_t kNoKey = std::numeric_limits<std::uint64_t>::max();
// Cell coordinates are offset by 2^20 and packed in 21 bits each: with cells of at least 8 m,
// the Earth's +-6,378 km take +-797,000 cells, inside +-2^20.
constexpr std::int64_t kCellBias = std::int64_t{1} << 20;
constexpr std::int64_t kMinCellCm = 800;
constexpr std::int64_t kMinGapCm = 1000000;  // 10 km
constexpr std::uint32_t kMaxRunSegments = 16;

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  std::int64_t q = a / b;
  if (a % b != 0 && (a < 0) != (b < 0)) --q;
  return q;
}

std::uint64_t pack(std::int64_t cx, std::int64_t cy, std::int64_t cz) {
  return (static_cast<std::uint64_t>(cx + kCellBias) << 42) | (static_cast<std::uint64_t>(cy + kCellBias) << 21) |
         static_cast<std::uint64_t>(cz + kCellBias);
}

std::array<std::int64_t, 3> unpack(std::uint64_t key) {
  constexpr std::uint64_t mask = (std::uint64_t{1} << 21) - 1;
  return {static_cast<std::int64_t>((key >> 42) & mask) - kCellBias,
          static_cast<std::int64_t>((key >> 21) & mask) - kCellBias, static_cast<std::int64_t>(key & mask) - kCellBias};
}

std::uint64_t mix(std::uint64_t x) {  // splitmix64's finaliser: spreads neighbouring cells over the table
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

template <typename Job>
void run_all(std::size_t count, const ParallelFor& parallel, const Job& job) {
  if (parallel && count > 1) {
    parallel(count, job);
    return;
  }
  for (std::size_t i = 0; i < count; ++i) job(i);
}

}  // namespace

// What a point's neighbourhood holds, gathered once for the consecutive points in one cell. Per
// source bounds on the distance to its gathered segments from where they were last measured (the
// anchor): as the points move on, the distance changes by at most the way travelled since (the
// triangle inequality), so a source well inside or well outside the radius is decided without
// measuring it again. The bounds come cheap from the runs (their boxes below, their first points
// above); only a source they leave on both sides of the radius is measured segment by segment.
struct NeighbourIndex::Scratch {
  std::uint64_t key = kNoKey;              // the cell gathered for
  std::vector<std::uint32_t> runs;         // the runs of the 27 cells around it, grouped by source
  std::vector<std::uint32_t> group_end;    // where each source's group ends in `runs`
  std::vector<double> lower_cm, upper_cm;  // per group: bounds on the distance at its anchor
  std::vector<double> anchor_way_cm;       // per group: `way_cm` when they were measured (-inf: never)
  double way_cm = 0.0;                     // the way travelled since the gathering
  bool has_previous = false;
  Cm previous;  // the last point counted
  // Grouping by source without sorting: each source's group in this gathering (by stamp).
  std::vector<std::uint32_t> source_stamp, source_group;
  std::uint32_t stamp = 0;
  std::vector<std::uint32_t> group_size;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> cells;  // [begin, end) of runs per cell
};

namespace {

// The place of a point on the ellipsoid (height 0) in whole centimetres; nullopt without a valid
// position.
template <typename Cm>
std::optional<Cm> surface_cm(double lat, double lon) {
  if (!std::isfinite(lat) || !std::isfinite(lon) || std::abs(lat) > 90.0) return std::nullopt;
  const glm::dvec3 e = geo::ecef_from_geodetic(lat, lon, 0.0);
  return Cm{static_cast<std::int32_t>(std::llround(e.x * 100.0)), static_cast<std::int32_t>(std::llround(e.y * 100.0)),
            static_cast<std::int32_t>(std::llround(e.z * 100.0))};
}

template <typename Cm>
double distance_cm(const Cm& a, const Cm& b) {
  const double dx = static_cast<double>(b.x) - a.x, dy = static_cast<double>(b.y) - a.y,
               dz = static_cast<double>(b.z) - a.z;
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// Squared distance from p to the segment a-b (a == b: the point), all in centimetres.
template <typename Cm>
double segment_distance2(const Cm& p, const Cm& a, const Cm& b) {
  const double ax = static_cast<double>(a.x) - p.x, ay = static_cast<double>(a.y) - p.y,
               az = static_cast<double>(a.z) - p.z;
  const double dx = static_cast<double>(b.x) - a.x, dy = static_cast<double>(b.y) - a.y,
               dz = static_cast<double>(b.z) - a.z;
  const double length2 = dx * dx + dy * dy + dz * dz;
  double t = 0.0;
  if (length2 > 0.0) t = std::clamp(-(ax * dx + ay * dy + az * dz) / length2, 0.0, 1.0);
  const double cx = ax + t * dx, cy = ay + t * dy, cz = az + t * dz;
  return cx * cx + cy * cy + cz * cz;
}

// Squared distance from p to a box (0 inside).
template <typename Cm>
double box_distance2(const Cm& p, const Cm& lo, const Cm& hi) {
  const auto axis = [](std::int32_t v, std::int32_t l, std::int32_t h) {
    const double d = v < l ? static_cast<double>(l) - v : v > h ? static_cast<double>(v) - h : 0.0;
    return d * d;
  };
  return axis(p.x, lo.x, hi.x) + axis(p.y, lo.y, hi.y) + axis(p.z, lo.z, hi.z);
}

template <typename Cm>
void grow(Cm& lo, Cm& hi, const Cm& p) {
  lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
  hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
}

}  // namespace

NeighbourIndex::NeighbourIndex(std::span<const NeighbourSource> sources, double radius_m, const ParallelFor& parallel)
    : radius_m_(radius_m), source_count_(sources.size()) {
  if (!(radius_m >= kMinNeighbourRadiusM && radius_m <= kMaxNeighbourRadiusM))
    throw std::invalid_argument("neighbour radius " + std::to_string(radius_m) + " m is not within " +
                                std::to_string(kMinNeighbourRadiusM) + " to " + std::to_string(kMaxNeighbourRadiusM) +
                                " m");
  if (sources.size() > kNoCell) throw std::length_error("more than 2^32 neighbour sources");
  radius_cm_ = radius_m * 100.0;
  // Strictly over the radius (in whole cm), so a point and anything within r of it are never more
  // than one cell apart on any axis.
  cell_cm_ = std::max(static_cast<std::int64_t>(std::ceil(radius_cm_)) + 1, kMinCellCm);
  max_step_cm_ = std::max(kMinGapCm, static_cast<std::int64_t>(std::ceil(10.0 * radius_cm_)));

  // Each source's valid points into its own slice of points_ (an invalid point leaves its slot
  // unused and ends its line), split into lines at gaps.
  std::vector<std::size_t> offset(sources.size() + 1, 0);
  for (std::size_t s = 0; s < sources.size(); ++s) {
    std::size_t n = 0;
    for (const PointLine& line : sources[s].lines) n += line.size();
    offset[s + 1] = offset[s] + n;
  }
  if (offset.back() >= kNoCell) throw std::length_error("more than 2^32 points to count neighbours of");
  points_.resize(offset.back());
  std::vector<std::vector<Line>> lines(sources.size());
  std::vector<std::vector<Run>> runs(sources.size());
  run_all(sources.size(), parallel, [&](std::size_t s) {
    auto next = static_cast<std::uint32_t>(offset[s]);
    std::vector<Line>& out = lines[s];
    for (const PointLine& line : sources[s].lines) {
      bool open = false;
      for (const TrackPoint& p : line) {
        const auto cm = surface_cm<Cm>(p.lat, p.lon);
        if (!cm) {
          open = false;
          continue;
        }
        if (open && distance_cm(points_[next - 1], *cm) > static_cast<double>(max_step_cm_)) open = false;
        if (!open) out.push_back({next, 0});
        open = true;
        points_[next++] = *cm;
        ++out.back().count;
      }
    }
    add_source_runs(out, static_cast<std::uint32_t>(s), runs[s]);
  });

  std::size_t total = 0;
  for (const auto& r : runs) total += r.size();
  if (total >= kNoCell) throw std::length_error("more than 2^32 neighbour runs");
  runs_.reserve(total);
  for (auto& r : runs) {
    runs_.insert(runs_.end(), r.begin(), r.end());
    std::vector<Run>().swap(r);
  }
  std::sort(runs_.begin(), runs_.end(), [](const Run& a, const Run& b) {
    if (a.cell != b.cell) return a.cell < b.cell;
    if (a.source != b.source) return a.source < b.source;
    return a.first < b.first;
  });
  build_table();
}

void NeighbourIndex::add_source_runs(const std::vector<Line>& lines, std::uint32_t source,
                                     std::vector<Run>& out) const {
  const auto cell_of = [this](std::int64_t v) { return floor_div(v, cell_cm_); };
  // The cells of the previous piece of line, each with its run: a line still in them extends the run.
  std::vector<std::pair<std::uint64_t, std::size_t>> previous, current;
  for (const Line& line : lines) {
    if (line.count == 1) {
      const Cm& p = points_[line.first];
      out.push_back({pack(cell_of(p.x), cell_of(p.y), cell_of(p.z)), source, line.first, line.first, p, p});
      continue;
    }
    previous.clear();
    for (std::uint32_t i = line.first; i + 1 < line.first + line.count; ++i) {
      const Cm& a = points_[i];
      const Cm& b = points_[i + 1];
      // Pieces no longer than a cell, so each piece's box spans at most 2 cells on an axis.
      const double length = distance_cm(a, b);
      const auto pieces =
          std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(length / static_cast<double>(cell_cm_))));
      const std::array<double, 3> from{static_cast<double>(a.x), static_cast<double>(a.y), static_cast<double>(a.z)};
      const std::array<double, 3> to{static_cast<double>(b.x), static_cast<double>(b.y), static_cast<double>(b.z)};
      for (std::int64_t k = 0; k < pieces; ++k) {
        const double f0 = static_cast<double>(k) / static_cast<double>(pieces);
        const double f1 = static_cast<double>(k + 1) / static_cast<double>(pieces);
        std::array<std::int64_t, 3> lo{}, hi{};
        for (int axis = 0; axis < 3; ++axis) {
          const double u = from[axis] + (to[axis] - from[axis]) * f0;
          const double v = from[axis] + (to[axis] - from[axis]) * f1;
          lo[axis] = cell_of(static_cast<std::int64_t>(std::floor(std::min(u, v))));
          hi[axis] = cell_of(static_cast<std::int64_t>(std::ceil(std::max(u, v))));
        }
        current.clear();
        for (std::int64_t cx = lo[0]; cx <= hi[0]; ++cx)
          for (std::int64_t cy = lo[1]; cy <= hi[1]; ++cy)
            for (std::int64_t cz = lo[2]; cz <= hi[2]; ++cz) {
              const std::uint64_t key = pack(cx, cy, cz);
              const auto found = std::find_if(previous.begin(), previous.end(),
                                              [key](const auto& entry) { return entry.first == key; });
              std::size_t run = 0;
              // A run of at most kMaxRunSegments: its box stays tight enough to rule it out whole.
              if (found != previous.end() && out[found->second].last - out[found->second].first < kMaxRunSegments) {
                run = found->second;
                out[run].last = i + 1;
                grow(out[run].lo, out[run].hi, b);
              } else {
                run = out.size();
                Run r{key, source, i, i + 1, a, a};
                grow(r.lo, r.hi, b);
                out.push_back(r);
              }
              current.emplace_back(key, run);
            }
        previous.swap(current);
      }
    }
  }
}

void NeighbourIndex::build_table() {
  cell_begin_.clear();
  std::vector<std::uint64_t> keys;
  for (std::size_t i = 0; i < runs_.size(); ++i) {
    if (i == 0 || runs_[i].cell != runs_[i - 1].cell) {
      cell_begin_.push_back(static_cast<std::uint32_t>(i));
      keys.push_back(runs_[i].cell);
    }
  }
  cell_begin_.push_back(static_cast<std::uint32_t>(runs_.size()));
  std::size_t capacity = 16;
  while (capacity < 2 * keys.size()) capacity *= 2;
  slot_keys_.assign(capacity, kNoKey);
  slot_cells_.assign(capacity, kNoCell);
  for (std::size_t c = 0; c < keys.size(); ++c) {
    std::size_t slot = mix(keys[c]) & (capacity - 1);
    while (slot_cells_[slot] != kNoCell) slot = (slot + 1) & (capacity - 1);
    slot_keys_[slot] = keys[c];
    slot_cells_[slot] = static_cast<std::uint32_t>(c);
  }
}

std::uint32_t NeighbourIndex::find_cell(std::uint64_t key) const {
  const std::size_t mask = slot_keys_.size() - 1;
  for (std::size_t slot = mix(key) & mask;; slot = (slot + 1) & mask) {
    if (slot_cells_[slot] == kNoCell) return kNoCell;
    if (slot_keys_[slot] == key) return slot_cells_[slot];
  }
}

void NeighbourIndex::gather(std::uint64_t key, Scratch& scratch) const {
  scratch.key = key;
  scratch.cells.clear();
  const auto [x, y, z] = unpack(key);
  for (std::int64_t dx = -1; dx <= 1; ++dx)
    for (std::int64_t dy = -1; dy <= 1; ++dy)
      for (std::int64_t dz = -1; dz <= 1; ++dz) {
        const std::uint32_t cell = find_cell(pack(x + dx, y + dy, z + dz));
        if (cell != kNoCell) scratch.cells.emplace_back(cell_begin_[cell], cell_begin_[cell + 1]);
      }
  if (scratch.source_stamp.size() != source_count_) {
    scratch.source_stamp.assign(source_count_, 0);
    scratch.source_group.assign(source_count_, 0);
    scratch.stamp = 0;
  }
  if (++scratch.stamp == 0) {  // wrapped: every old stamp could match again
    std::fill(scratch.source_stamp.begin(), scratch.source_stamp.end(), 0);
    scratch.stamp = 1;
  }
  // Each source's group, numbered in the order met; then the runs placed group by group.
  scratch.group_size.clear();
  std::size_t total = 0;
  for (const auto& [begin, end] : scratch.cells)
    for (std::uint32_t r = begin; r < end; ++r) {
      const std::uint32_t source = runs_[r].source;
      if (scratch.source_stamp[source] != scratch.stamp) {
        scratch.source_stamp[source] = scratch.stamp;
        scratch.source_group[source] = static_cast<std::uint32_t>(scratch.group_size.size());
        scratch.group_size.push_back(0);
      }
      ++scratch.group_size[scratch.source_group[source]];
      ++total;
    }
  scratch.group_end.resize(scratch.group_size.size());
  std::uint32_t at = 0;
  for (std::size_t g = 0; g < scratch.group_size.size(); ++g) {
    const std::uint32_t size = scratch.group_size[g];
    scratch.group_size[g] = at;  // now where the group's next run goes
    at += size;
    scratch.group_end[g] = at;
  }
  scratch.runs.resize(total);
  for (const auto& [begin, end] : scratch.cells)
    for (std::uint32_t r = begin; r < end; ++r)
      scratch.runs[scratch.group_size[scratch.source_group[runs_[r].source]]++] = r;
  scratch.lower_cm.assign(scratch.group_end.size(), 0.0);
  scratch.upper_cm.assign(scratch.group_end.size(), 0.0);
  scratch.anchor_way_cm.assign(scratch.group_end.size(), -std::numeric_limits<double>::infinity());
  scratch.way_cm = 0.0;
}

std::pair<double, double> NeighbourIndex::group_bounds(const Cm& p, const Scratch& scratch, std::uint32_t begin,
                                                       std::uint32_t end) const {
  double lower2 = std::numeric_limits<double>::infinity(), upper2 = lower2;
  for (std::uint32_t g = begin; g < end; ++g) {
    const Run& run = runs_[scratch.runs[g]];
    lower2 = std::min(lower2, box_distance2(p, run.lo, run.hi));
    upper2 = std::min(upper2, segment_distance2(p, points_[run.first], points_[run.first]));
  }
  return {std::sqrt(lower2), std::sqrt(upper2)};
}

double NeighbourIndex::distance_to_group(const Cm& p, const Scratch& scratch, std::uint32_t begin,
                                         std::uint32_t end) const {
  double best2 = std::numeric_limits<double>::infinity();
  for (std::uint32_t g = begin; g < end; ++g) {
    const Run& run = runs_[scratch.runs[g]];
    if (box_distance2(p, run.lo, run.hi) >= best2) continue;
    if (run.first == run.last) {
      best2 = std::min(best2, segment_distance2(p, points_[run.first], points_[run.first]));
      continue;
    }
    for (std::uint32_t i = run.first; i < run.last; ++i)
      best2 = std::min(best2, segment_distance2(p, points_[i], points_[i + 1]));
  }
  return std::sqrt(best2);
}

std::size_t NeighbourIndex::count_at(const Cm& p, Scratch& scratch) const {
  if (scratch.has_previous) scratch.way_cm += distance_cm(scratch.previous, p);
  scratch.previous = p;
  scratch.has_previous = true;
  std::size_t count = 0;
  std::uint32_t begin = 0;
  for (std::size_t group = 0; group < scratch.group_end.size(); ++group) {
    const std::uint32_t end = scratch.group_end[group];
    // How far the distance may have moved since it was bounded; 1 mm more for rounding.
    const double moved = scratch.way_cm - scratch.anchor_way_cm[group] + 0.1;
    bool near = scratch.upper_cm[group] + moved <= radius_cm_;
    const bool far = scratch.lower_cm[group] - moved > radius_cm_;
    if (!near && !far) {
      auto [lower, upper] = group_bounds(p, scratch, begin, end);
      if (lower <= radius_cm_ && upper > radius_cm_) lower = upper = distance_to_group(p, scratch, begin, end);
      scratch.lower_cm[group] = lower;
      scratch.upper_cm[group] = upper;
      scratch.anchor_way_cm[group] = scratch.way_cm;
      near = upper <= radius_cm_;
    }
    count += near ? 1 : 0;
    begin = end;
  }
  return count;
}

void NeighbourIndex::count_near(PointLine points, std::span<float> out) const {
  if (out.size() != points.size())
    throw std::invalid_argument("count_near: " + std::to_string(out.size()) + " values for " +
                                std::to_string(points.size()) + " points");
  // One per thread, kept from line to line: its per-source arrays are as long as the sources.
  thread_local Scratch scratch;
  scratch.key = kNoKey;
  scratch.has_previous = false;
  const auto cell_of = [this](std::int32_t v) { return floor_div(v, cell_cm_); };
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto p = surface_cm<Cm>(points[i].lat, points[i].lon);
    if (!p) {
      out[i] = std::numeric_limits<float>::quiet_NaN();
      continue;
    }
    const std::uint64_t key = pack(cell_of(p->x), cell_of(p->y), cell_of(p->z));
    if (key != scratch.key) gather(key, scratch);
    out[i] = static_cast<float>(count_at(*p, scratch));
  }
}

std::size_t NeighbourIndex::count_near(double lat_deg, double lon_deg) const {
  TrackPoint p;
  p.lat = lat_deg;
  p.lon = lon_deg;
  float out = 0.0f;
  count_near(PointLine(&p, 1), std::span<float>(&out, 1));
  return std::isfinite(out) ? static_cast<std::size_t>(out) : 0;
}

std::vector<std::vector<std::vector<float>>> neighbour_counts(std::span<const NeighbourSource> sources,
                                                              std::span<const std::vector<PointLine>> targets,
                                                              double radius_m, const ParallelFor& parallel) {
  const NeighbourIndex index(sources, radius_m, parallel);
  std::vector<std::vector<std::vector<float>>> out(targets.size());
  run_all(targets.size(), parallel, [&](std::size_t t) {
    out[t].resize(targets[t].size());
    for (std::size_t l = 0; l < targets[t].size(); ++l) {
      out[t][l].resize(targets[t][l].size());
      index.count_near(targets[t][l], out[t][l]);
    }
  });
  return out;
}

}  // namespace trailray::track
