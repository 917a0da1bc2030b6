#include "scene/film/film_camera.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geo/wgs84.hpp"

namespace trailray::scene {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadPerDeg = kPi / 180.0;
constexpr double kSteepestPitchDeg = -88.0;
constexpr double kRaiseStepDeg = 6.0;
// Points along the line of sight from the camera to the target checked against the terrain
// (fractions of the way); the last stops short of the target, which may lie on the ground.
constexpr double kSightFractions[] = {0.0, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45,
                                      0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85, 0.9};

glm::dvec3 forward_at(const glm::dvec3& target, double heading_deg, double pitch_deg) {
  const geo::Geodetic g = geo::geodetic_from_ecef(target);
  const EnuAxes enu = enu_axes_at(g.lat_deg, g.lon_deg);
  const double h = heading_deg * kRadPerDeg, p = pitch_deg * kRadPerDeg;
  return std::cos(p) * (std::sin(h) * enu.east + std::cos(h) * enu.north) + std::sin(p) * enu.up;
}

template <class T>
std::vector<T> moving_average(const std::vector<T>& v, int half) {
  if (v.empty() || half <= 0) return v;
  const long n = static_cast<long>(v.size());
  std::vector<T> out(v.size());
  for (long i = 0; i < n; ++i) {
    const long a = std::max(0L, i - half), b = std::min(n - 1, i + half);
    T sum{};
    for (long j = a; j <= b; ++j) sum += v[static_cast<std::size_t>(j)];
    out[static_cast<std::size_t>(i)] = sum / static_cast<double>(b - a + 1);
  }
  return out;
}

std::vector<double> moving_min(const std::vector<double>& v, int half) {
  const long n = static_cast<long>(v.size());
  std::vector<double> out(v.size());
  for (long i = 0; i < n; ++i) {
    double m = v[static_cast<std::size_t>(i)];
    for (long j = std::max(0L, i - half); j <= std::min(n - 1, i + half); ++j)
      m = std::min(m, v[static_cast<std::size_t>(j)]);
    out[static_cast<std::size_t>(i)] = m;
  }
  return out;
}

// Whether each look's camera clears the terrain and sees its target, in one batch of heights.
std::vector<bool> clear_of_terrain(const std::vector<FilmLook>& looks, double clearance_m, const HeightBatch& heights) {
  constexpr std::size_t k = std::size(kSightFractions);
  std::vector<geo::LatLon> points;
  std::vector<double> needed;  // the height each point must be above
  points.reserve(looks.size() * k);
  for (const FilmLook& look : looks) {
    const glm::dvec3 camera = camera_position(look);
    for (double f : kSightFractions) {
      const geo::Geodetic g = geo::geodetic_from_ecef(camera + (look.target - camera) * f);
      points.push_back({g.lat_deg, g.lon_deg});
      needed.push_back(g.height_m - (f == 0.0 ? clearance_m : 0.0));
    }
  }
  const std::vector<double> ground = heights(points);
  std::vector<bool> clear(looks.size(), true);
  for (std::size_t i = 0; i < points.size() && i < ground.size(); ++i)
    if (std::isfinite(ground[i]) && ground[i] > needed[i]) clear[i / k] = false;
  return clear;
}

// Steepens each look until it is clear (or as steep as it goes), then spreads the raise over
// the neighbouring frames: the steepest pitch over a window, averaged over it, so the camera
// rises before an obstacle and sinks after it. A last pass steepens any look still unclear.
void raise_over_terrain(std::vector<FilmLook>& looks, const FilmCameraSettings& s, const HeightBatch& heights) {
  if (!heights || looks.empty()) return;
  std::vector<double> pitch(looks.size());
  for (std::size_t i = 0; i < looks.size(); ++i) pitch[i] = looks[i].pitch_deg;
  std::vector<std::size_t> todo(looks.size());
  for (std::size_t i = 0; i < todo.size(); ++i) todo[i] = i;
  const auto steepen = [&](std::vector<double>& pitches) {
    while (!todo.empty()) {
      std::vector<FilmLook> trial;
      for (std::size_t i : todo) {
        trial.push_back(looks[i]);
        trial.back().pitch_deg = pitches[i];
      }
      const std::vector<bool> clear = clear_of_terrain(trial, s.clearance_m, heights);
      std::vector<std::size_t> next;
      for (std::size_t j = 0; j < todo.size(); ++j) {
        double& p = pitches[todo[j]];
        if (clear[j] || p <= kSteepestPitchDeg) continue;
        p = std::max(kSteepestPitchDeg, p - kRaiseStepDeg);
        next.push_back(todo[j]);
      }
      todo = std::move(next);
    }
  };
  steepen(pitch);
  pitch = moving_average(moving_min(pitch, s.raise_window), s.raise_window);
  todo.resize(looks.size());
  for (std::size_t i = 0; i < looks.size(); ++i) todo[i] = i;
  steepen(pitch);
  for (std::size_t i = 0; i < looks.size(); ++i) looks[i].pitch_deg = pitch[i];
}

}  // namespace

