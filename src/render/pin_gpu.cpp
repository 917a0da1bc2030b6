#include "render/pin_gpu.hpp"

namespace trailray::render {
namespace {

std::optional<TrackBuffer> buffer_of(const scene::TrackGeometry& geometry) {
  if (geometry.segments.empty() || geometry.segments.front().points_ecef.empty()) return std::nullopt;
  return std::optional<TrackBuffer>(std::in_place, geometry);
}

// A pin's look: the stem and the ball, widths bounded in pixels below and metres near the camera.
CapsuleShape stem_shape(const scene::PinStyle& s, double lift_px, double lift_m) {
  return {scene::TrackWidth{s.stem_m, scene::TrackWidth::Unit::metres},
          s.stem_px,
          0.0f,
          static_cast<float>(lift_px),
          static_cast<float>(lift_m),
          CapsuleShape::Capsules::pairs};
}
CapsuleShape ball_shape(double px, double m, double lift_px, double lift_m) {
  return {scene::TrackWidth{m, scene::TrackWidth::Unit::metres},
          px,
          0.0f,
          static_cast<float>(lift_px),
          static_cast<float>(lift_m),
          CapsuleShape::Capsules::singles};
}

}  // namespace

PinGeometry pin_geometry(const scene::WaypointSet& set) {
  PinGeometry out;
  for (scene::TrackGeometry* g : {&out.waypoint_stems, &out.waypoint_balls, &out.place_stems, &out.place_balls,
                                  &out.thermal_stems, &out.thermal_balls, &out.photo_stems, &out.photo_balls})
    g->segments.resize(1);
  for (const scene::Waypoint& w : set.points) {
    if (!w.visible) continue;
    scene::TrackGeometry* stems = &out.waypoint_stems;
    scene::TrackGeometry* balls = &out.waypoint_balls;
    switch (w.kind) {
      case scene::WaypointKind::Place: stems = &out.place_stems, balls = &out.place_balls; break;
      case scene::WaypointKind::Thermal: stems = &out.thermal_stems, balls = &out.thermal_balls; break;
      case scene::WaypointKind::Photo: stems = &out.photo_stems, balls = &out.photo_balls; break;
      case scene::WaypointKind::Waypoint: break;
    }
    stems->segments.front().points_ecef.push_back(w.ground_ecef);
    stems->segments.front().points_ecef.push_back(w.marker_ecef);
    balls->segments.front().points_ecef.push_back(w.marker_ecef);
  }
  return out;
}

std::vector<TrackDraw> PinGpu::draws(const scene::WaypointSet* set, const scene::PinStyle& style) {
  if (set != set_ || (set != nullptr && set->revision != revision_)) {
    set_ = set;
    revision_ = set != nullptr ? set->revision : 0;
    const PinGeometry geometry = set != nullptr ? pin_geometry(*set) : PinGeometry{};
    waypoint_stems_ = buffer_of(geometry.waypoint_stems);
    waypoint_balls_ = buffer_of(geometry.waypoint_balls);
    place_stems_ = buffer_of(geometry.place_stems);
    place_balls_ = buffer_of(geometry.place_balls);
    thermal_stems_ = buffer_of(geometry.thermal_stems);
    thermal_balls_ = buffer_of(geometry.thermal_balls);
    photo_stems_ = buffer_of(geometry.photo_stems);
    photo_balls_ = buffer_of(geometry.photo_balls);
  }
  std::vector<TrackDraw> out;
  const auto add = [&](const std::optional<TrackBuffer>& buffer, const glm::vec3& color, const CapsuleShape& shape) {
    if (buffer) out.push_back({&*buffer, color, false, shape, true, {}});
  };
  add(place_stems_, style.stem_color, stem_shape(style, style.place_lift_px, style.place_lift_m));
  add(place_balls_, style.place_color,
      ball_shape(style.place_marker_px, style.place_marker_m, style.place_lift_px, style.place_lift_m));
  add(waypoint_stems_, style.stem_color, stem_shape(style, style.lift_px, style.lift_m));
  add(waypoint_balls_, style.waypoint_color, ball_shape(style.marker_px, style.marker_m, style.lift_px, style.lift_m));
  // Thermal markers stand on the track in the air: waypoints' sizes, their own colour.
  add(thermal_stems_, style.stem_color, stem_shape(style, style.lift_px, style.lift_m));
  add(thermal_balls_, style.thermal_color, ball_shape(style.marker_px, style.marker_m, style.lift_px, style.lift_m));
  // Photos' pins: waypoints' sizes, a pale ball under the thumbnail.
  add(photo_stems_, style.stem_color, stem_shape(style, style.lift_px, style.lift_m));
  add(photo_balls_, style.photo_color, ball_shape(style.marker_px, style.marker_m, style.lift_px, style.lift_m));
  return out;
}

}  // namespace trailray::render
