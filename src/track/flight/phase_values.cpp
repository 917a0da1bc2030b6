#include "track/flight/phase_values.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "track/color_values.hpp"

namespace trailray::track::flight {
namespace {

constexpr float kNoValue = std::numeric_limits<float>::quiet_NaN();

// The span of `flight` holding time t (its last span whose start is at or before t); nullptr
// outside the flight.
const PhaseSpan* span_at(const Flight& flight, double t) {
  if (flight.phases.empty() || !(t >= flight.takeoff.time) || !(t <= flight.landing.time)) return nullptr;
  const auto after = std::upper_bound(flight.phases.begin(), flight.phases.end(), t,
                                      [](double time, const PhaseSpan& s) { return time < s.start.time; });
  return after == flight.phases.begin() ? &flight.phases.front() : &*std::prev(after);
}

const PhaseSpan* span_at(const FlightAnalysis& analysis, double t) {
  for (const Flight& f : analysis.flights)
    if (const PhaseSpan* s = span_at(f, t)) return s;
  return nullptr;
}

// The climb at point i of `points` over [t - w/2, t + w/2] clipped to [from, to]: the height
// difference of the first and last points inside over their time difference.
float climb_at(const std::vector<TrackPoint>& points, std::size_t i, double half_window, double from, double to) {
  const double t = points[i].time;
  const double lo = std::max(t - half_window, from), hi = std::min(t + half_window, to);
  std::size_t a = i, b = i;
  while (a > 0 && points[a - 1].time >= lo && !std::isnan(points[a - 1].time)) --a;
  while (b + 1 < points.size() && points[b + 1].time <= hi && !std::isnan(points[b + 1].time)) ++b;
  // Too short a window (the span's first or last second): the neighbours' climb instead.
  if (a == b) {
    if (a > 0 && !std::isnan(points[a - 1].time)) --a;
    if (b + 1 < points.size() && !std::isnan(points[b + 1].time)) ++b;
  }
  const double dt = points[b].time - points[a].time;
  const double dz = points[b].ele - points[a].ele;
  if (!(dt > 1e-3) || !std::isfinite(dz)) return kNoValue;
  return static_cast<float>(dz / dt);
}

}  // namespace

Phase phase_at_time(const FlightAnalysis& analysis, double t) {
  if (std::isnan(t)) return Phase::Unknown;
  const PhaseSpan* s = span_at(analysis, t);
  return s != nullptr ? s->phase : Phase::Ground;
}

std::vector<std::vector<float>> phase_color_values(const Track& drawn, const FlightAnalysis& analysis,
                                                   double climb_window_s) {
  std::vector<std::vector<float>> values(drawn.segments.size());
  for (std::size_t s = 0; s < drawn.segments.size(); ++s) {
    const std::vector<TrackPoint>& points = drawn.segments[s].points;
    values[s].assign(points.size(), kNoValue);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double t = points[i].time;
      if (std::isnan(t)) continue;
      const PhaseSpan* span = span_at(analysis, t);
      if (span == nullptr) continue;
      if (span->phase == Phase::Gliding)
        values[s][i] = kCategoryValue;
      else if (is_circling(span->phase))
        values[s][i] = climb_at(points, i, 0.5 * climb_window_s, span->start.time, span->end.time);
    }
  }
  return values;
}

}  // namespace trailray::track::flight
