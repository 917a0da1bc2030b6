#pragma once
// Where a track is at a clock time: the replay's marker in the viewer and the film's (`trailray
// video`), the trail a film draws up to it, the camera that follows it.

#include <glm/glm.hpp>

#include <cstddef>
#include <optional>

#include "scene/tracks/track_set.hpp"

namespace trailray::scene {

// Where a track is at a clock time: between points `point` and `point + 1` (fraction 0..1 of the
// way), or on a point (fraction 0). Before the track's start it waits at its first timed point,
// after its end at its last; across a segment gap it waits at the gap's start (never bridged).
struct TrackPosition {
  bool valid = false;     // false: the track has no timed point
  bool active = false;    // the time lies within the track's start..end
  std::size_t point = 0;  // flat index
  double fraction = 0.0;
  glm::dvec3 ecef{0.0};
};
// A binary search over the track's timed points (Track::timed_points) when their times rise, as
// cleaned tracks' do; a scan in file order otherwise.
TrackPosition position_at(const Track& track, double time_unix_s);

struct TimeSpan {
  double start = 0.0, end = 0.0;  // unix seconds
};
// From the earliest start to the latest end of the tracks with times (nullopt: none has one).
std::optional<TimeSpan> common_time_span(const TrackSet& tracks);

}  // namespace trailray::scene
