#pragma once
// An XC score drawn in 3D (`--score`): the scored turnpoints as waypoint pins labelled TP1, TP2, ...
// (start and finish for a free distance) with the leg that leaves each, the legs as a route on the
// ground (closed for closed types), and the closing gap of a closed type as a short route of its
// own colour. Both are ordinary scene types (Waypoint, Track with is_route), so no pass of the
// renderer knows about scoring; the score itself is the track layer's (track/scoring).

#include <glm/glm.hpp>

#include <string>
#include <vector>

#include "scene/diagnostics.hpp"
#include "scene/style.hpp"
#include "scene/tracks/track_building.hpp"
#include "scene/tracks/track_set.hpp"
#include "scene/pins/waypoint_building.hpp"
#include "scene/pins/waypoints.hpp"
#include "track/model.hpp"
#include "track/scoring/score.hpp"

namespace trailray::scene {

// Distinct from the palette's track colours and from the route colour (yellow).
inline constexpr glm::vec3 kScoredLegsColor{1.0f, 0.0f, 0.85f};  // magenta
inline constexpr glm::vec3 kClosingGapColor{0.0f, 0.95f, 1.0f};  // cyan

// What the legend key calls the legs, e.g. "FAI triangle 228.69 pts, xcontest".
std::string scored_route_name(const track::scoring::ScoreResult& result);

// The best type of `result` as a track file: route 0 the legs (points without elevation, so they
// lie on the ground; the first point repeated at the end for a closed type), route 1 (closed types
// with a gap only) the closing pair of fixes, and one waypoint per turnpoint. Empty without a best
// type. `fixes` are the fixes the result's indexes refer to.
track::TrackFile scored_route_file(const track::scoring::ScoreResult& result,
                                   const std::vector<track::scoring::Fix>& fixes);

struct ScoredRouteDrawing {
  std::vector<Track> tracks;        // the legs, then the closing gap (if any), coloured
  std::vector<Waypoint> waypoints;  // the turnpoints' pins
};

// The file above built as the scene builds any file (`source` names it in messages); the tracks
// are routes whatever the style colours tracks by.
ScoredRouteDrawing build_scored_route(const track::scoring::ScoreResult& result,
                                      const std::vector<track::scoring::Fix>& fixes, const std::string& source,
                                      const TrackStyle& style, const TrackBuildOptions& options,
                                      const WaypointBuildOptions& placing, Diagnostics& diagnostics);

}  // namespace trailray::scene
