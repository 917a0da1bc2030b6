#include "ui/script_session.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "scene/volumes/volume_shapes.hpp"
#include "ui/session_state.hpp"
#include "ui/tooltip.hpp"
#include "ui/track_picking.hpp"
#include "ui/waypoint_view.hpp"

namespace trailray::ui {
namespace {

std::string waypoints_text(const ViewerModel& m, const scene::Camera& camera) {
  std::string out;
  const int chart = m.tracks.empty() ? -1 : std::max(0, m.selected_track);
  std::vector<ChartWaypoint> on_chart;
  if (chart >= 0) on_chart = chart_waypoints(m.tracks[static_cast<std::size_t>(chart)], m.waypoints);
  for (std::size_t i = 0; i < m.waypoints.points.size(); ++i) {
    const scene::Waypoint& w = m.waypoints.points[i];
    std::string where = "behind the camera";
    if (const auto s = pin_screen_position(camera, w, m.settings.style.pins))
      where = fmt::format("pin at {:.1f} {:.1f}", s->x, s->y);
    std::string chart_text = "not on the chart";
    for (const ChartWaypoint& cw : on_chart)
      if (cw.waypoint == i) chart_text = fmt::format("chart point {}", cw.point);
    out += fmt::format("waypoint {} '{}' {} {}{}, {}\n", i, w.name,
                       w.kind == scene::WaypointKind::Place ? "place" : "waypoint", where,
                       w.visible ? "" : " (hidden)", chart_text);
  }
  return out;
}

std::string hover_text(const ViewerModel& m) {
  std::string out;
  const HoverState& h = m.hover;
  if (h.waypoint >= 0 && h.waypoint < static_cast<int>(m.waypoints.points.size())) {
    const scene::Waypoint& w = m.waypoints.points[static_cast<std::size_t>(h.waypoint)];
    out += fmt::format("hover: waypoint {} '{}'\n", h.waypoint, w.name);
    for (const std::string& line : waypoint_tooltip_lines(w)) out += fmt::format("  {}\n", line);
  } else if (h.track < 0 && h.volume >= 0 && h.volume < static_cast<int>(m.volumes.volumes.size())) {
    const scene::Volume& v = m.volumes.volumes[static_cast<std::size_t>(h.volume)];
    out += fmt::format("hover: airspace {} '{}'\n", h.volume, v.name);
    for (const std::string& line : scene::volume_tooltip_lines(v)) out += fmt::format("  {}\n", line);
  } else if (h.track < 0) {
    out += "hover: none\n";
  } else {
    const scene::Track& t = m.tracks[static_cast<std::size_t>(h.track)];
    out += fmt::format("hover: track {} '{}' point {}\n", h.track, t.name, h.point);
    for (const std::string& line : tooltip_lines(t, h.point)) out += fmt::format("  {}\n", line);
  }
  return out;
}

std::string markers_text(const ViewerModel& m, const scene::Camera& camera) {
  std::string out;
  for (std::size_t i = 0; i < m.tracks.size(); ++i) {
    const TrackPosition p = position_at(m.tracks[i], m.clock.time());
    const auto s = p.valid ? screen_position(camera, p.ecef) : std::nullopt;
    if (s)
      out += fmt::format("marker: track {} point {} at {:.1f} {:.1f}\n", i, p.point, s->x, s->y);
    else
      out += fmt::format("marker: track {} none\n", i);
  }
  return out;
}

}  // namespace

std::optional<std::string> run_session_command(ViewerSession& session, const ScriptCommand& c,
                                               const std::string& file) {
  using Kind = ScriptCommand::Kind;
  const auto fail = [&](const std::string& why) { throw ScriptError(fmt::format("{}:{}: {}", file, c.line, why)); };
  ViewerModel& m = session.model();
  const auto camera = [&]() -> scene::CameraController& {
    if (!session.has_camera()) fail("there is no view yet (no track open and no camera given)");
    return session.camera();
  };
  switch (c.kind) {
    case Kind::orbit:
      camera();
      session.orbit(c.x, c.y);
      return "";
    case Kind::pan:
    case Kind::zoom: {
      const scene::Lens& lens = camera().lens();
      const double cx = lens.width_px / 2.0, cy = lens.height_px / 2.0;
      if (c.kind == Kind::pan)
        session.pan(cx, cy, cx + c.x, cy + c.y);
      else
        session.zoom(c.x, cx, cy);
      return "";
    }
    case Kind::select:
      if (c.x >= static_cast<double>(m.tracks.size()) || c.x != std::floor(c.x))
        fail(fmt::format("select {}: there {} {} track{} (0..{})", c.x, m.tracks.size() == 1 ? "is" : "are",
                         m.tracks.size(), m.tracks.size() == 1 ? "" : "s", static_cast<int>(m.tracks.size()) - 1));
      m.selected_track = static_cast<int>(c.x);
      session.fly_to_track(m.selected_track);
      session.update(1e9);  // scripted flights arrive at once
      return "";
    case Kind::select_waypoint:
      if (c.x >= static_cast<double>(m.waypoints.points.size()) || c.x != std::floor(c.x))
        fail(fmt::format("select-waypoint {}: there are {} waypoints", c.x, m.waypoints.points.size()));
      session.fly_to_waypoint(static_cast<int>(c.x));
      session.update(1e9);  // scripted flights arrive at once
      return "";
    case Kind::print_waypoints:
      return waypoints_text(m, camera().camera());
    case Kind::print_hover:
      return hover_text(m);
    case Kind::print_marker:
      return markers_text(m, camera().camera());
    case Kind::print_camera: {
      const scene::LookAt& v = camera().view();
      return fmt::format("camera: pivot {:.6f},{:.6f},{:.1f} distance {:.1f} heading {:.2f} pitch {:.2f}\n",
                         v.target.lat_deg, v.target.lon_deg, v.target.height_m, v.distance_m, v.heading_deg,
                         v.pitch_deg);
    }
    case Kind::print_state:
      return session_state_json(session) + "\n";
    case Kind::play:
      m.clock.play();
      m.clock.advance(c.x);
      m.clock.pause();
      return "";
    case Kind::speed:
      m.clock.set_speed(c.x);
      return "";
    default:
      return std::nullopt;
  }
}

}  // namespace trailray::ui
