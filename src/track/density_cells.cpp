// The questions to a NeighbourIndex: every point asked about, taken cell by cell (density.hpp's
// "How"). Many tracks pass the same places (a take-off, a city's paths), so the work on a place is
// done once for all of them; the work on a point is only the sources near the radius' edge.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "track/density.hpp"
#include "track/density_detail.hpp"

namespace trailray::track {

using density_detail::box_box_distance2;
using density_detail::box_distance2;
using density_detail::floor_div;
using density_detail::grow;
using density_detail::kNoCell;
using density_detail::pack;
using density_detail::run_all;
using density_detail::segment_distance2;
using density_detail::surface_cm;
using density_detail::unpack;

namespace {

// A box of points with at most this many is measured point by point, not split again.
constexpr std::size_t kLeafPoints = 4;
// Splitting in halves on the longest axis: 64 levels take any box of the Earth down to one point.
constexpr std::size_t kMaxDepth = 64;
// A decision for a whole box keeps this far from the radius (cm), so a point within rounding of
// the edge is measured as a brute force would measure it.
constexpr double kMarginCm = 0.01;

}  // namespace

struct NeighbourIndex::CellCounter {
  struct Point {
    Cm p;
    float* out = nullptr;
  };
  // Runs grouped by source: a group per source, `ends` where each group ends in `runs`.
  // Per group too, from when all its segments were last measured (at the centre `at`): the
  // distance to the nearest, and the one that came nearest to covering the box then (its run in
  // `runs` and its first point).
  struct Candidates {
    std::vector<std::uint32_t> runs, ends, segment_run, segment;
    std::vector<double> nearest;
    double at[3] = {0.0, 0.0, 0.0};
  };

  const NeighbourIndex* index = nullptr;
  double r2 = 0.0, r2_in = 0.0, r2_out = 0.0;  // the radius squared, less and more the margin
  std::vector<Point> points;                   // the cell's points
  std::vector<Candidates> levels;              // per level of splitting: the sources still undecided
  // Grouping by source without sorting: each source's group in this gathering (by stamp).
  std::vector<std::uint32_t> source_stamp, source_group, group_size;
  std::uint32_t stamp = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> cells;  // [begin, end) of runs per cell

  void start(const NeighbourIndex& with) {
    index = &with;
    const double r = with.radius_cm_;
    r2 = r * r;
    r2_in = (r - kMarginCm) * (r - kMarginCm);
    r2_out = (r + kMarginCm) * (r + kMarginCm);
    levels.resize(kMaxDepth + 2);
    if (source_stamp.size() != with.source_count_) {
      source_stamp.assign(with.source_count_, 0);
      source_group.assign(with.source_count_, 0);
      stamp = 0;
    }
  }

  // The runs of the 27 cells around `key`, grouped by source, into levels[0].
  void gather(std::uint64_t key) {
    const NeighbourIndex& ix = *index;
    cells.clear();
    const auto [x, y, z] = unpack(key);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const std::uint32_t cell = ix.find_cell(pack(x + dx, y + dy, z + dz));
          if (cell != kNoCell) cells.emplace_back(ix.cell_begin_[cell], ix.cell_begin_[cell + 1]);
        }
    if (++stamp == 0) {  // wrapped: every old stamp could match again
      std::fill(source_stamp.begin(), source_stamp.end(), 0);
      stamp = 1;
    }
    // Each source's group, numbered in the order met; then the runs placed group by group.
    group_size.clear();
    std::size_t total = 0;
    for (const auto& [begin, end] : cells)
      for (std::uint32_t r = begin; r < end; ++r) {
        const std::uint32_t source = ix.runs_[r].source;
        if (source_stamp[source] != stamp) {
          source_stamp[source] = stamp;
          source_group[source] = static_cast<std::uint32_t>(group_size.size());
          group_size.push_back(0);
        }
        ++group_size[source_group[source]];
        ++total;
      }
    Candidates& out = levels[0];
    out.ends.resize(group_size.size());
    std::uint32_t at = 0;
    for (std::size_t g = 0; g < group_size.size(); ++g) {
      const std::uint32_t size = group_size[g];
      group_size[g] = at;  // now where the group's next run goes
      at += size;
      out.ends[g] = at;
    }
    out.runs.resize(total);
    for (const auto& [begin, end] : cells)
      for (std::uint32_t r = begin; r < end; ++r) out.runs[group_size[source_group[ix.runs_[r].source]]++] = r;
  }

