#include "scene/film/camera_path.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "geo/wgs84.hpp"
#include "scene/film/film_timing.hpp"
#include "track/io/parse_util.hpp"

namespace trailray::scene {
namespace {

// A camera keyframe becomes a look at the point this far ahead of it.
constexpr double kCameraLookDistanceM = 1000.0;

std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
    if (j > i) words.push_back(line.substr(i, j - i));
    i = j;
  }
  return words;
}

double catmull_rom(double p0, double p1, double p2, double p3, double t) {
  const double t2 = t * t, t3 = t2 * t;
  return 0.5 * (2.0 * p1 + (-p0 + p2) * t + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * t2 +
                (-p0 + 3.0 * p1 - 3.0 * p2 + p3) * t3);
}

// The heading nearest to `previous` among heading + k * 360 (so interpolation turns the short way).
double unwrap(double heading, double previous) { return heading + 360.0 * std::round((previous - heading) / 360.0); }

}  // namespace

Result<std::vector<CameraKeyframe>> parse_camera_path(std::string_view text, const std::string& name) {
  std::vector<CameraKeyframe> keys;
  std::size_t line_no = 0;
  const auto fail = [&](const std::string& why) {
    return Result<std::vector<CameraKeyframe>>{std::nullopt, fmt::format("{}:{}: {}", name, line_no, why)};
  };
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    ++line_no;
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    const std::vector<std::string_view> w = words_of(track::trim(line));
    if (w.empty()) continue;
    CameraKeyframe key;
    const Result<double> when = parse_film_duration(w[0]);
    if (w[0] == "0" || w[0] == "0s")
      key.film_s = 0.0;
    else if (!when.ok())
      return fail(fmt::format("'{}' is not a time in the film such as 0, 12.5s or 1m30s", w[0]));
    else
      key.film_s = *when.value;
    if (!keys.empty() && !(key.film_s > keys.back().film_s))
      return fail(
          fmt::format("{} s comes after {} s: keyframes must be in rising order", key.film_s, keys.back().film_s));
    if (w.size() == 3 && w[1] == "camera") {
      const Result<CameraPlacement> c = parse_camera_option(w[2]);
      if (!c.ok()) return fail(c.error);
      const glm::dvec3 position = ecef_from(c.value->position);
      const EnuAxes enu = enu_axes_at(c.value->position.lat_deg, c.value->position.lon_deg);
      const double h = glm::radians(c.value->heading_deg), p = glm::radians(c.value->pitch_deg);
      const glm::dvec3 forward =
          std::cos(p) * (std::sin(h) * enu.east + std::cos(h) * enu.north) + std::sin(p) * enu.up;
      // Looking at a point ahead of the camera, from the same heading and pitch (the frame tilts
      // by under a hundredth of a degree over the distance: not visible).
      key.look = {position + forward * kCameraLookDistanceM, c.value->heading_deg, c.value->pitch_deg,
                  kCameraLookDistanceM};
    } else if (w.size() == 6 && w[1] == "look-at") {
      const Result<GeoPosition> at = parse_look_at_option(w[2]);
      if (!at.ok()) return fail(at.error);
      const auto distance = track::parse_double(w[3]), heading = track::parse_double(w[4]),
                 pitch = track::parse_double(w[5]);
      if (!distance || !(*distance > 0.0)) return fail(fmt::format("'{}' is not a distance in metres above 0", w[3]));
      if (!heading) return fail(fmt::format("'{}' is not a heading in degrees", w[4]));
      if (!pitch || std::abs(*pitch) > 90.0) return fail(fmt::format("'{}' is not a pitch within -90..90", w[5]));
      key.look = {ecef_from(*at.value), *heading, *pitch, *distance};
    } else {
      return fail(
          "expected 'WHEN camera LAT,LON,ALT,HEADING,PITCH' or 'WHEN look-at LAT,LON,ALT DISTANCE HEADING PITCH'");
    }
    keys.push_back(key);
  }
  if (keys.empty()) {
    line_no = std::max<std::size_t>(line_no, 1);
    return fail("no keyframe");
  }
  return {std::move(keys), {}};
}

FilmLook camera_path_look(const std::vector<CameraKeyframe>& keys, double film_s) {
  if (film_s <= keys.front().film_s) return keys.front().look;
  if (film_s >= keys.back().film_s) return keys.back().look;
  std::size_t i = 0;
  while (keys[i + 1].film_s < film_s) ++i;
  const auto at = [&](long k) -> const FilmLook& {
    return keys[static_cast<std::size_t>(std::clamp(k, 0L, static_cast<long>(keys.size()) - 1))].look;
  };
  const long k = static_cast<long>(i);
  const FilmLook &a = at(k - 1), &b = at(k), &c = at(k + 1), &d = at(k + 2);
  const double t = (film_s - keys[i].film_s) / (keys[i + 1].film_s - keys[i].film_s);
  FilmLook out;
  for (int axis = 0; axis < 3; ++axis)
    out.target[axis] = catmull_rom(a.target[axis], b.target[axis], c.target[axis], d.target[axis], t);
  out.distance_m = std::max(1.0, catmull_rom(a.distance_m, b.distance_m, c.distance_m, d.distance_m, t));
  const double hb = b.heading_deg, hc = unwrap(c.heading_deg, hb), ha = unwrap(a.heading_deg, hb),
               hd = unwrap(d.heading_deg, hc);
  out.heading_deg = std::fmod(catmull_rom(ha, hb, hc, hd, t) + 720.0, 360.0);
  out.pitch_deg = std::clamp(catmull_rom(a.pitch_deg, b.pitch_deg, c.pitch_deg, d.pitch_deg, t), -90.0, 90.0);
  return out;
}

}  // namespace trailray::scene
