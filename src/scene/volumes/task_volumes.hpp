#pragma once
// A competition task drawn in 3D (`--task FILE`): each turnpoint's cylinder as a volume
// (scene::Volume, kind TaskCylinder, category its role: the volume pass draws them), a goal line
// as a thin upright wall, the optimised route as a route on the ground, and the turnpoint
// centres as waypoint pins named as in the file. The task and its distances are the track
// layer's (track/task); nothing here knows GL.

#include <glm/glm.hpp>

#include <string>
#include <vector>

#include "scene/diagnostics.hpp"
#include "scene/style.hpp"
#include "scene/tracks/track_building.hpp"
#include "scene/tracks/track_set.hpp"
#include "scene/volumes/volumes.hpp"
#include "scene/pins/waypoint_building.hpp"
#include "scene/pins/waypoints.hpp"
#include "track/model.hpp"
#include "track/task/task.hpp"
#include "track/task/task_distance.hpp"

namespace trailray::scene {

// Colours by role, apart from the palette's tracks and the route colour: take-off grey, start
// green, turnpoints blue, ESS orange, goal red; the optimised route cyan.
glm::vec3 task_role_color(track::task::Role role);
inline constexpr glm::vec3 kTaskRouteColor{0.0f, 0.85f, 1.0f};  // cyan

// A circle of `radius_m` around `centre` on the task's earth model: enough points that the
// chord between two strays less than 2 m from the circle (at least 96 points, at most 1440).
std::vector<geo::LatLon> task_ring(const track::task::Task& task, const geo::LatLon& centre, double radius_m);

// Cylinders from the ground (0 m above it) up to `ceiling_msl_m` above sea level; without one
// (NaN: no flight), to 1500 m above the ground, which covers what a paraglider or a hang
// glider flies on a task. A goal line is a wall 2 x radius long across the last leg, a few
// metres thick.
VolumeSet task_volumes(const track::task::Task& task, const track::task::TaskDistances& distances,
                       const std::string& source, double ceiling_msl_m);

// The task as a track file: route 0 the optimised route (points without elevation: on the
// ground), and one waypoint per turnpoint centre, named as in the file with its role and radius
// in the description.
track::TrackFile task_route_file(const track::task::Task& task, const track::task::TaskDistances& distances);

struct TaskDrawing {
  std::vector<Track> tracks;        // the optimised route
  std::vector<Waypoint> waypoints;  // the turnpoints' pins
  VolumeSet volumes;                // the cylinders
};

// All of the above built as the scene builds any file (`source` names it in messages).
TaskDrawing build_task_drawing(const track::task::Task& task, const track::task::TaskDistances& distances,
                               const std::string& source, double ceiling_msl_m, const TrackStyle& style,
                               const TrackBuildOptions& options, const WaypointBuildOptions& placing,
                               Diagnostics& diagnostics);

// The highest recorded altitude of the tracks (not routes) of a set, NaN without one.
double highest_recorded_m(const TrackSet& tracks);

}  // namespace trailray::scene
