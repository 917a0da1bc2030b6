// The replay: one clock for every track (where a track is at a time: scene/tracks/replay_position).
#include <algorithm>
#include <cmath>

#include "ui/replay.hpp"

namespace trailray::ui {

void ReplayClock::set_span(const TimeSpan& span) {
  span_ = TimeSpan{span.start, std::max(span.start, span.end)};
  if (!(time_ >= span_->start && time_ <= span_->end)) time_ = span_->start;
}

double ReplayClock::fraction() const {
  if (!span_ || span_->end <= span_->start) return 0.0;
  return (time_ - span_->start) / (span_->end - span_->start);
}

void ReplayClock::play() {
  if (!span_) return;
  if (time_ >= span_->end) time_ = span_->start;
  playing_ = true;
}

void ReplayClock::set_speed(double speed) {
  if (!std::isfinite(speed)) return;
  speed_ = std::clamp(speed, kMinSpeed, kMaxSpeed);
}

void ReplayClock::seek(double time) {
  if (!span_ || std::isnan(time)) return;
  time_ = std::clamp(time, span_->start, span_->end);
}

void ReplayClock::seek_fraction(double f) {
  if (!span_ || std::isnan(f)) return;
  seek(span_->start + std::clamp(f, 0.0, 1.0) * (span_->end - span_->start));
}

void ReplayClock::advance(double wall_seconds) {
  if (!playing_ || !span_ || !(wall_seconds > 0.0)) return;
  time_ = std::min(span_->end, time_ + wall_seconds * speed_);
  if (time_ >= span_->end) playing_ = false;
}

}  // namespace trailray::ui
