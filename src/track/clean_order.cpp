// Cleaning steps 1 and 2 (clean.hpp): invalid coordinates and values, then timestamps
// (duplicates, same-second runs, frozen clocks, backward jumps).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "track/clean_steps.hpp"

namespace trailray::track::detail {
namespace {

bool valid_coordinates(const TrackPoint& p) {
  return std::isfinite(p.lat) && std::isfinite(p.lon) && std::abs(p.lat) <= 90.0 && std::abs(p.lon) <= 180.0;
}

// A segment whose clock never advances: at least 3 timestamps spanning less than 1 ms per point
// (no GPS logs at 1 kHz; seen with placeholder times such as 1901-12-13T20:45:52Z). Fed the
// finite timestamps of the points with valid coordinates.
struct FrozenClockCheck {
  std::size_t timed = 0;
  double lo = 0.0, hi = 0.0;
  void add(double t) {
    lo = timed == 0 ? t : std::min(lo, t);
    hi = timed == 0 ? t : std::max(hi, t);
    ++timed;
  }
  bool frozen() const { return timed >= 3 && hi - lo < 1e-3 * static_cast<double>(timed - 1); }
};

bool same_fix(const TrackPoint& a, const TrackPoint& b) {
  const bool same_ele = a.ele == b.ele || (std::isnan(a.ele) && std::isnan(b.ele));
  return a.time == b.time && a.lat == b.lat && a.lon == b.lon && same_ele;
}

// Step 2b: runs of one timestamp at different places get evenly spread times over the
// interval to the next later timestamp (at most 1 s: loggers stamp whole seconds). Real runs
// are up to 10 long (10 Hz loggers); a longer run than kMaxFixesPerSecond is a stuck clock
// (seen: 51 fixes, 30 m apart, all stamped 10:24:03) and loses its times instead.
constexpr std::size_t kMaxFixesPerSecond = 20;

void spread_same_second_runs(std::vector<TrackPoint>& pts, CleanReport& report) {
  std::size_t i = 0;
  while (i < pts.size()) {
    if (!pts[i].has_time()) {
      ++i;
      continue;
    }
    const double t = pts[i].time;
    std::size_t end = i + 1;
    while (end < pts.size() && pts[end].time == t) ++end;
    const std::size_t run = end - i;
    if (run > kMaxFixesPerSecond) {
      // No logger writes that many fixes in one second: the clock stood still. Keep the
      // places, drop the made-up times.
      for (std::size_t k = 1; k < run; ++k) pts[i + k].time = kMissing;
      report.frozen_time += run - 1;
    } else if (run >= 2) {
      double next = kMissing;
      for (std::size_t k = end; k < pts.size(); ++k)
        if (pts[k].has_time()) {
          next = pts[k].time;
          break;
        }
      const double span = std::isnan(next) || next <= t ? 1.0 : std::min(next - t, 1.0);
      for (std::size_t k = 1; k < run; ++k)
        pts[i + k].time = t + span * static_cast<double>(k) / static_cast<double>(run);
      report.spread_time += run - 1;
    }
    i = end;
  }
}

}  // namespace

// Steps 1 and 2: invalid coordinates, non-finite values, duplicates, same-second runs,
// non-increasing timestamps. Returns the kept points: one copy of the input, then compacted in
// place. The frozen-clock check needs every timestamp first: the copy assumes a running clock
// and is redone in the rare case that it was frozen.
std::vector<TrackPoint> drop_invalid_and_unordered(const std::vector<TrackPoint>& in, CleanReport& report) {
  std::vector<TrackPoint> pts;
  pts.reserve(in.size());
  CleanReport r;         // added to `report` once the pass is final
  bool repeats = false;  // two consecutive kept points with one timestamp: runs to spread
  bool ordered = true;   // every timestamp after the last earlier one: nothing to drop
  for (const bool frozen : {false, true}) {
    pts.clear();
    r = CleanReport{};
    repeats = false;
    ordered = true;
    FrozenClockCheck clock;
    double last_time = kMissing;
    for (const TrackPoint& in_point : in) {
      if (!valid_coordinates(in_point)) {
        ++r.invalid_coordinates;
        continue;
      }
      TrackPoint p = in_point;
      if (std::isinf(p.ele) || std::isinf(p.time)) {
        if (std::isinf(p.ele)) p.ele = kMissing;
        if (std::isinf(p.time)) p.time = kMissing;
        ++r.invalid_values;
      }
      if (p.has_time()) {
        clock.add(p.time);
        if (frozen) {
          p.time = kMissing;
          ++r.frozen_time;
        }
      }
      if (p.has_time()) {
        if (!pts.empty() && same_fix(pts.back(), p)) {
          ++r.duplicate_points;
          continue;
        }
        if (!pts.empty() && pts.back().time == p.time) repeats = true;
        if (!std::isnan(last_time) && !(p.time > last_time)) ordered = false;
        last_time = p.time;
      }
      pts.push_back(p);
    }
    if (frozen || !clock.frozen()) break;
  }
  report.invalid_coordinates += r.invalid_coordinates;
  report.invalid_values += r.invalid_values;
  report.frozen_time += r.frozen_time;
  report.duplicate_points += r.duplicate_points;

  if (repeats) spread_same_second_runs(pts, report);
  if (repeats || !ordered) {
    std::size_t kept = 0;
    double last_time = kMissing;  // the last kept timestamp of this segment
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const TrackPoint& p = pts[i];
      if (p.has_time()) {
        if (!std::isnan(last_time) && !(p.time > last_time)) {
          ++report.non_increasing_time;
          continue;
        }
        last_time = p.time;
      }
      if (kept != i) pts[kept] = p;
      ++kept;
    }
    pts.resize(kept);
  }
  return pts;
}

}  // namespace trailray::track::detail
