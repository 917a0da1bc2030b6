#pragma once
// From the points of files to a scene's WaypointSet: the waypoints the track files carry (GPX
// wpt, KML Point placemarks, FIT course points, GeoJSON Point features: TrackFile::waypoints)
// and the place labels of points files (--labels: CSV, GPX, GeoJSON, ...), each placed in ECEF
// once, with the terrain below it.

#include <string>
#include <vector>

#include "scene/diagnostics.hpp"
#include "scene/tracks/track_files.hpp"
#include "scene/pins/waypoints.hpp"
#include "terrain/sources/tile_source.hpp"
#include "track/diagnostics.hpp"
#include "track/model.hpp"

namespace trailray::scene {

struct WaypointBuildOptions {
  terrain::HeightSource* heights = nullptr;  // the terrain below each point (nullptr: none)
  double neutral_ground_m = 0.0;             // the ground where there is no terrain height
};

// Which label wins where two would overlap (Waypoint::priority): a file's own waypoints before
// place labels.
inline constexpr int kWaypointPriority = 2;
inline constexpr int kPlacePriority = 1;

// Where a waypoint with its place, elevation and ground (NaN: unknown) is drawn: the stem's foot
// on the ground, else on the neutral ground; the marker at the elevation but never below the
// foot (a GPS height under the ground would bury the pin), else on the foot.
void place_on_ground(Waypoint& waypoint, double neutral_ground_m);

// One scene waypoint per point with valid coordinates, in order: the ground below it sampled
// from the terrain (NaN without), the stem's foot on it (else on the neutral ground), the marker
// at the recorded elevation but never below the foot (a GPS height under the ground would bury
// the pin), else on the foot.
std::vector<Waypoint> build_waypoints(const std::vector<track::Waypoint>& points, const std::string& source,
                                      WaypointKind kind, const WaypointBuildOptions& options);

// The waypoints of the files, file after file (kind Waypoint).
std::vector<Waypoint> file_waypoints(const std::vector<LoadedTrackFile>& files, const WaypointBuildOptions& options);

// The place labels of points files (track::load_points_file: CSV by name, else any track file's
// waypoints), file after file (kind Place). Warnings go to `diagnostics`. Throws
// std::runtime_error naming the file (and the line) for a file that cannot be read or has no
// points.
std::vector<Waypoint> read_place_labels(const std::vector<std::string>& paths, const track::ReadOptions& read,
                                        const WaypointBuildOptions& options, Diagnostics& diagnostics);

// Shows or hides the files' waypoints and the place labels (their pins and labels: `--no-waypoints`
// and the viewer's checkbox) and bumps the set's revision. Thermal markers and photos have options
// of their own (`--thermals`, `--photos`) and stay as they are.
void set_waypoints_visible(WaypointSet& set, bool visible);

}  // namespace trailray::scene
