#include "ui/replay_follow.hpp"

#include <cmath>
#include <optional>

#include "geo/wgs84.hpp"
#include "scene/camera/camera.hpp"
#include "scene/tracks/replay_position.hpp"

namespace trailray::ui {

bool follow_replay(const ViewerModel& model, scene::CameraController& controller) {
  const ReplayClock& clock = model.clock;
  if (clock.follow == FollowMode::off || clock.follow_track < 0 ||
      clock.follow_track >= static_cast<int>(model.tracks.size()))
    return false;
  const scene::Track& t = model.tracks[static_cast<std::size_t>(clock.follow_track)];
  const scene::TrackPosition p = scene::position_at(t, clock.time());
  if (!p.valid) return false;
  const geo::Geodetic g = geo::geodetic_from_ecef(p.ecef);
  const scene::GeoPosition at{g.lat_deg, g.lon_deg, g.height_m};
  std::optional<double> heading;
  if (clock.follow == FollowMode::chase && p.point + 1 < t.point_count()) {
    // Look along the way the track goes from here (the segment the marker is on).
    const scene::EnuAxes enu = scene::enu_axes_at(at.lat_deg, at.lon_deg);
    const glm::dvec3 d = t.ecef(p.point + 1) - t.ecef(p.point);
    const double east = glm::dot(d, enu.east), north = glm::dot(d, enu.north);
    if (std::hypot(east, north) > 0.1) heading = std::atan2(east, north) * 180.0 / 3.14159265358979323846;
  }
  controller.follow(at, heading);
  return true;
}

}  // namespace trailray::ui
