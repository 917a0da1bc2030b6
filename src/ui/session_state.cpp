#include "ui/session_state.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>

#include "scene/volumes/volume_shapes.hpp"
#include "ui/profile_chart.hpp"
#include "ui/tooltip.hpp"
#include "ui/waypoint_view.hpp"

namespace trailray::ui {
namespace {

double rounded(double v, double step) { return std::round(v / step) * step; }

nlohmann::json hover_json(const ViewerModel& m) {
  const HoverState& h = m.hover;
  nlohmann::json j = {{"track", h.track}, {"waypoint", -1}, {"airspace", -1}};
  if (h.waypoint >= 0 && h.waypoint < static_cast<int>(m.waypoints.points.size())) {
    const scene::Waypoint& w = m.waypoints.points[static_cast<std::size_t>(h.waypoint)];
    j["track"] = -1;
    j["waypoint"] = h.waypoint;
    j["name"] = w.name;
    j["lines"] = waypoint_tooltip_lines(w);
  } else if (h.track >= 0 && h.track < static_cast<int>(m.tracks.size())) {
    const scene::Track& t = m.tracks[static_cast<std::size_t>(h.track)];
    j["point"] = h.point;
    j["name"] = t.name;
    j["lines"] = tooltip_lines(t, h.point);
  } else if (h.volume >= 0 && h.volume < static_cast<int>(m.volumes.volumes.size())) {
    const scene::Volume& v = m.volumes.volumes[static_cast<std::size_t>(h.volume)];
    j["track"] = -1;
    j["airspace"] = h.volume;
    j["name"] = v.name;
    j["lines"] = scene::volume_tooltip_lines(v);
  } else {
    j["track"] = -1;
  }
  return j;
}

}  // namespace

std::string session_state_json(const ViewerSession& session) {
  const ViewerModel& m = session.model();
  nlohmann::json j;
  j["tracks"] = nlohmann::json::array();
  for (const scene::Track& t : m.tracks.tracks())
    j["tracks"].push_back({{"name", t.name}, {"points", t.point_count()}, {"visible", t.visible}});
  j["selected_track"] = m.selected_track;
  j["statistics"] = nlohmann::json::array();
  if (m.selected_track >= 0 && m.selected_track < static_cast<int>(m.tracks.size()))
    j["statistics"] = statistics_lines(m.tracks[static_cast<std::size_t>(m.selected_track)].summary.clean);
  j["hover"] = hover_json(m);
  j["camera"] = nullptr;
  if (session.has_camera()) {
    const scene::LookAt& v = session.camera().view();
    j["camera"] = {{"lat", rounded(v.target.lat_deg, 1e-6)},  {"lon", rounded(v.target.lon_deg, 1e-6)},
                   {"height", rounded(v.target.height_m, 0.1)}, {"distance", rounded(v.distance_m, 0.1)},
                   {"heading", rounded(v.heading_deg, 0.01)},   {"pitch", rounded(v.pitch_deg, 0.01)}};
  }
  j["enlarged_photo"] = nullptr;
  if (const int e = session.enlarged_photo(); e >= 0)
    j["enlarged_photo"] = {{"waypoint", e}, {"name", m.waypoints.points[static_cast<std::size_t>(e)].name}};
  j["waypoints"] = m.waypoints.points.size();
  j["replay"] = {{"time", m.clock.time()}, {"playing", m.clock.playing()}};
  j["warnings"] = session.warnings();
  j["errors"] = m.errors;
  return j.dump();
}

}  // namespace trailray::ui
