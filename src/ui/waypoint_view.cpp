#include "ui/waypoint_view.hpp"

#include <fmt/format.h>

#include <cmath>
#include <ctime>
#include <limits>

#include "geo/wgs84.hpp"
#include "ui/tooltip.hpp"

namespace trailray::ui {
namespace {

constexpr const char* kMissingText = "\u2014";  // em dash

std::string metres(double v) { return std::isfinite(v) ? fmt::format("{:.0f} m", v) : kMissingText; }

}  // namespace

std::vector<ChartWaypoint> chart_waypoints(const scene::Track& track, const scene::WaypointSet& waypoints,
                                           double reach_m) {
  std::vector<ChartWaypoint> out;
  for (std::size_t w = 0; w < waypoints.points.size(); ++w) {
    const scene::Waypoint& p = waypoints.points[w];
    // Thermal markers: the chart shades the thermals instead (flight_panel.hpp).
    if (!p.visible || p.kind == scene::WaypointKind::Thermal) continue;
    // Measured at the ground, so a waypoint recorded high above a flight's track still finds it.
    std::optional<std::size_t> best;
    double best_m = reach_m;
    for (std::size_t i = 0; i < track.point_count(); ++i) {
      const double d = glm::length(track.ecef(i) - p.ground_ecef);
      if (d <= best_m) {
        best_m = d;
        best = i;
      }
    }
    if (best) out.push_back({w, *best});
  }
  return out;
}

std::optional<glm::dvec2> pin_screen_position(const scene::Camera& camera, const scene::Waypoint& waypoint,
                                              const scene::PinStyle& style) {
  const auto p = camera.project(waypoint.marker_ecef);
  if (!p) return std::nullopt;
  const bool place = waypoint.kind == scene::WaypointKind::Place;
  // The renderer raises the ball by max(lift px at the marker's depth, lift m) along the vertical.
  const scene::Lens& lens = camera.lens();
  const double pixel_m = 2.0 * std::tan(0.5 * lens.vertical_fov_deg * M_PI / 180.0) / lens.height_px * p->depth_m;
  const double lift =
      std::max((place ? style.place_lift_px : style.lift_px) * pixel_m, place ? style.place_lift_m : style.lift_m);
  const geo::Geodetic g = geo::geodetic_from_ecef(waypoint.marker_ecef);
  const glm::dvec3 up = scene::enu_axes_at(g.lat_deg, g.lon_deg).up;
  const auto q = camera.project(waypoint.marker_ecef + up * lift);
  if (!q) return glm::dvec2(p->x_px, p->y_px);
  return glm::dvec2(q->x_px, q->y_px);
}

int pick_waypoint(const scene::WaypointSet& waypoints, const scene::Camera& camera, const scene::PinStyle& style,
                  double x_px, double y_px, double radius_px) {
  int best = -1;
  double best_px = radius_px;
  for (std::size_t i = 0; i < waypoints.points.size(); ++i) {
    const scene::Waypoint& w = waypoints.points[i];
    if (!w.visible) continue;
    const auto at = pin_screen_position(camera, w, style);
    if (!at) continue;
    const double d = std::hypot(at->x - x_px, at->y - y_px);
    if (d <= best_px) {
      best_px = d;
      best = static_cast<int>(i);
    }
  }
  return best;
}

std::vector<std::string> waypoint_tooltip_lines(const scene::Waypoint& w) {
  std::vector<std::string> out;
  out.push_back(fmt::format("elevation: {}", metres(w.ele_m)));
  if (std::isfinite(w.ground_m)) out.push_back(fmt::format("ground: {}", metres(w.ground_m)));
  if (!w.description.empty()) out.push_back(w.description);
  if (std::isfinite(w.time_unix_s)) out.push_back(fmt::format("time: {}", tooltip_time_text(w.time_unix_s)));
  out.push_back(fmt::format("{}: {}", w.kind == scene::WaypointKind::Place ? "place from" : "file", w.source));
  return out;
}

scene::LookAt look_at_waypoint(const scene::Waypoint& w, double heading_deg, double pitch_deg, double distance_m) {
  const geo::Geodetic g = geo::geodetic_from_ecef(w.marker_ecef);
  return {{g.lat_deg, g.lon_deg, g.height_m}, distance_m, heading_deg, pitch_deg};
}

}  // namespace trailray::ui
