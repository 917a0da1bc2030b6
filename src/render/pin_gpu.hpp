#pragma once
// The pins of a scene's waypoints on the GPU: each pin a thin stem from the ground up to its
// marker and a ball resting on top, drawn by the track pass as capsules standing alone (a stem
// from the ground to its marker raised by the style's lift, a ball at the marker raised the
// same), so they are ray traced, lit, shadowed and depth-tested with the terrain like tracks.
// One buffer of stems and one of balls per kind (waypoints, the smaller place labels, thermal
// markers in the thermal colour, photos' pins under their thumbnails), made
// again only when the set's revision (or the set) changes.

#include <cstdint>
#include <optional>
#include <vector>

#include "render/passes/track_buffer.hpp"
#include "render/passes/track_pass.hpp"
#include "scene/style.hpp"
#include "scene/pins/waypoints.hpp"

namespace trailray::render {

// The stems and balls of the visible points, as the geometry the buffers are made from (GL-free;
// tests read it): for each kind one segment of stems (ground, marker, ground, marker, ...: drawn
// as pairs) and one of balls (each marker: drawn as singles), so that all the pins of a kind are
// one draw however many there are.
struct PinGeometry {
  scene::TrackGeometry waypoint_stems, waypoint_balls, place_stems, place_balls, thermal_stems, thermal_balls,
      photo_stems, photo_balls;
};
PinGeometry pin_geometry(const scene::WaypointSet& set);

class PinGpu {
 public:
  // The draws of the set's visible pins in `style` (nullptr: none), uploading the buffers when
  // the set or its revision changed. They stay valid until the next call.
  std::vector<TrackDraw> draws(const scene::WaypointSet* set, const scene::PinStyle& style);

 private:
  const scene::WaypointSet* set_ = nullptr;
  std::uint64_t revision_ = 0;
  std::optional<TrackBuffer> waypoint_stems_, waypoint_balls_, place_stems_, place_balls_, thermal_stems_,
      thermal_balls_, photo_stems_, photo_balls_;
};

}  // namespace trailray::render
