#pragma once
// The replay: one clock for every track, and where each track is at a clock time.

#include <glm/glm.hpp>

#include <cstddef>
#include <optional>

#include "scene/tracks/replay_position.hpp"
#include "scene/tracks/track_set.hpp"

namespace trailray::ui {

enum class FollowMode { off, chase, orbit };

using scene::common_time_span;
using scene::position_at;
using scene::TimeSpan;
using scene::TrackPosition;

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

}  // namespace trailray::ui
