// Where a track is at a clock time.
#include "scene/tracks/replay_position.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace trailray::scene {
namespace {
TrackPosition on_point(const Track& t, std::size_t i, bool active) { return {true, active, i, 0.0, t.ecef(i)}; }

// The last timed point at or before `time`, in file order (cleaned times rise within a segment;
// a later segment that starts earlier than the previous one ended stops the scan).
std::optional<std::size_t> last_point_before(const Track& t, double time) {
  if (t.times_rise) {
    const auto after = std::upper_bound(t.timed_points.begin(), t.timed_points.end(), time,
                                        [&t](double when, std::size_t i) { return when < t.time_unix_s[i]; });
    if (after == t.timed_points.begin()) return std::nullopt;
    return *std::prev(after);
  }
  std::optional<std::size_t> before;
  for (std::size_t i : t.timed_points) {
    if (t.time_unix_s[i] <= time)
      before = i;
    else if (before)
      break;
  }
  return before;
}

}  // namespace

TrackPosition position_at(const Track& t, double time) {
  if (t.timed_points.empty()) return {};
  const double start = t.time_unix_s[t.timed_points.front()], end = t.time_unix_s[t.timed_points.back()];
  const std::size_t n = t.point_count();
  const std::optional<std::size_t> before = last_point_before(t, time);
  if (!before) return on_point(t, t.timed_points.front(), false);
  const std::size_t a = *before;
  const bool active = time >= start && time <= end;
  // The next timed point in the same segment: interpolate towards it; none: wait at `a`.
  const std::size_t seg = t.segment_of(a);
  const std::size_t seg_end = seg + 1 < t.segment_first.size() ? t.segment_first[seg + 1] : n;
  for (std::size_t j = a + 1; j < seg_end; ++j) {
    const double tj = t.time_unix_s[j];
    if (std::isnan(tj)) continue;
    const double ta = t.time_unix_s[a];
    if (tj <= ta) break;
    const double f = std::clamp((time - ta) / (tj - ta), 0.0, 1.0);
    if (f <= 0.0) return on_point(t, a, active);
    // Untimed points between a and j (rare) are skipped: the marker moves straight from a to j.
    return {true, active, a, f, t.ecef(a) + (t.ecef(j) - t.ecef(a)) * f};
  }
  return on_point(t, a, active);
}

std::optional<TimeSpan> common_time_span(const TrackSet& tracks) {
  std::optional<TimeSpan> span;
  for (const Track& t : tracks.tracks()) {
    const auto s = t.start_time();
    const auto e = t.end_time();
    if (!s || !e) continue;
    if (!span)
      span = TimeSpan{*s, *e};
    else
      span = TimeSpan{std::min(span->start, *s), std::max(span->end, *e)};
  }
  return span;
}

}  // namespace trailray::scene