  // The point of the segment a-b nearest to c, as an offset from c (a == b: a).
  static std::array<double, 3> nearest_on(const double (&c)[3], const Cm& a, const Cm& b) {
    const double ax = a.x - c[0], ay = a.y - c[1], az = a.z - c[2];
    const double dx = static_cast<double>(b.x) - a.x, dy = static_cast<double>(b.y) - a.y,
                 dz = static_cast<double>(b.z) - a.z;
    const double length2 = dx * dx + dy * dy + dz * dz;
    double t = 0.0;
    if (length2 > 0.0) t = std::clamp(-(ax * dx + ay * dy + az * dz) / length2, 0.0, 1.0);
    return {ax + t * dx, ay + t * dy, az + t * dz};
  }

  // How far the box centred on c with half sizes h reaches from the segment a-b, squared: from
  // the segment's point nearest c, its farthest corner is |offset| + h away on each axis. Within
  // the radius (less the margin), the segment is within the radius of the whole box.
  static double farthest2(const double (&c)[3], const double (&h)[3], const Cm& a, const Cm& b) {
    const auto o = nearest_on(c, a, b);
    const double fx = std::abs(o[0]) + h[0], fy = std::abs(o[1]) + h[1], fz = std::abs(o[2]) + h[2];
    return fx * fx + fy * fy + fz * fz;
  }

