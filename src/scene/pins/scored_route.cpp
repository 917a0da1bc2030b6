#include "scene/pins/scored_route.hpp"

#include <fmt/format.h>

namespace trailray::scene {

namespace sc = track::scoring;

namespace {

const sc::TypeResult* best_of(const sc::ScoreResult& r) {
  if (r.best < 0 || static_cast<std::size_t>(r.best) >= r.by_type.size()) return nullptr;
  return &r.by_type[static_cast<std::size_t>(r.best)];
}

bool is_closed(const sc::TypeResult& t) { return t.closing >= 0.0; }

// As `trailray score` names them: start, TP1.., finish for a free distance; TP1.. otherwise.
std::string turnpoint_name(const sc::TypeResult& t, std::size_t i) {
  const bool free = !is_closed(t);
  if (free && i == 0) return "start";
  if (free && i + 1 == t.points.size()) return "finish";
  return fmt::format("TP{}", free ? i : i + 1);
}

track::TrackPoint ground_point(double lat, double lon) {
  track::TrackPoint p;
  p.lat = lat;
  p.lon = lon;
  return p;  // no elevation: placed on the terrain (or the neutral ground)
}

}  // namespace

std::string scored_route_name(const sc::ScoreResult& result) {
  const sc::TypeResult* best = best_of(result);
  if (best == nullptr) return fmt::format("no score ({})", result.rules);
  return fmt::format("{} {:.2f} pts, {}", best->type.name, best->score, result.rules);
}

track::TrackFile scored_route_file(const sc::ScoreResult& result, const std::vector<sc::Fix>& fixes) {
  track::TrackFile file;
  const sc::TypeResult* best = best_of(result);
  if (best == nullptr || best->positions.empty()) return file;
  track::Route legs;
  legs.name = scored_route_name(result);
  for (const auto& [lat, lon] : best->positions) legs.points.push_back(ground_point(lat, lon));
  if (is_closed(*best)) legs.points.push_back(legs.points.front());
  file.routes.push_back(std::move(legs));

  const auto fix_at = [&fixes](int i) -> const sc::Fix* {
    return i >= 0 && static_cast<std::size_t>(i) < fixes.size() ? &fixes[static_cast<std::size_t>(i)] : nullptr;
  };
  const sc::Fix* in = fix_at(best->closing_in);
  const sc::Fix* out = fix_at(best->closing_out);
  if (is_closed(*best) && in != nullptr && out != nullptr && (in->lat != out->lat || in->lon != out->lon)) {
    track::Route gap;
    gap.name = fmt::format("closing {:.2f} km", best->closing);
    gap.points = {ground_point(in->lat, in->lon), ground_point(out->lat, out->lon)};
    file.routes.push_back(std::move(gap));
  }

  for (std::size_t i = 0; i < best->positions.size(); ++i) {
    track::Waypoint w;
    w.point = ground_point(best->positions[i].first, best->positions[i].second);
    const std::string name = turnpoint_name(*best, i);
    // The leg leaving this point (a closed route's last leg goes back to TP1).
    w.name = i < best->legs.size() ? fmt::format("{} {:.2f} km", name, best->legs[i]) : name;
    w.description = fmt::format("{} of {}", name, scored_route_name(result));
    if (i < best->points.size()) {
      if (const sc::Fix* f = fix_at(best->points[i])) w.point.time = f->time;
    }
    file.waypoints.push_back(std::move(w));
  }
  return file;
}

ScoredRouteDrawing build_scored_route(const sc::ScoreResult& result, const std::vector<sc::Fix>& fixes,
                                      const std::string& source, const TrackStyle& style,
                                      const TrackBuildOptions& options, const WaypointBuildOptions& placing,
                                      Diagnostics& diagnostics) {
  ScoredRouteDrawing out;
  const std::vector<LoadedTrackFile> files{{source, scored_route_file(result, fixes)}};
  // Routes are never coloured by value nor by --color: the style's colours do not apply.
  TrackStyle route_style = style;
  route_style.colors.clear();
  route_style.color_by = track::ColorMetric::solid;
  route_style.curtain = false;
  // Its legs are routes, which build_tracks never smooths: the corners stay on the turnpoints.
  out.tracks = build_tracks(files, route_style, options, diagnostics);
  for (std::size_t i = 0; i < out.tracks.size(); ++i)
    out.tracks[i].color_srgb = i == 0 ? kScoredLegsColor : kClosingGapColor;
  out.waypoints = build_waypoints(files.front().file.waypoints, source, WaypointKind::Waypoint, placing);
  for (Waypoint& w : out.waypoints) w.priority = kWaypointPriority + 1;  // the score's labels before the files'
  return out;
}

}  // namespace trailray::scene
