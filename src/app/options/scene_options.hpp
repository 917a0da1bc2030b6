#pragma once
// What a scene drawn in full holds and how it looks, as the options every command that draws it
// shares (`render`, `video`, `view`): the terrain and imagery, the tracks' style, the waypoints and
// places, the photos, the airspaces, the labels, and how the tracks are read and cleaned. One
// struct and one function, so the commands cannot drift apart; each command adds before them what
// differs between them (the picture's size, the camera, the shading, the wait for tiles, its own).

#include "app/options/airspace_options.hpp"
#include "app/options/photo_options.hpp"
#include "app/options/style_options.hpp"
#include "app/options/terrain_options.hpp"
#include "app/options/track_options.hpp"
#include "app/options/waypoint_options.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

struct SceneArgs {
  StyleArgs style;  // the tracks' style and the labels here; the shading where each command puts it
  TerrainOptions terrain;
  WaypointArgs waypoints;
  PhotoArgs photos;  // --photos, --photo-tz, --photo-time-offset
  AirspaceArgs airspace;
  TrackOptions track_options;  // --strict, --igc-altitude and the cleaning
};

// Adds, in the help in this order: the terrain, the imagery, the tracks' style, the waypoints,
// the photos, the airspaces, the labels, the reading and the cleaning options.
void add_scene_options(CLI::App& command, SceneArgs& args);

}  // namespace trailray::app
