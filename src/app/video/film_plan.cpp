#include "app/video/film_plan.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "app/drawing/scene_setup.hpp"
#include "geo/wgs84.hpp"
#include "scene/film/camera_path.hpp"
#include "scene/tracks/replay_position.hpp"
#include "terrain/height_sampler.hpp"

namespace trailray::app {
namespace {

constexpr double kDefaultFilmSeconds = 60.0;

template <class T>
T value_or_throw(scene::Result<T> r, const char* option) {
  if (!r.ok()) throw CLI::ValidationError(option, r.error);
  return *r.value;
}

int frames_of(double seconds, double fps) { return std::max(1, static_cast<int>(std::lround(seconds * fps))); }

// The tracks' extent: the middle of their points (ECEF, at mid height) and the diagonal (m).
struct Extent {
  glm::dvec3 centre{0.0};
  double diagonal_m = 0.0;
};
Extent extent_of(const scene::TrackSet& tracks) {
  double lat0 = 90, lat1 = -90, lon0 = 180, lon1 = -180, h0 = 1e9, h1 = -1e9;
  for (const scene::Track& t : tracks.tracks())
    for (const scene::TrackPolyline& line : t.geometry.segments)
      for (const glm::dvec3& p : line.points_ecef) {
        const geo::Geodetic g = geo::geodetic_from_ecef(p);
        lat0 = std::min(lat0, g.lat_deg), lat1 = std::max(lat1, g.lat_deg);
        lon0 = std::min(lon0, g.lon_deg), lon1 = std::max(lon1, g.lon_deg);
        h0 = std::min(h0, g.height_m), h1 = std::max(h1, g.height_m);
      }
  if (lat0 > lat1) return {};
  const glm::dvec3 a = geo::ecef_from_geodetic(lat0, lon0, h0), b = geo::ecef_from_geodetic(lat1, lon1, h1);
  return {geo::ecef_from_geodetic((lat0 + lat1) / 2, (lon0 + lon1) / 2, (h0 + h1) / 2), glm::length(b - a)};
}

// The cameras of the looks, their depth ranges from the ground below each.
std::vector<scene::Camera> cameras_of(const std::vector<scene::FilmLook>& looks, const scene::Lens& lens,
                                      const scene::HeightBatch& ground) {
  std::vector<geo::LatLon> below(looks.size());
  for (std::size_t i = 0; i < looks.size(); ++i) {
    const geo::Geodetic g = geo::geodetic_from_ecef(scene::camera_position(looks[i]));
    below[i] = {g.lat_deg, g.lon_deg};
  }
  const std::vector<double> ground_below = ground(below);
  std::vector<scene::Camera> cameras;
  cameras.reserve(looks.size());
  for (std::size_t i = 0; i < looks.size(); ++i) cameras.push_back(scene::camera_of(looks[i], lens, ground_below[i]));
  return cameras;
}

}  // namespace

FilmClock plan_film_clock(const VideoArgs& a, const scene::TrackSet& tracks) {
  FilmClock clock;
  clock.offsets.assign(tracks.size(), 0.0);
  std::optional<scene::TimeSpan> span;
  if (a.align == "start") {
    // Every track from its own start: the film's clock is the followed track's (else the first
    // timed one's), and each other track is shifted so that all start together.
    std::optional<double> reference;
    const std::size_t followed = static_cast<std::size_t>(a.follow - 1);
    if (followed < tracks.size()) reference = tracks[followed].start_time();
    for (std::size_t i = 0; i < tracks.size() && !reference; ++i) reference = tracks[i].start_time();
    for (std::size_t i = 0; i < tracks.size() && reference; ++i) {
      const auto s = tracks[i].start_time(), e = tracks[i].end_time();
      if (!s || !e) continue;
      clock.offsets[i] = *s - *reference;
      const scene::TimeSpan own{*reference, *reference + (*e - *s)};
      span = span ? scene::TimeSpan{span->start, std::max(span->end, own.end)} : own;
    }
  } else {
    span = scene::common_time_span(tracks);
  }
  if (!span) throw std::runtime_error("no track has times: a film replays tracks by their times");
  scene::TimeSpan part = *span;
  if (!a.from.empty()) part.start = value_or_throw(scene::parse_film_instant(a.from, *span, "--from"), "--from");
  if (!a.to.empty()) part.end = value_or_throw(scene::parse_film_instant(a.to, *span, "--to"), "--to");
  if (!(part.end > part.start))
    throw CLI::ValidationError("--from/--to", "the part filmed is empty (--to must come after --from)");
  scene::FilmLength length;
  if (!a.speed.empty())
    length.speed = value_or_throw(scene::parse_film_speed(a.speed), "--speed");
  else
    length.duration_s =
        a.duration.empty() ? kDefaultFilmSeconds : value_or_throw(scene::parse_film_duration(a.duration), "--duration");
  clock.timing = value_or_throw(scene::make_film_timing(part, length, a.fps), "--duration/--speed/--fps");
  return clock;
}

scene::HeightBatch film_heights(terrain::HeightSource* heights, double neutral_ground_m) {
  return [heights, neutral_ground_m](std::span<const geo::LatLon> points) {
    std::vector<double> out(points.size(), neutral_ground_m);
    if (heights != nullptr) {
      // Clearance needs no finer heights than about 20 m apart (zoom 13), and the lines of sight
      // of a whole film cover much ground: a tile source's finest level would load far more.
      terrain::HeightSamplerOptions options;
      options.zoom = std::min(heights->info().max_zoom, 13);
      terrain::HeightSampler sampler(*heights, options);
      out = sampler.sample(points);
      for (double& h : out)
        if (std::isnan(h)) h = neutral_ground_m;
    }
    return out;
  };
}

std::vector<scene::Camera> plan_film_cameras(const VideoArgs& a, FilmCameraMode mode, const scene::Lens& lens,
                                             const FilmClock& clock, const scene::TrackSet& tracks,
                                             double neutral_ground_m, terrain::HeightSource* heights) {
  const std::size_t frames = clock.timing.frames;
  if (mode == FilmCameraMode::fixed) {
    const CameraRequest request = parse_camera_request(a.camera, true);
    return std::vector<scene::Camera>(frames, initial_camera(request, lens, tracks, neutral_ground_m, heights));
  }
  const scene::HeightBatch ground = film_heights(heights, neutral_ground_m);
  if (mode == FilmCameraMode::path) {
    std::ifstream in(a.camera_path, std::ios::binary);
    if (!in) throw std::runtime_error(a.camera_path + ": cannot read the camera path");
    std::stringstream text;
    text << in.rdbuf();
    const auto keys = scene::parse_camera_path(text.str(), a.camera_path);
    if (!keys.ok()) throw std::runtime_error(keys.error);
    std::vector<scene::FilmLook> looks(frames);
    for (std::size_t i = 0; i < frames; ++i)
      looks[i] = scene::camera_path_look(*keys.value, static_cast<double>(i) / clock.timing.fps);
    return cameras_of(looks, lens, ground);
  }
  const Extent extent = extent_of(tracks);
  scene::FilmCameraSettings settings;
  const double fps = clock.timing.fps;
  // Smoothing in replay seconds: half a film second of travel for the point (at most 15 s: the
  // marker stays near the middle), two for the direction (at least 30 s: a glider's circles do
  // not spin the camera).
  const double speed = clock.timing.speed();
  settings.position_window_s = std::clamp(0.5 * speed, 1.0, 15.0);
  settings.heading_window_s = std::max(2.0 * speed, 30.0);
  settings.raise_window = frames_of(1.0, fps);
  std::vector<scene::FilmLook> looks;
  if (mode == FilmCameraMode::follow) {
    settings.distance_m = a.camera.distance_m.value_or(std::clamp(0.08 * extent.diagonal_m, 200.0, 2500.0));
    settings.pitch_deg = a.camera.pitch_deg.value_or(-25.0);
    const std::size_t followed = static_cast<std::size_t>(a.follow - 1);
    const scene::Track& t = tracks.at(followed);
    if (!t.start_time())
      throw CLI::ValidationError("--follow", fmt::format("track {} has no times to follow", a.follow));
    std::vector<double> times(frames);
    for (std::size_t i = 0; i < frames; ++i) times[i] = clock.timing.time_of(i) + clock.offsets[followed];
    looks = scene::follow_looks(
        times, [&t](double time) { return scene::position_at(t, time).ecef; }, settings, ground);
  } else {
    // Orbit at the distance that frames the tracks, around their middle.
    const scene::Camera framed = initial_camera({}, lens, tracks, neutral_ground_m, heights);
    settings.distance_m = a.camera.distance_m.value_or(glm::length(framed.position() - extent.centre));
    settings.pitch_deg = a.camera.pitch_deg.value_or(-35.0);
    looks = scene::orbit_looks(extent.centre, frames, a.camera.heading_deg.value_or(framed.heading_deg()), settings,
                               ground);
  }
  return cameras_of(looks, lens, ground);
}

}  // namespace trailray::app
