#include "ui/first_camera.hpp"

#include <fmt/format.h>

#include <cmath>
#include <vector>

#include "scene/camera/camera_controller.hpp"

namespace trailray::ui {

scene::Camera first_camera(const CameraRequest& request, const scene::Lens& lens, const scene::TrackSet& tracks,
                           const scene::WaypointSet* waypoints, double neutral_ground_m, const GroundHeight& ground,
                           const FramingRoom& room, scene::Diagnostics* diagnostics) {
  if (request.placement || request.look_at) {
    const scene::GeoPosition& where = request.placement ? request.placement->position : request.look_at->target;
    double height = ground ? ground(where.lat_deg, where.lon_deg) : std::nan("");
    if (std::isnan(height)) height = neutral_ground_m;
    auto made = request.placement ? scene::camera_at(*request.placement, lens, height)
                                  : scene::camera_looking_at(*request.look_at, lens, height);
    if (!made.ok()) throw FirstCameraError(request.placement ? "--camera" : "--look-at", made.error);
    return std::move(*made.value);
  }
  scene::FramingOptions framing;
  framing.lens = lens;
  framing.keep_clear = room.keep_clear;
  framing.area = room.area;
  bool any_track_point = false;
  for (const scene::Track& t : tracks.tracks()) any_track_point = any_track_point || (t.visible && t.point_count() > 0);
  if (!any_track_point && waypoints != nullptr && !waypoints->points.empty()) {
    std::vector<scene::GeoPosition> points;
    for (const scene::Waypoint& w : waypoints->points) {
      const double height = std::isnan(w.ele_m) ? w.ground_m : w.ele_m;
      points.push_back({w.lat_deg, w.lon_deg, std::isnan(height) ? neutral_ground_m : height});
    }
    auto framed = scene::frame_points(points, framing);
    if (!framed.ok()) throw FirstCameraError("", "cannot frame the waypoints: " + framed.error);
    return framed.value->camera;
  }
  // Tracks far apart (a pilot's flights over several countries, or both sides of the Earth): the
  // largest group of them near each other, as one view of them all would show little but the
  // globe; the others are a fly-to away in the viewer, or a --camera away.
  const std::vector<const scene::Track*> group = scene::largest_track_group(tracks);
  std::size_t visible = 0;
  for (const scene::Track& t : tracks.tracks()) visible += t.visible && t.point_count() > 0 ? 1 : 0;
  if (!group.empty() && group.size() < visible) {
    auto grouped = scene::frame_tracks(group, framing);
    if (grouped.ok()) {
      if (diagnostics != nullptr)
        diagnostics->warning(
            fmt::format("the tracks lie too far apart for one view: it shows the {} of {} within "
                        "{:.0f} km of each other",
                        group.size(), visible, scene::kTrackGroupRadiusM / 1000.0));
      return grouped.value->camera;
    }
  }
  auto framed = scene::frame_tracks(tracks, framing);
  if (!framed.ok()) throw FirstCameraError("", "cannot frame the tracks: " + framed.error);
  return framed.value->camera;
}

std::optional<scene::LookAt> first_view(const CameraRequest& request, const scene::Lens& lens,
                                        const scene::TrackSet& tracks, const scene::WaypointSet& waypoints,
                                        double neutral_ground_m, const GroundHeight& ground, const FramingRoom& room,
                                        scene::Diagnostics* diagnostics) {
  if (request.look_at) return *request.look_at;
  if (tracks.empty() && waypoints.points.empty() && !request.placement) return std::nullopt;
  const scene::Camera camera =
      first_camera(request, lens, tracks, &waypoints, neutral_ground_m, ground, room, diagnostics);
  // The pivot where the view's centre meets the tracks' lowest level (no tile read for it).
  return scene::CameraController::look_at_from_camera(camera, neutral_ground_m);
}

}  // namespace trailray::ui
