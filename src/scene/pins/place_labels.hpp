#pragma once
// OpenStreetMap places (--places: track/places) as a scene's place labels: waypoints of kind
// Place named "Eiger 3967 m", at their elevation (else on the ground), that the labels pass lays
// out with the others. Which wins where two collide is their priority: a hand-made --labels
// place before any of these, then by prominence: cities, peaks (the higher first), towns, lakes,
// passes and saddles (the higher first), huts, villages, hamlets.

#include <string>
#include <vector>

#include "scene/pins/waypoint_building.hpp"
#include "scene/pins/waypoints.hpp"
#include "track/places/place.hpp"

namespace trailray::scene {

// Waypoint::priority of an OpenStreetMap place: always below kPlacePriority (a --labels place).
int osm_place_priority(const track::places::Place& place);

// One waypoint of kind Place per place, in order, placed as build_waypoints places them;
// `source` is the file they came from.
std::vector<Waypoint> osm_place_waypoints(const std::vector<track::places::Place>& places, const std::string& source,
                                          const WaypointBuildOptions& options);

}  // namespace trailray::scene
