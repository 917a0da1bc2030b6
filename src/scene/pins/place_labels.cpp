#include "scene/pins/place_labels.hpp"

#include <algorithm>
#include <cmath>

#include "track/places/place_tags.hpp"

namespace trailray::scene {

namespace {

using track::places::PlaceKind;

// Bands of 10,000 apart, so an elevation (up to 8,849 m) orders within its band and never
// reaches the next.
int band(PlaceKind kind) {
  switch (kind) {
    case PlaceKind::City: return 9;
    case PlaceKind::Peak:
    case PlaceKind::Volcano: return 8;
    case PlaceKind::Town: return 7;
    case PlaceKind::Lake: return 6;
    case PlaceKind::Pass:
    case PlaceKind::Saddle: return 5;
    case PlaceKind::AlpineHut:
    case PlaceKind::WildernessHut: return 4;
    case PlaceKind::Village: return 3;
    case PlaceKind::Hamlet: return 2;
  }
  return 1;
}

}  // namespace

int osm_place_priority(const track::places::Place& place) {
  const bool by_height = track::places::is_summit(place.kind) || place.kind == PlaceKind::Pass ||
                         place.kind == PlaceKind::Saddle;
  const int height = by_height && std::isfinite(place.ele_m)
                         ? static_cast<int>(std::clamp(std::lround(place.ele_m), 0L, 9999L))
                         : 0;
  // Below kPlacePriority: the bands count down from there.
  return kPlacePriority - 1 - (10 - band(place.kind)) * 10000 + height;
}

std::vector<Waypoint> osm_place_waypoints(const std::vector<track::places::Place>& places, const std::string& source,
                                          const WaypointBuildOptions& options) {
  std::vector<track::Waypoint> points;
  points.reserve(places.size());
  for (const track::places::Place& p : places) {
    track::Waypoint w;
    w.name = track::places::place_label(p);
    w.symbol = std::string(track::places::kind_name(p.kind));
    w.point.lat = p.lat_deg;
    w.point.lon = p.lon_deg;
    w.point.ele = p.ele_m;
    points.push_back(std::move(w));
  }
  std::vector<Waypoint> out = build_waypoints(points, source, WaypointKind::Place, options);
  // build_waypoints drops invalid coordinates: match the priorities by position in the kept list.
  std::size_t k = 0;
  for (const track::places::Place& p : places) {
    if (k >= out.size()) break;
    if (out[k].lat_deg == p.lat_deg && out[k].lon_deg == p.lon_deg) out[k++].priority = osm_place_priority(p);
  }
  return out;
}

}  // namespace trailray::scene
