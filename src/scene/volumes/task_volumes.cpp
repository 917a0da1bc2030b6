#include "scene/volumes/task_volumes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "geo/local_frame.hpp"
#include "scene/tracks/track_files.hpp"
#include "track/task/earth.hpp"

namespace trailray::scene {

namespace tt = track::task;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNoFlightCeilingAboveGroundM = 1500.0;

track::TrackPoint ground_point(double lat, double lon) {
  track::TrackPoint p;
  p.lat = lat;
  p.lon = lon;
  return p;
}

// A thin rectangle across the last leg into the goal, through its centre.
std::vector<geo::LatLon> goal_line_ring(const tt::Task& task, const tt::TaskDistances& d, std::size_t goal) {
  const tt::Turnpoint& g = task.turnpoints[goal];
  const geo::LocalFrame frame(g.lat, g.lon, 0.0);
  double ve = 1.0, vn = 0.0;  // along the leg
  for (std::size_t i = goal; i-- > 0;) {
    const geo::Enu p = frame.to_local(d.optimised.points[i].lat, d.optimised.points[i].lon, 0.0);
    const double len = std::hypot(p.east, p.north);
    if (len > 1.0) {
      ve = -p.east / len;
      vn = -p.north / len;
      break;
    }
  }
  const double half = g.radius_m, thick = std::max(2.0, g.radius_m / 100.0);
  const double ue = -vn, un = ve;  // across the leg
  std::vector<geo::LatLon> ring;
  for (const auto& [a, b] :
       {std::pair{-half, -thick}, std::pair{half, -thick}, std::pair{half, thick}, std::pair{-half, thick}}) {
    double lat = 0, lon = 0, h = 0;
    frame.to_geodetic({a * ue + b * ve, a * un + b * vn, 0.0}, lat, lon, h);
    ring.push_back({lat, lon});
  }
  return ring;
}

}  // namespace

glm::vec3 task_role_color(tt::Role role) {
  switch (role) {
    case tt::Role::Takeoff:
      return {0.75f, 0.75f, 0.75f};
    case tt::Role::Sss:
      return {0.1f, 0.8f, 0.2f};
    case tt::Role::Turnpoint:
      return {0.2f, 0.45f, 1.0f};
    case tt::Role::Ess:
      return {1.0f, 0.6f, 0.0f};
    case tt::Role::Goal:
      return {0.95f, 0.1f, 0.1f};
  }
  return {0.2f, 0.45f, 1.0f};
}

std::vector<geo::LatLon> task_ring(const tt::Task& task, const geo::LatLon& centre, double radius_m) {
  // A chord of angle a strays r (1 - cos(a / 2)) from the circle: at most 2 m.
  const double max_angle = 2.0 * std::acos(std::clamp(1.0 - 2.0 / std::max(radius_m, 1.0), -1.0, 1.0));
  const int n = std::clamp(static_cast<int>(std::ceil(2.0 * kPi / max_angle)), 96, 1440);
  const tt::Earth earth(task.earth);
  std::vector<geo::LatLon> ring;
  ring.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) ring.push_back(earth.destination(centre, 360.0 * k / n, radius_m));
  return ring;
}

VolumeSet task_volumes(const tt::Task& task, const tt::TaskDistances& d, const std::string& source,
                       double ceiling_msl_m) {
  VolumeSet set;
  const int goal = task.goal_index();
  for (std::size_t i = 0; i < task.turnpoints.size(); ++i) {
    const tt::Turnpoint& t = task.turnpoints[i];
    if (t.radius_m <= 0.0 || task.waypoints_only) continue;  // a place, not a cylinder
    Volume v;
    v.kind = VolumeKind::TaskCylinder;
    v.name = fmt::format("{} ({}, {:.0f} m)", t.name, tt::role_name(t.role), t.radius_m);
    v.category = tt::role_name(t.role);
    v.source = source;
    const bool line = static_cast<int>(i) == goal && task.goal_type == tt::GoalType::Line;
    v.boundary = line && d.optimised.points.size() == task.turnpoints.size()
                     ? goal_line_ring(task, d, i)
                     : task_ring(task, {t.lat, t.lon}, t.radius_m);
    v.floor = {VolumeHeightReference::Ground, 0.0, false};
    v.ceiling = std::isnan(ceiling_msl_m)
                    ? VolumeLimit{VolumeHeightReference::Ground, kNoFlightCeilingAboveGroundM, false}
                    : VolumeLimit{VolumeHeightReference::Msl, ceiling_msl_m, false};
    v.color_srgb = task_role_color(t.role);
    v.opacity = t.role == tt::Role::Takeoff ? 0.12f : 0.22f;
    set.volumes.push_back(std::move(v));
  }
  set.revision = 1;
  return set;
}

track::TrackFile task_route_file(const tt::Task& task, const tt::TaskDistances& d) {
  track::TrackFile file;
  if (task.turnpoints.empty() || d.optimised.points.size() != task.turnpoints.size()) return file;
  track::Route route;
  route.name = fmt::format("task {:.1f} km optimised ({:.1f} km through centres)", d.optimised.distance_m / 1000.0,
                           d.centre_m / 1000.0);
  for (const geo::LatLon& p : d.optimised.points) {
    // Repeated touch points (nested or repeated cylinders) add nothing to draw.
    if (!route.points.empty() && route.points.back().lat == p.lat && route.points.back().lon == p.lon) continue;
    route.points.push_back(ground_point(p.lat, p.lon));
  }
  if (route.points.size() >= 2) file.routes.push_back(std::move(route));
  for (std::size_t i = 0; i < task.turnpoints.size(); ++i) {
    const tt::Turnpoint& t = task.turnpoints[i];
    // A turnpoint repeated at once (a cylinder inside another around one centre) gets one pin.
    if (i > 0 && task.turnpoints[i - 1].lat == t.lat && task.turnpoints[i - 1].lon == t.lon) continue;
    track::Waypoint w;
    w.point = ground_point(t.lat, t.lon);
    w.name = t.name;
    w.description = fmt::format("{} {}, {:.0f} m{}{}", tt::role_name(t.role), i + 1, t.radius_m,
                                t.description.empty() ? "" : ": ", t.description);
    file.waypoints.push_back(std::move(w));
  }
  return file;
}

TaskDrawing build_task_drawing(const tt::Task& task, const tt::TaskDistances& distances, const std::string& source,
                               double ceiling_msl_m, const TrackStyle& style, const TrackBuildOptions& options,
                               const WaypointBuildOptions& placing, Diagnostics& diagnostics) {
  TaskDrawing out;
  const std::vector<LoadedTrackFile> files{{source, task_route_file(task, distances)}};
  TrackStyle route_style = style;
  route_style.colors.clear();
  route_style.color_by = track::ColorMetric::solid;
  route_style.curtain = false;
  TrackBuildOptions exact = options;
  exact.analysis.clean.smooth = false;  // the route's corners are exact places
  out.tracks = build_tracks(files, route_style, exact, diagnostics);
  for (Track& t : out.tracks) t.color_srgb = kTaskRouteColor;
  out.waypoints = build_waypoints(files.front().file.waypoints, source, WaypointKind::Waypoint, placing);
  for (Waypoint& w : out.waypoints) w.priority = kWaypointPriority + 1;
  out.volumes = task_volumes(task, distances, source, ceiling_msl_m);
  return out;
}

double highest_recorded_m(const TrackSet& tracks) {
  double top = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    if (tracks[i].is_route) continue;
    for (double h : tracks[i].altitude_m)
      if (!std::isnan(h) && !(h <= top)) top = h;
  }
  return top;
}

}  // namespace trailray::scene
