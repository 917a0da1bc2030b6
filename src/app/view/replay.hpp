#pragma once
// The replay: one clock for every track, and where each track is at a clock time.

#include <glm/glm.hpp>

#include <cstddef>
#include <optional>

#include "scene/track_set.hpp"

namespace trailray::app::view {

enum class FollowMode { off, chase, orbit };

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
TrackPosition position_at(const scene::Track& track, double time_unix_s);

struct TimeSpan {
  double start = 0.0, end = 0.0;  // unix seconds
};
// From the earliest start to the latest end of the tracks with times (nullopt: none has one).
std::optional<TimeSpan> common_time_span(const scene::TrackSet& tracks);

// One clock for all tracks: time runs at `speed` times the wall clock while playing, and stops
// (pauses) at the span's end.
class ReplayClock {
 public:
  static constexpr double kMinSpeed = 1.0, kMaxSpeed = 1000.0;

  void set_span(const TimeSpan& span);  // keeps the time when it is inside, else goes to the start
  const std::optional<TimeSpan>& span() const { return span_; }
  double time() const { return time_; }
  double speed() const { return speed_; }
  bool playing() const { return playing_; }
  // 0..1 along the span (0 without a span).
  double fraction() const;

  void play();  // at the end: starts over
  void pause() { playing_ = false; }
  void toggle() { playing_ ? pause() : play(); }
  void set_speed(double speed);       // clamped to kMinSpeed..kMaxSpeed
  void seek(double time_unix_s);      // clamped to the span
  void seek_fraction(double f);       // 0..1
  void advance(double wall_seconds);  // moves the time when playing

  FollowMode follow = FollowMode::off;
  int follow_track = 0;  // the track the camera follows

 private:
  std::optional<TimeSpan> span_;
  double time_ = 0.0;
  double speed_ = 10.0;
  bool playing_ = false;
};

}  // namespace trailray::app::view
