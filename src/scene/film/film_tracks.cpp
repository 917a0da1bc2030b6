#include "scene/film/film_tracks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "geo/wgs84.hpp"
#include "scene/film/film_timing.hpp"

namespace trailray::scene {
namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

float lerp_value(const std::vector<float>& v, std::size_t i, double f) {
  if (v.empty()) return 0.0f;
  if (f <= 0.0 || i + 1 >= v.size()) return v[i];
  return static_cast<float>(v[i] + (v[i + 1] - v[i]) * f);
}

// A track as drawn, without the numbers a frame does not need.
Track drawn_copy(const Track& t) {
  Track d;
  d.name = "";  // the marker carries the name: no label at the trail's start too
  d.source = t.source;
  d.geometry = t.geometry;
  d.visible = t.visible;
  d.color_srgb = t.color_srgb;
  d.by_value = t.by_value;
  d.is_route = t.is_route;
  return d;
}

}  // namespace

Result<TrailMode> parse_trail_mode(std::string_view text) {
  if (text == "all") return {TrailMode{TrailKind::all, 0.0}, {}};
  if (text == "past") return {TrailMode{TrailKind::past, 0.0}, {}};
  const Result<double> tail = parse_film_duration(text);
  if (!tail.ok()) return {std::nullopt, fmt::format("--trail: '{}' is not all, past or a duration such as 10m", text)};
  return {TrailMode{TrailKind::tail, *tail.value}, {}};
}

TrackGeometry slice_geometry(const Track& t, const TrackPosition& from, const TrackPosition& to) {
  TrackGeometry out;
  const std::size_t n = t.point_count();
  for (std::size_t s = 0; s < t.geometry.segments.size() && s < t.segment_first.size(); ++s) {
    const std::size_t first = t.segment_first[s];
    const std::size_t end = s + 1 < t.segment_first.size() ? t.segment_first[s + 1] : n;
    if (end <= from.point || first > to.point) continue;
    const TrackPolyline& line = t.geometry.segments[s];
    TrackPolyline cut;
    const auto push = [&](const glm::dvec3& p, std::size_t local, double f) {
      cut.points_ecef.push_back(p);
      if (!line.values.empty()) cut.values.push_back(lerp_value(line.values, local, f));
      if (!line.heights_above_ground_m.empty())
        cut.heights_above_ground_m.push_back(lerp_value(line.heights_above_ground_m, local, f));
    };
    std::size_t i = first;
    if (from.point >= first) {  // the cut starts inside this segment
      push(from.ecef, from.point - first, from.fraction);
      i = from.point + 1;
    }
    const std::size_t last = std::min(to.point, end - 1);
    for (; i <= last; ++i) push(line.points_ecef[i - first], i - first, 0.0);
    if (to.point < end && to.fraction > 0.0) push(to.ecef, to.point - first, to.fraction);
    if (cut.points_ecef.size() >= 2) out.segments.push_back(std::move(cut));
  }
  return out;
}

glm::vec3 ghost_color(const glm::vec3& srgb) { return glm::mix(srgb, glm::vec3(0.82f), 0.6f); }

FilmTracks::FilmTracks(const TrackSet& source, const WaypointSet& waypoints, TrailMode mode, double neutral_ground_m)
    : source_(source), file_waypoints_(waypoints), mode_(mode), neutral_ground_m_(neutral_ground_m) {
  for (const Track& t : source.tracks()) {
    trail_of_.push_back(drawn_.size());
    drawn_.add(drawn_copy(t));
    future_of_.push_back(kNone);
    if (mode_.kind == TrailKind::all && !t.timed_points.empty() && !t.is_route) {
      Track future = drawn_copy(t);
      future.color_srgb = ghost_color(t.color_srgb);
      future.by_value = false;
      future_of_.back() = drawn_.size();
      drawn_.add(std::move(future));
    }
  }
  positions_.resize(source.size());
}

double FilmTracks::track_time(std::size_t i, double film_time) const {
  return film_time + (i < offsets_.size() ? offsets_[i] : 0.0);
}

void FilmTracks::set_time(double film_time) {
  waypoints_.points = file_waypoints_.points;
  for (std::size_t i = 0; i < source_.size(); ++i) {
    const Track& t = source_[i];
    const double time = track_time(i, film_time);
    const TrackPosition now = position_at(t, time);
    positions_[i] = now;
    if (!now.valid || t.is_route) continue;  // drawn whole, no marker
    const std::size_t last = t.point_count() - 1;
    const TrackPosition start{true, true, 0, 0.0, t.ecef(0)}, finish{true, true, last, 0.0, t.ecef(last)};
    TrackPosition from = start;
    if (mode_.kind == TrailKind::tail) from = position_at(t, time - mode_.tail_s);
    Track& trail = drawn_[trail_of_[i]];
    trail.geometry = slice_geometry(t, from, now);
    trail.bump_revision();
    if (future_of_[i] != kNone) {
      Track& future = drawn_[future_of_[i]];
      future.geometry = slice_geometry(t, now, finish);
      future.bump_revision();
    }
    // The marker: a pin from the ground below up to the current position, named after the track.
    Waypoint marker;
    marker.name = t.name;
    marker.source = t.source;
    marker.priority = 1000;  // the followed names win over the files' waypoints
    marker.marker_ecef = now.ecef;
    const geo::Geodetic g = geo::geodetic_from_ecef(now.ecef);
    marker.lat_deg = g.lat_deg;
    marker.lon_deg = g.lon_deg;
    marker.ele_m = g.height_m;
    double ground = std::numeric_limits<double>::quiet_NaN();
    if (now.point < t.ground_m.size()) {
      ground = t.ground_m[now.point];
      if (now.fraction > 0.0 && now.point + 1 < t.ground_m.size())
        ground += (t.ground_m[now.point + 1] - ground) * now.fraction;
    }
    if (!std::isfinite(ground)) ground = std::isfinite(neutral_ground_m_) ? neutral_ground_m_ : g.height_m;
    marker.ground_m = ground;
    marker.ground_ecef = geo::ecef_from_geodetic(g.lat_deg, g.lon_deg, std::min(ground, g.height_m));
    waypoints_.points.push_back(std::move(marker));
  }
  ++waypoints_.revision;
}

}  // namespace trailray::scene
