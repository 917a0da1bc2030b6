#include "track/density.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "track/density_detail.hpp"

namespace trailray::track {

using density_detail::distance_cm;
using density_detail::floor_div;
using density_detail::grow;
using density_detail::kNoCell;
using density_detail::pack;
using density_detail::run_all;
using density_detail::surface_cm;

namespace {

constexpr std::uint64_t kNoKey = std::numeric_limits<std::uint64_t>::max();
constexpr std::int64_t kMinCellCm = 800;
constexpr std::int64_t kMinGapCm = 1000000;  // 10 km
constexpr std::uint32_t kMaxRunSegments = 8;

std::uint64_t mix(std::uint64_t x) {  // splitmix64's finaliser: spreads neighbouring cells over the table
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
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

void NeighbourIndex::count_near(PointLine points, std::span<float> out) const {
  const std::span<float> outs[] = {out};
  count_near_lines(std::span<const PointLine>(&points, 1), outs);
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
  std::vector<PointLine> lines;
  std::vector<std::span<float>> values;
  for (std::size_t t = 0; t < targets.size(); ++t) {
    out[t].resize(targets[t].size());
    for (std::size_t l = 0; l < targets[t].size(); ++l) {
      out[t][l].resize(targets[t][l].size());
      lines.push_back(targets[t][l]);
      values.emplace_back(out[t][l]);
    }
  }
  index.count_near_lines(lines, values, parallel);
  return out;
}

}  // namespace trailray::track
