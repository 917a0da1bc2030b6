#pragma once
// The viewer's waypoints (the files' and the places of --labels): where each lies along a track
// for the profile chart, which pin is under the cursor, and its tooltip. Pure functions of the
// model and a camera, so tests check them without a window.

#include <glm/glm.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "scene/camera/camera.hpp"
#include "scene/style.hpp"
#include "scene/tracks/track_set.hpp"
#include "scene/pins/waypoints.hpp"

namespace trailray::ui {

// A waypoint farther than this from every point of a track is not on its chart.
inline constexpr double kChartWaypointReachM = 1000.0;

struct ChartWaypoint {
  std::size_t waypoint = 0;  // index into the set's points
  std::size_t point = 0;     // the track's nearest flat point
};
// The visible waypoints within `reach_m` of the track, each at its nearest point (in the set's
// order).
std::vector<ChartWaypoint> chart_waypoints(const scene::Track& track, const scene::WaypointSet& waypoints,
                                           double reach_m = kChartWaypointReachM);

// Where a pin's ball appears (pixels): its marker projected, raised by the style's lift (the
// renderer's: at least lift_px pixels); nullopt behind the camera.
std::optional<glm::dvec2> pin_screen_position(const scene::Camera& camera, const scene::Waypoint& waypoint,
                                              const scene::PinStyle& style);

// The visible pin whose ball is nearest pixel (x, y) within `radius_px`, -1 for none.
int pick_waypoint(const scene::WaypointSet& waypoints, const scene::Camera& camera, const scene::PinStyle& style,
                  double x_px, double y_px, double radius_px);

// The tooltip: "elevation: 1234 m" (recorded, else "—"), "ground: 1200 m" (when known), the
// description, the time (UTC) when recorded, the file.
std::vector<std::string> waypoint_tooltip_lines(const scene::Waypoint& waypoint);

// A view onto a waypoint for a flight: looking at its marker from `distance_m` with the given
// heading and pitch.
scene::LookAt look_at_waypoint(const scene::Waypoint& waypoint, double heading_deg, double pitch_deg,
                               double distance_m = 1500.0);

}  // namespace trailray::ui
