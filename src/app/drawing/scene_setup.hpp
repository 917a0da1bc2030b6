#pragma once
// From options to a scene, shared by the commands that draw (`render`, `view`): the terrain and
// imagery sources, the tracks read and built, the sun's time, the first camera.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/options/camera_options.hpp"
#include "app/options/terrain_options.hpp"
#include "app/options/waypoint_options.hpp"
#include "scene/camera/framing.hpp"
#include "scene/diagnostics.hpp"
#include "scene/pins/scored_route.hpp"
#include "scene/pins/waypoints.hpp"
#include "scene/style.hpp"
#include "scene/text/legend.hpp"
#include "scene/tracks/canopy_cut.hpp"
#include "scene/tracks/track_building.hpp"
#include "scene/tracks/track_files.hpp"
#include "scene/tracks/track_set.hpp"
#include "scene/volumes/task_volumes.hpp"
#include "terrain/sources/tile_source.hpp"
#include "track/places/place.hpp"

namespace trailray::app {

struct TerrainSources {
  std::unique_ptr<terrain::HeightSource> heights;   // nullptr: --terrain none
  // --surface: the surface model, and what is drawn of it (the canopy cut along the tracks under
  // cover: set_cut_lines once the tracks are built, before the first frame). nullptr without.
  std::unique_ptr<terrain::HeightSource> surface;
  std::unique_ptr<scene::CanopyCutHeights> drawn_surface;
  std::unique_ptr<terrain::ImagerySource> imagery;  // nullptr: the hypsometric tint (--overlay: composited in)
  std::optional<scene::ColorLegend> overlay_legend;  // a heatmap overlay's colour bar

  // What the terrain pass draws: the surface (cut) with --surface, else the terrain.
  terrain::HeightSource* drawn() const {
    return drawn_surface ? static_cast<terrain::HeightSource*>(drawn_surface.get()) : heights.get();
  }
  // Once the tracks are built: the canopy cut along their covered parts (nothing without --surface).
  void cut_canopy(const scene::TrackSet& tracks) const;
};
// The sources of --terrain/--imagery, the configuration file and the defaults; the sources'
// warnings go to `diagnostics`. Throws terrain::ConfigError and the sources' errors.
// Without terrain (--terrain none) no imagery is opened: it only ever colours the terrain, and
// asking a server for it costs time (seconds offline). `imagery_without_terrain`: opened anyway
// (serve hands its tiles to pages that may bring terrain of their own).
TerrainSources open_terrain_sources(const TerrainOptions& options, scene::Diagnostics& diagnostics,
                                    bool imagery_without_terrain = false);

// The terrain height at a place from the source (NaN where it has none, or without a source).
double ground_height_at(terrain::HeightSource* source, double lat, double lon);

// Tracks read from files and built for the scene, with their waypoints and the place labels.
struct SceneTracks {
  scene::TrackSet tracks;
  scene::RecordedPoints recorded;  // the files' points as recorded (the sun's day, the lowest height)
  scene::WaypointSet waypoints;    // the files' waypoints, then the places of --labels
  scene::VolumeSet volumes;        // --task: the task's cylinders
};
// Reads every file (the first that cannot be read throws, naming it) and builds its tracks
// (build_tracks' errors), both on all cores with a progress line (app/common/track_reading), points without an elevation on
// the lowest recorded height where there is no terrain (options.neutral_ground_m is not read); the files' waypoints and
// the places of `waypoints.label_files` (read_place_labels' errors) and of `waypoints.places_file`
// (osm_place_labels), hidden with --no-waypoints.
SceneTracks load_scene_tracks(const std::vector<std::string>& paths, const track::ReadOptions& read,
                              const scene::TrackStyle& style, const scene::TrackBuildOptions& options,
                              scene::Diagnostics& diagnostics, const WaypointArgs& waypoints = {});
// The same from files already read (the Python module's): `paths` are those of them that are
// files on disk, for --score (it reads the first IGC file of them again, as the scorer reads IGC).
// The files' track points are freed as their tracks are built (build_tracks_releasing).
SceneTracks build_scene_tracks(std::vector<scene::LoadedTrackFile> files, const std::vector<std::string>& paths,
                               const track::ReadOptions& read, const scene::TrackStyle& style,
                               const scene::TrackBuildOptions& options, scene::Diagnostics& diagnostics,
                               const WaypointArgs& waypoints = {});

// --places: the places of the OpenStreetMap `file` around the visible tracks (else the waypoints;
// app/options/places_options: their bounds and 5 km) as place labels (scene/pins/place_labels), with a note
// saying how many. Throws std::runtime_error naming the file when it cannot be read.
// The places themselves (the viewer also lists the summits and huts the tracks reached).
std::vector<track::places::Place> places_around(const std::string& file, const scene::TrackSet& tracks,
                                                const scene::WaypointSet& waypoints, scene::Diagnostics& diagnostics);
std::vector<scene::Waypoint> osm_place_labels(const std::string& file, const scene::TrackSet& tracks,
                                              const scene::WaypointSet& waypoints,
                                              const scene::WaypointBuildOptions& placing,
                                              scene::Diagnostics& diagnostics);

// --score: the first IGC file of `paths` scored under the rule set `rules_name` and its best route
// built for the scene (nothing, after a warning, when no route scores). Throws std::runtime_error
// without an IGC file, for unknown rules or a log that cannot be read.
scene::ScoredRouteDrawing scored_route_of(const std::vector<std::string>& paths, const std::string& rules_name,
                                          const scene::TrackStyle& style, const scene::TrackBuildOptions& build,
                                          const scene::WaypointBuildOptions& placing, scene::Diagnostics& diagnostics);

// --task: the task of `task_file` read, measured and built for the scene; its cylinders reach
// 300 m above `highest_m` (the tracks' highest point; NaN: 1500 m above the ground). Throws
// std::runtime_error naming the file and the place when it cannot be read; its warnings go to
// `diagnostics`.
scene::TaskDrawing task_drawing_of(const std::string& task_file, double highest_m, const scene::TrackStyle& style,
                                   const scene::TrackBuildOptions& build, const scene::WaypointBuildOptions& placing,
                                   scene::Diagnostics& diagnostics);

// The sun's time: --time when given, else the tracks' day at noon (scene::default_sun_time).
double sun_time(const std::optional<double>& given, const scene::RecordedPoints& recorded);

// The first camera as the command line makes it: scene::first_camera (scene/camera/first_camera:
// the request's, else the visible tracks framed out of `keep_clear` into `area`, else the
// waypoints) with the ground's height under a requested camera sampled from `heights`. Throws
// CLI::ValidationError naming --camera or --look-at for a camera the options make impossible,
// std::runtime_error when nothing can be framed.
scene::Camera initial_camera(const CameraRequest& request, const scene::Lens& lens, const scene::TrackSet& tracks,
                             double neutral_ground_m, terrain::HeightSource* heights,
                             const scene::KeptClearCorner& keep_clear = {},
                             const std::optional<scene::ImageArea>& area = std::nullopt,
                             const scene::WaypointSet* waypoints = nullptr, scene::Diagnostics* diagnostics = nullptr);

}  // namespace trailray::app
