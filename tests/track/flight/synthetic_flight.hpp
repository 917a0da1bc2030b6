#pragma once
// A flight simulator for the flight analysis tests: 1 Hz fixes of a glider flying known legs
// (glides at a set airspeed and sink, circles of a set radius and climb) in a steady wind, with
// ground time before, between and after.

#include <cmath>
#include <numbers>

#include "track/model.hpp"

namespace trailray::track::test {

class SyntheticFlight {
 public:
  // Wind: speed in m/s, blowing FROM `from_deg` (meteorological).
  SyntheticFlight(double wind_speed = 0.0, double wind_from_deg = 0.0) {
    const double to = (wind_from_deg + 180.0) * kRad;
    wind_e_ = wind_speed * std::sin(to);
    wind_n_ = wind_speed * std::cos(to);
  }

  // Standing still on the ground.
  void ground(int seconds) {
    for (int i = 0; i < seconds; ++i) step(0, 0, 0, false);
  }
  // Straight at `airspeed` towards `heading_deg` (of the air track), sinking at `sink` m/s.
  void glide(int seconds, double heading_deg, double airspeed = 10.0, double sink = 1.0) {
    heading_ = heading_deg * kRad;
    for (int i = 0; i < seconds; ++i) step(airspeed * std::sin(heading_), airspeed * std::cos(heading_), -sink, true);
  }
  // Circling at `airspeed` on a circle of `radius` m in the air, right (clockwise) or left.
  void circle(int seconds, bool right, double climb, double radius = 40.0, double airspeed = 10.0) {
    const double omega = (right ? 1.0 : -1.0) * airspeed / radius;  // rad/s, clockwise positive
    for (int i = 0; i < seconds; ++i) {
      // The heading at mid-step, so each step is the chord of the air circle.
      const double h = heading_ + 0.5 * omega;
      step(airspeed * std::sin(h) * chord(omega), airspeed * std::cos(h) * chord(omega), climb, true);
      heading_ += omega;
    }
  }
  // Glides with the air heading swinging +-`swing_deg` every `half_period` s (S-turns).
  void s_turns(int seconds, double heading_deg, double swing_deg, int half_period, double sink = 1.0) {
    for (int i = 0; i < seconds; ++i) {
      const double h = (heading_deg + ((i / half_period) % 2 == 0 ? swing_deg : -swing_deg)) * kRad;
      step(10.0 * std::sin(h), 10.0 * std::cos(h), -sink, true);
    }
  }
  // No fixes for `seconds` while flying straight (a logger gap).
  void gap(int seconds, double heading_deg, double sink = 1.0) {
    const double h = heading_deg * kRad;
    for (int i = 0; i < seconds; ++i) {
      e_ += 10.0 * std::sin(h) + wind_e_;
      n_ += 10.0 * std::cos(h) + wind_n_;
      alt_ -= sink;
      t_ += 1.0;
    }
  }

  double time() const { return t_; }
  double alt() const { return alt_; }
  Track track() const {
    Track t;
    t.segments.push_back(Segment{points_});
    return t;
  }
  const std::vector<TrackPoint>& points() const { return points_; }
  static constexpr double kLat0 = 46.5, kLon0 = 8.0, kT0 = 1.7e9;

 private:
  static constexpr double kRad = std::numbers::pi / 180.0;
  static double chord(double omega) { return omega == 0 ? 1.0 : std::sin(0.5 * omega) / (0.5 * omega); }

  void step(double ve, double vn, double vz, bool airborne) {
    if (points_.empty()) emit();
    e_ += ve + (airborne ? wind_e_ : 0.0);
    n_ += vn + (airborne ? wind_n_ : 0.0);
    alt_ += vz;
    t_ += 1.0;
    emit();
  }
  void emit() {
    TrackPoint p;
    // Local metres to degrees with the sphere of the mean radius: a few km, exact enough.
    constexpr double r = 6371008.8;
    p.lat = kLat0 + n_ / r / kRad;
    p.lon = kLon0 + e_ / (r * std::cos(kLat0 * kRad)) / kRad;
    p.ele = alt_;
    p.time = t_;
    points_.push_back(p);
  }

  double wind_e_ = 0, wind_n_ = 0;
  double e_ = 0, n_ = 0, alt_ = 1000, t_ = kT0, heading_ = 0;
  std::vector<TrackPoint> points_;
};

}  // namespace trailray::track::test
