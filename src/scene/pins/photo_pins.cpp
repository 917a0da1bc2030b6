#include "scene/pins/photo_pins.hpp"

#include <filesystem>

namespace trailray::scene {

std::string photo_name(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  return name.empty() ? path : name;
}

std::vector<Waypoint> photo_waypoints(const std::vector<track::PlacedPhoto>& photos,
                                      const std::vector<std::shared_ptr<const PhotoImage>>& thumbnails,
                                      const WaypointBuildOptions& options) {
  std::vector<Waypoint> out;
  out.reserve(photos.size());
  for (std::size_t i = 0; i < photos.size(); ++i) {
    const track::PlacedPhoto& p = photos[i];
    track::Waypoint point;
    point.point.lat = p.lat_deg;
    point.point.lon = p.lon_deg;
    point.point.ele = p.ele_m;
    point.point.time = p.time_unix_s;
    point.name = photo_name(p.photo.path);
    std::vector<Waypoint> built = build_waypoints({point}, p.photo.path, WaypointKind::Photo, options);
    if (built.empty()) continue;  // not on the Earth: placement never gives such a point
    Waypoint& w = built.front();
    w.priority = kPhotoPriority;
    if (i < thumbnails.size()) w.thumbnail = thumbnails[i];
    out.push_back(std::move(w));
  }
  return out;
}

}  // namespace trailray::scene
