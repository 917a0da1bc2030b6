// Phases from the turn rate: heading change per second over a centred window, with hysteresis
// and minimum durations (see flight_analysis.hpp for the rules).
#include <cmath>

#include "track/flight/flight_samples.hpp"

namespace trailray::track::flight::detail {
namespace {

// Below this ground speed a step's direction is mostly GPS noise: the heading is kept.
constexpr double kMinHeadingSpeed = 1.0;  // m/s

double wrap180(double d) {
  while (d > 180.0) d -= 360.0;
  while (d <= -180.0) d += 360.0;
  return d;
}

// Joins neighbouring runs of the same phase.
void merge_adjacent(std::vector<Run>& runs) {
  std::vector<Run> out;
  for (const Run& r : runs) {
    if (!out.empty() && out.back().phase == r.phase)
      out.back().last = r.last;
    else
      out.push_back(r);
  }
  runs.swap(out);
}

}  // namespace

TurnPhases turn_phases(const std::vector<Sample>& s, std::size_t first, std::size_t last, const FlightOptions& o) {
  TurnPhases out;
  const std::size_t n = last - first + 1;
  std::vector<double>& sum = out.heading_sum;
  sum.assign(n, 0.0);
  std::vector<int> gaps(n, 0);  // gaps before sample k, cumulative
  double heading = kMissing;
  for (std::size_t k = 1; k < n; ++k) {
    const Sample& a = s[first + k - 1];
    const Sample& b = s[first + k];
    gaps[k] = gaps[k - 1] + (b.gap_before ? 1 : 0);
    double change = 0.0;
    if (b.gap_before) {
      heading = kMissing;  // do not connect headings across a gap
    } else {
      const EastNorth d = east_north(a.lat, a.lon, b.lat, b.lon);
      const double dist = std::hypot(d.e, d.n);
      if (dist >= kMinHeadingSpeed * (b.time - a.time)) {
        const double h = bearing_deg(d.e, d.n);
        if (!std::isnan(heading)) change = wrap180(h - heading);
        heading = h;
      }
    }
    sum[k] = sum[k - 1] + change;
  }
  // Turn rate per sample over [t - w/2, t + w/2] and the phase each sample is in.
  const double half = 0.5 * o.turn_window_s;
  std::vector<Phase> state(n, Phase::Gliding);
  std::size_t lo = 0, hi = 0;
  Phase current = Phase::Gliding;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = s[first + k].time;
    while (lo < k && s[first + lo].time < t - half) ++lo;
    if (hi < k) hi = k;
    while (hi + 1 < n && s[first + hi + 1].time <= t + half) ++hi;
    // Fixes further apart than half the window: the rate from the neighbours at least.
    const std::size_t a = lo == k && k > 0 ? k - 1 : lo, b = hi == k && k + 1 < n ? k + 1 : hi;
    const double span = s[first + b].time - s[first + a].time;
    // A gap longer than half the window is in no window: the fixes on either side are unknown.
    const bool next_gap = k + 1 < n && s[first + k + 1].gap_before;
    if (gaps[b] != gaps[a] || span <= 0.0 || (k > 0 && s[first + k].gap_before) || next_gap) {
      state[k] = current = Phase::Unknown;
      continue;
    }
    const double rate = (sum[b] - sum[a]) / span;
    const Phase dir = rate > 0 ? Phase::CirclingRight : Phase::CirclingLeft;
    if (std::fabs(rate) >= o.circling_enter_deg_s)
      current = dir;
    else if (!(is_circling(current) && current == dir && std::fabs(rate) >= o.circling_exit_deg_s))
      current = Phase::Gliding;
    state[k] = current;
  }
  // Runs over samples; each run ends at the next run's first sample.
  std::vector<Run>& runs = out.runs;
  for (std::size_t k = 0; k < n; ++k) {
    if (runs.empty() || runs.back().phase != state[k]) {
      if (!runs.empty()) runs.back().last = first + k;
      runs.push_back({state[k], first + k, first + k});
    }
  }
  if (!runs.empty()) runs.back().last = last;
  auto duration = [&](const Run& r) { return s[r.last].time - s[r.first].time; };
  // Too little circling is not a thermal; then a short straight bit between two circlings is
  // part of the thermal (re-centring), joined to the circling before it.
  for (Run& r : runs)
    if (is_circling(r.phase) && duration(r) < o.min_thermal_s) r.phase = Phase::Gliding;
  merge_adjacent(runs);
  for (std::size_t k = 1; k + 1 < runs.size(); ++k)
    if (runs[k].phase == Phase::Gliding && is_circling(runs[k - 1].phase) && is_circling(runs[k + 1].phase) &&
        duration(runs[k]) < o.min_glide_s)
      runs[k].phase = runs[k - 1].phase;
  merge_adjacent(runs);
  return out;
}

}  // namespace trailray::track::flight::detail
