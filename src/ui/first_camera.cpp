#include "ui/first_camera.hpp"

#include "scene/camera/camera_controller.hpp"

namespace trailray::ui {

std::optional<scene::LookAt> first_view(const CameraRequest& request, const scene::Lens& lens,
                                        const scene::TrackSet& tracks, const scene::WaypointSet& waypoints,
                                        double neutral_ground_m, const GroundHeight& ground, const FramingRoom& room,
                                        scene::Diagnostics* diagnostics) {
  if (request.look_at) return *request.look_at;
  if (tracks.empty() && waypoints.points.empty() && !request.placement) return std::nullopt;
  const scene::Camera camera = scene::first_camera(request, lens, tracks, &waypoints, neutral_ground_m, ground,
                                                   {room.keep_clear, room.area}, diagnostics);
  // The pivot where the view's centre meets the tracks' lowest level (no tile read for it).
  return scene::CameraController::look_at_from_camera(camera, neutral_ground_m);
}

}  // namespace trailray::ui