glm::dvec3 camera_position(const FilmLook& look) {
  return look.target - look.distance_m * forward_at(look.target, look.heading_deg, look.pitch_deg);
}

std::vector<FilmLook> follow_looks(std::span<const double> times, const PositionAt& position,
                                   const FilmCameraSettings& s, const HeightBatch& heights) {
  constexpr int kSamples = 8;  // each side of a frame's time, for both averages
  const double step = std::max(s.position_window_s, 1e-3) / kSamples;
  const double heading_step = std::max(s.heading_window_s, 1e-3) / kSamples;
  const double reach = heading_step;  // the direction of travel: from `reach` before to `reach` after
  std::vector<FilmLook> looks(times.size());
  // The direction as a horizontal unit vector (east, north), averaged as vectors before it
  // becomes an angle, so a turn through north does not spin the camera.
  std::vector<glm::dvec2> along(times.size(), glm::dvec2(0.0));
  for (std::size_t i = 0; i < times.size(); ++i) {
    glm::dvec3 sum(0.0);
    for (int k = -kSamples; k <= kSamples; ++k) sum += position(times[i] + k * step);
    const glm::dvec3 target = sum / static_cast<double>(2 * kSamples + 1);
    const geo::Geodetic g = geo::geodetic_from_ecef(target);
    const EnuAxes enu = enu_axes_at(g.lat_deg, g.lon_deg);
    glm::dvec2 direction(0.0);
    for (int k = -kSamples; k <= kSamples; ++k) {
      const double t = times[i] + k * heading_step;
      const glm::dvec3 d = position(t + reach) - position(t - reach);
      const glm::dvec2 h(glm::dot(d, enu.east), glm::dot(d, enu.north));
      if (glm::length(h) > 1e-3) direction += glm::normalize(h);
    }
    along[i] = direction;
    looks[i] = {target, 0.0, s.pitch_deg, s.distance_m};
  }
  // Where the track stands still over a whole window: the heading before, else the first known.
  std::size_t first_known = along.size();
  for (std::size_t i = 0; i < along.size() && first_known == along.size(); ++i)
    if (glm::length(along[i]) > 1e-6) first_known = i;
  double heading =
      first_known < along.size() ? std::atan2(along[first_known].x, along[first_known].y) / kRadPerDeg : 0.0;
  for (std::size_t i = 0; i < looks.size(); ++i) {
    if (glm::length(along[i]) > 1e-6) heading = std::atan2(along[i].x, along[i].y) / kRadPerDeg;
    looks[i].heading_deg = std::fmod(heading + 360.0, 360.0);
  }
  raise_over_terrain(looks, s, heights);
  return looks;
}

std::vector<FilmLook> orbit_looks(const glm::dvec3& centre, std::size_t frames, double start_heading_deg,
                                  const FilmCameraSettings& s, const HeightBatch& heights) {
  std::vector<FilmLook> looks(frames);
  for (std::size_t i = 0; i < frames; ++i) {
    const double turn = frames > 1 ? 360.0 * static_cast<double>(i) / static_cast<double>(frames) : 0.0;
    looks[i] = {centre, std::fmod(start_heading_deg + turn, 360.0), s.pitch_deg, s.distance_m};
  }
  raise_over_terrain(looks, s, heights);
  return looks;
}

Camera camera_of(const FilmLook& look, const Lens& lens, double ground_m) {
  const geo::Geodetic t = geo::geodetic_from_ecef(look.target);
  const LookAt at{{t.lat_deg, t.lon_deg, t.height_m}, look.distance_m, look.heading_deg, look.pitch_deg};
  const double camera_height = geo::geodetic_from_ecef(camera_position(look)).height_m;
  const double ground = std::isfinite(ground_m) ? ground_m : camera_height - 25.0;
  Result<Camera> camera = camera_looking_at(at, lens, ground);
  if (!camera.ok()) throw std::invalid_argument("film camera: " + camera.error);
  return *camera.value;
}

}  // namespace trailray::scene