  // Over the run's segments: the nearest distance to c (squared) into `nearest2`, and the segment
  // reaching farthest over the box (farthest2) into `reach2` / `segment` where it reaches farther
  // (then true).
  bool measure(const Run& run, const double (&c)[3], const double (&h)[3], double& nearest2, double& reach2,
               std::uint32_t& segment) const {
    const std::vector<Cm>& pts = index->points_;
    const std::uint32_t last = run.first == run.last ? run.first : run.last - 1;
    bool farther = false;
    for (std::uint32_t i = run.first; i <= last; ++i) {
      const Cm& b = pts[run.first == run.last ? i : i + 1];
      const auto o = nearest_on(c, pts[i], b);
      nearest2 = std::min(nearest2, o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
      const double fx = std::abs(o[0]) + h[0], fy = std::abs(o[1]) + h[1], fz = std::abs(o[2]) + h[2];
      const double f = fx * fx + fy * fy + fz * fz;
      if (f < reach2) {
        reach2 = f;
        segment = i;
        farther = true;
      }
    }
    return farther;
  }

  // The segment `segment` names: from it to the next point, or the point alone at a run's end.
  const Cm& segment_end(std::uint32_t segment, const Run& run) const {
    return index->points_[run.first == run.last ? segment : segment + 1];
  }

  // Whether a segment of the group's runs [begin, end) of `c` is within the radius of p.
  bool near(const Cm& p, const Candidates& c, std::uint32_t begin, std::uint32_t end) const {
    const std::vector<Cm>& pts = index->points_;
    for (std::uint32_t g = begin; g < end; ++g) {
      const Run& run = index->runs_[c.runs[g]];
      if (box_distance2(p, run.lo, run.hi) > r2_out) continue;
      if (run.first == run.last) {
        if (segment_distance2(p, pts[run.first], pts[run.first]) <= r2) return true;
        continue;
      }
      for (std::uint32_t i = run.first; i < run.last; ++i) {
        const Cm& a = pts[i];
        const Cm& b = pts[i + 1];
        // The segment's own box first: integer comparisons rule most of them out.
        const Cm lo{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
        const Cm hi{std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
        if (box_distance2(p, lo, hi) > r2_out) continue;
        if (segment_distance2(p, a, b) <= r2) return true;
      }
    }
    return false;
  }

  // The sources of `c` within the radius of p, plus `certain`. Before measuring a source
  // segment by segment: its segment that came nearest to covering the box, then the distance
  // measured at `c.at` less the way from there.
  std::size_t count_one(const Cm& p, const Candidates& c, std::size_t certain) const {
    const double mx = p.x - c.at[0], my = p.y - c.at[1], mz = p.z - c.at[2];
    const double far = std::sqrt(r2_out) + std::sqrt(mx * mx + my * my + mz * mz);
    std::uint32_t begin = 0;
    for (std::size_t group = 0; group < c.ends.size(); ++group) {
      const std::uint32_t end = c.ends[group];
      const std::uint32_t segment = c.segment[group];
      if (segment_distance2(p, index->points_[segment], segment_end(segment, index->runs_[c.segment_run[group]])) <= r2)
        ++certain;
      else if (c.nearest[group] <= far && near(p, c, begin, end))
        ++certain;
      begin = end;
    }
    return certain;
  }

  // Counts points [begin, end), whose sources levels[depth] holds undecided; `certain` sources
  // are within the radius of all of them.
  void count(std::size_t depth, std::size_t begin, std::size_t end, std::size_t certain) {
    Cm lo = points[begin].p, hi = lo;
    for (std::size_t i = begin + 1; i < end; ++i) grow(lo, hi, points[i].p);
    const double c[3] = {(static_cast<double>(lo.x) + hi.x) / 2, (static_cast<double>(lo.y) + hi.y) / 2,
                         (static_cast<double>(lo.z) + hi.z) / 2};
    const double h[3] = {(static_cast<double>(hi.x) - lo.x) / 2, (static_cast<double>(hi.y) - lo.y) / 2,
                         (static_cast<double>(hi.z) - lo.z) / 2};
    const Candidates& in = levels[depth];
    Candidates& kept = levels[depth + 1];
    kept.runs.clear();
    kept.ends.clear();
    kept.segment_run.clear();
    kept.segment.clear();
    kept.nearest.clear();
    // Every segment of the undecided sources is measured on every third level (a box halved on
    // each axis); on the others only the one that came nearest to covering then, and the distance
    // measured then, less the way from there (the triangle inequality), rules sources out.
    const bool measure_all = depth % 3 == 0;
    const bool measured = depth > 0;                                          // the gathering has no measures yet
    const double reach = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);  // centre to corner
    double moved = 0.0;
    if (measured) {
      const double mx = c[0] - in.at[0], my = c[1] - in.at[1], mz = c[2] - in.at[2];
      moved = std::sqrt(mx * mx + my * my + mz * mz);
    }
    std::copy(measure_all ? std::begin(c) : std::begin(in.at), measure_all ? std::end(c) : std::end(in.at),
              std::begin(kept.at));
    const double far = std::sqrt(r2_out) + reach;  // a source farther from the centre is out
    std::uint32_t from = 0;
    for (std::size_t group = 0; group < in.ends.size(); ++group) {
      const std::uint32_t to = in.ends[group];
      const std::size_t first_kept = kept.runs.size();
      double nearest = std::numeric_limits<double>::infinity(), reach2 = nearest;
      std::uint32_t segment = 0, segment_run = 0;
      if (measured) {
        segment = in.segment[group];
        segment_run = in.segment_run[group];
        reach2 = farthest2(c, h, index->points_[segment], segment_end(segment, index->runs_[segment_run]));
        nearest = in.nearest[group];  // at in.at
        if (reach2 > r2_in && nearest - moved > far) {
          from = to;
          continue;
        }
      }
      double nearest2 = std::numeric_limits<double>::infinity();
      for (std::uint32_t g = from; g < to && reach2 > r2_in; ++g) {
        const Run& run = index->runs_[in.runs[g]];
        if (box_box_distance2(run.lo, run.hi, lo, hi) > r2_out) continue;  // too far from all of the box
        kept.runs.push_back(in.runs[g]);
        if (measure_all && measure(run, c, h, nearest2, reach2, segment)) segment_run = in.runs[g];
      }
      from = to;
      if (reach2 <= r2_in) {
        ++certain;
        kept.runs.resize(first_kept);
        continue;
      }
      if (measure_all) nearest = std::sqrt(nearest2);
      if (kept.runs.size() == first_kept || (measure_all && nearest > far)) {
        kept.runs.resize(first_kept);
        continue;
      }
      kept.ends.push_back(static_cast<std::uint32_t>(kept.runs.size()));
      kept.segment_run.push_back(segment_run);
      kept.segment.push_back(segment);
      kept.nearest.push_back(nearest);
    }
    const bool one_place = lo.x == hi.x && lo.y == hi.y && lo.z == hi.z;
    if (kept.ends.empty() || one_place || end - begin <= kLeafPoints || depth + 1 >= kMaxDepth) {
      if (kept.ends.empty() || one_place) {
        const auto value = static_cast<float>(kept.ends.empty() ? certain : count_one(lo, kept, certain));
        for (std::size_t i = begin; i < end; ++i) *points[i].out = value;
        return;
      }
      for (std::size_t i = begin; i < end; ++i)
        *points[i].out = static_cast<float>(count_one(points[i].p, kept, certain));
      return;
    }
    // In halves across the longest axis (both sides have points: the box is tight).
    const std::int32_t extent[3] = {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
    const int axis = extent[0] >= extent[1] && extent[0] >= extent[2] ? 0 : extent[1] >= extent[2] ? 1 : 2;
    const auto coordinate = [axis](const Cm& p) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; };
    const std::int32_t mid = coordinate(lo) + extent[axis] / 2;
    const auto split = std::partition(points.begin() + static_cast<std::ptrdiff_t>(begin),
                                      points.begin() + static_cast<std::ptrdiff_t>(end),
                                      [&](const Point& q) { return coordinate(q.p) <= mid; });
    const auto middle = static_cast<std::size_t>(split - points.begin());
    count(depth + 1, begin, middle, certain);
    count(depth + 1, middle, end, certain);
  }
};

void NeighbourIndex::count_near_lines(std::span<const PointLine> lines, std::span<const std::span<float>> out,
                                      const ParallelFor& parallel) const {
  if (out.size() != lines.size())
    throw std::invalid_argument("count_near: " + std::to_string(out.size()) + " outputs for " +
                                std::to_string(lines.size()) + " lines");
  std::vector<std::size_t> offset(lines.size() + 1, 0);
  for (std::size_t l = 0; l < lines.size(); ++l) {
    if (out[l].size() != lines[l].size())
      throw std::invalid_argument("count_near: " + std::to_string(out[l].size()) + " values for " +
                                  std::to_string(lines[l].size()) + " points");
    offset[l + 1] = offset[l] + lines[l].size();
  }
  if (offset.back() >= kNoCell) throw std::length_error("more than 2^32 points to count neighbours at");

  // Each point's place, and the stretches of consecutive points of a line in one cell.
  struct Stretch {
    std::uint64_t cell = 0;
    std::uint32_t first = 0, count = 0;  // points [first, first + count), numbered over all lines
  };
  std::vector<Cm> places(offset.back());
  std::vector<std::vector<Stretch>> line_stretches(lines.size());
  const auto cell_of = [this](std::int32_t v) { return floor_div(v, cell_cm_); };
  run_all(lines.size(), parallel, [&](std::size_t l) {
    std::vector<Stretch>& stretches = line_stretches[l];
    for (std::size_t i = 0; i < lines[l].size(); ++i) {
      const auto p = surface_cm<Cm>(lines[l][i].lat, lines[l][i].lon);
      if (!p) {
        out[l][i] = std::numeric_limits<float>::quiet_NaN();
        continue;
      }
      const auto id = static_cast<std::uint32_t>(offset[l] + i);
      places[id] = *p;
      const std::uint64_t cell = pack(cell_of(p->x), cell_of(p->y), cell_of(p->z));
      if (!stretches.empty() && stretches.back().cell == cell && stretches.back().first + stretches.back().count == id)
        ++stretches.back().count;
      else
        stretches.push_back({cell, id, 1});
    }
  });
  std::vector<Stretch> stretches;
  std::size_t total = 0;
  for (const auto& s : line_stretches) total += s.size();
  stretches.reserve(total);
  for (auto& s : line_stretches) {
    stretches.insert(stretches.end(), s.begin(), s.end());
    std::vector<Stretch>().swap(s);
  }
  std::sort(stretches.begin(), stretches.end(),
            [](const Stretch& a, const Stretch& b) { return a.cell != b.cell ? a.cell < b.cell : a.first < b.first; });
  std::vector<std::size_t> cell_first;  // per cell its first stretch; one more at the end
  for (std::size_t i = 0; i < stretches.size(); ++i)
    if (i == 0 || stretches[i].cell != stretches[i - 1].cell) cell_first.push_back(i);
  cell_first.push_back(stretches.size());

  run_all(cell_first.size() - 1, parallel, [&](std::size_t cell) {
    // One per thread, kept from cell to cell: its per-source arrays are as long as the sources.
    thread_local CellCounter counter;
    counter.start(*this);
    counter.points.clear();
    for (std::size_t s = cell_first[cell]; s < cell_first[cell + 1]; ++s) {
      const Stretch& stretch = stretches[s];
      const auto line =
          static_cast<std::size_t>(std::upper_bound(offset.begin(), offset.end(), stretch.first) - offset.begin() - 1);
      float* values = out[line].data() + (stretch.first - offset[line]);
      for (std::uint32_t k = 0; k < stretch.count; ++k)
        counter.points.push_back({places[stretch.first + k], values + k});
    }
    counter.gather(stretches[cell_first[cell]].cell);
    counter.count(0, 0, counter.points.size(), 0);
  });
}

}  // namespace trailray::track
