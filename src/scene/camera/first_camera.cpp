#include "scene/camera/first_camera.hpp"

#include <fmt/format.h>

#include <cmath>
#include <vector>

namespace trailray::scene {

Camera first_camera(const CameraRequest& request, const Lens& lens, const TrackSet& tracks,
                    const WaypointSet* waypoints, double neutral_ground_m, const GroundHeight& ground,
                    const FramingSpace& space, Diagnostics* diagnostics) {
  if (request.placement || request.look_at) {
    const GeoPosition& where = request.placement ? request.placement->position : request.look_at->target;
    double height = ground ? ground(where.lat_deg, where.lon_deg) : std::nan("");
    if (std::isnan(height)) height = neutral_ground_m;
    auto made = request.placement ? camera_at(*request.placement, lens, height)
                                  : camera_looking_at(*request.look_at, lens, height);
    if (!made.ok()) throw FirstCameraError(request.placement ? "--camera" : "--look-at", made.error);
    return std::move(*made.value);
  }
  FramingOptions framing;
  framing.lens = lens;
  framing.keep_clear = space.keep_clear;
  framing.area = space.area;
  bool any_track_point = false;
  for (const Track& t : tracks.tracks()) any_track_point = any_track_point || (t.visible && t.point_count() > 0);
  if (!any_track_point && waypoints != nullptr && !waypoints->points.empty()) {
    std::vector<GeoPosition> points;
    for (const Waypoint& w : waypoints->points) {
      const double height = std::isnan(w.ele_m) ? w.ground_m : w.ele_m;
      points.push_back({w.lat_deg, w.lon_deg, std::isnan(height) ? neutral_ground_m : height});
    }
    auto framed = frame_points(points, framing);
    if (!framed.ok()) throw FirstCameraError("", "cannot frame the waypoints: " + framed.error);
    return framed.value->camera;
  }
  // Tracks far apart (a pilot's flights over several countries, or both sides of the Earth): the
  // largest group of them near each other, as one view of them all would show little but the
  // globe; the others are a fly-to away in the viewer, or a --camera away.
  const std::vector<const Track*> group = largest_track_group(tracks);
  std::size_t visible = 0;
  for (const Track& t : tracks.tracks()) visible += t.visible && t.point_count() > 0 ? 1 : 0;
  if (!group.empty() && group.size() < visible) {
    auto grouped = frame_tracks(group, framing);
    if (grouped.ok()) {
      if (diagnostics != nullptr)
        diagnostics->warning(
            fmt::format("the tracks lie too far apart for one view: it shows the {} of {} within "
                        "{:.0f} km of each other",
                        group.size(), visible, kTrackGroupRadiusM / 1000.0));
      return grouped.value->camera;
    }
  }
  auto framed = frame_tracks(tracks, framing);
  if (!framed.ok()) throw FirstCameraError("", "cannot frame the tracks: " + framed.error);
  return framed.value->camera;
}

}  // namespace trailray::scene
