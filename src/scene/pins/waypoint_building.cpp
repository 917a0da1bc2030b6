#include "scene/pins/waypoint_building.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "geo/wgs84.hpp"
#include "scene/camera/camera.hpp"
#include "terrain/height_sampler.hpp"
#include "track/io/points_csv.hpp"
#include "track/io/readers.hpp"

namespace trailray::scene {

void place_on_ground(Waypoint& w, double neutral_ground_m) {
  const double foot = std::isnan(w.ground_m) ? neutral_ground_m : w.ground_m;
  const double marker = std::isnan(w.ele_m) ? foot : std::max(w.ele_m, foot);
  w.ground_ecef = ecef_from({w.lat_deg, w.lon_deg, foot});
  w.marker_ecef = ecef_from({w.lat_deg, w.lon_deg, marker});
}

std::vector<Waypoint> build_waypoints(const std::vector<track::Waypoint>& points, const std::string& source,
                                      WaypointKind kind, const WaypointBuildOptions& options) {
  std::vector<const track::Waypoint*> kept;
  std::vector<geo::LatLon> where;
  for (const track::Waypoint& p : points)
    if (track::valid_coordinates(p.point.lat, p.point.lon)) {
      kept.push_back(&p);
      where.push_back({p.point.lat, p.point.lon});
    }
  std::vector<double> ground(kept.size(), std::numeric_limits<double>::quiet_NaN());
  if (options.heights != nullptr && !kept.empty()) ground = terrain::HeightSampler(*options.heights).sample(where);
  std::vector<Waypoint> out;
  out.reserve(kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const track::Waypoint& p = *kept[i];
    Waypoint w;
    w.name = p.name;
    w.description = p.description;
    w.symbol = p.symbol;
    w.source = source;
    w.kind = kind;
    w.priority = kind == WaypointKind::Waypoint ? kWaypointPriority : kPlacePriority;
    w.lat_deg = p.point.lat;
    w.lon_deg = p.point.lon;
    w.ele_m = p.point.ele;
    w.ground_m = ground[i];
    w.time_unix_s = p.point.time;
    place_on_ground(w, options.neutral_ground_m);
    out.push_back(std::move(w));
  }
  return out;
}

std::vector<Waypoint> file_waypoints(const std::vector<LoadedTrackFile>& files, const WaypointBuildOptions& options) {
  std::vector<Waypoint> out;
  for (const LoadedTrackFile& f : files)
    for (Waypoint& w : build_waypoints(f.file.waypoints, f.path, WaypointKind::Waypoint, options))
      out.push_back(std::move(w));
  return out;
}

std::vector<Waypoint> read_place_labels(const std::vector<std::string>& paths, const track::ReadOptions& read,
                                        const WaypointBuildOptions& options, Diagnostics& diagnostics) {
  std::vector<Waypoint> out;
  for (const std::string& path : paths) {
    track::ReadResult result = track::load_points_file(path, read);
    for (const auto& w : result.warnings) diagnostics.warning(w.to_string());
    if (result.error) throw std::runtime_error(result.error->to_string());
    std::vector<Waypoint> places = build_waypoints(result.file.waypoints, path, WaypointKind::Place, options);
    if (places.empty())
      throw std::runtime_error(path +
                               ": has no points for place labels (a CSV with name,lat,lon columns, or a file "
                               "with waypoints: GPX wpt, GeoJSON Point features)");
    for (Waypoint& w : places) out.push_back(std::move(w));
  }
  return out;
}

void set_waypoints_visible(WaypointSet& set, bool visible) {
  for (Waypoint& w : set.points)
    if (w.kind != WaypointKind::Thermal && w.kind != WaypointKind::Photo) w.visible = visible;
  ++set.revision;
}

}  // namespace trailray::scene
