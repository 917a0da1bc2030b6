#pragma once
// `--airspace FILE` for the commands that draw (`render`, `view`): an OpenAir file's airspaces
// drawn as translucent volumes around the tracks (scene/volumes/airspace_volumes.hpp), and the setup
// that reads it into the scene's VolumeSet.

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "app/options/camera_options.hpp"
#include "geo/bounds.hpp"
#include "scene/diagnostics.hpp"
#include "scene/pins/waypoints.hpp"
#include "scene/tracks/track_set.hpp"
#include "scene/volumes/volumes.hpp"
#include "terrain/sources/tile_source.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

struct AirspaceArgs {
  std::vector<std::string> files;  // --airspace (repeatable)
};

void add_airspace_options(CLI::App& command, AirspaceArgs& args);

// Where the airspaces are drawn and how high: the box of the visible tracks' points (else the
// waypoints', else the camera's place) and their highest point (NaN: none).
struct AirspaceRegion {
  std::optional<geo::LatLonBounds> bounds;
  double highest_m = std::numeric_limits<double>::quiet_NaN();
};
AirspaceRegion airspace_region(const scene::TrackSet& tracks, const scene::WaypointSet& waypoints,
                               const CameraRequest& camera);

// Reads every file (warnings to `diagnostics`; throws std::runtime_error with FILE:LINE for the
// first that cannot be read), adds the airspaces around `region` to `set` (a note says how many
// were left out and why), and places every volume of the set not yet placed (a task's cylinders
// too) on the terrain of `heights`.
void add_airspace_volumes(scene::VolumeSet& set, const std::vector<std::string>& files, const AirspaceRegion& region,
                          terrain::HeightSource* heights, scene::Diagnostics& diagnostics);

}  // namespace trailray::app
