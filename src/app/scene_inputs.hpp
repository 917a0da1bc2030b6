#pragma once
// What `trailray render` and `trailray view` share between the command line and the renderer:
// the camera and effect options (spelled the same in both), the tracks' points as read, the sun's
// time, the terrain and imagery sources, and the first camera (from --camera / --look-at, else
// framed on the tracks).

#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/terrain_options.hpp"
#include "app/track_scene.hpp"
#include "scene/camera.hpp"
#include "scene/framing.hpp"
#include "terrain/tile_source.hpp"
#include "track/io/load.hpp"

namespace trailray::app {

using WarnFunction = std::function<void(const std::string&)>;

// --camera, --look-at, --distance, --heading, --pitch, --fov.
struct CameraArgs {
  std::string camera, look_at;
  std::optional<double> distance_m, heading_deg, pitch_deg;
  double fov_deg = scene::kDefaultVerticalFovDeg;
};
void add_camera_options(CLI::App& command, CameraArgs& args);

// --time, --no-ssao, --no-atmosphere, --no-shadows, --snow, --snowline.
struct EffectArgs {
  std::string time;
  bool no_ssao = false, no_atmosphere = false, no_shadows = false, snow = false;
  double snowline_m = 2500.0;
};
void add_effect_options(CLI::App& command, EffectArgs& args);

// The camera the options ask for: a placement, a look-at, or neither (frame the tracks).
struct CameraRequest {
  std::optional<scene::CameraPlacement> placement;
  std::optional<scene::LookAt> look_at;
};
// Throws CLI::ValidationError naming the option: --camera with --look-at, --distance/--heading/
// --pitch without --look-at, no camera and no track (`have_tracks` false), unparsable text.
CameraRequest parse_camera_request(const CameraArgs& args, bool have_tracks);

// Every recorded point of the tracks (track and route points), and the first timestamp.
struct TrackPoints {
  std::vector<LoadedTrackFile> files;
  std::vector<scene::GeoPosition> points;
  std::optional<double> first_time_s;
  double first_lon_deg = 0.0;         // of the first timed point
  std::optional<double> any_lon_deg;  // of the first point at all
};
// Reads the files (warnings to `warn`). Throws std::runtime_error naming the file for one that
// cannot be read or has no point to draw.
TrackPoints load_track_points(const std::vector<std::string>& paths, const track::ReadOptions& read,
                              const WarnFunction& warn);
// Adds one file's points (for files opened later, e.g. dropped on the viewer).
void add_track_points(TrackPoints& points, LoadedTrackFile file);

// The lowest recorded height among the points (NaN: none has one).
double lowest_height(const std::vector<scene::GeoPosition>& points);

// The sun's time: --time (ISO 8601; CLI::ValidationError when it is not), else local solar noon
// on the tracks' first day, today's noon at tracks without times, now without tracks.
double sun_time(const std::string& time_text, const TrackPoints& tracks);

struct TerrainSources {
  std::unique_ptr<terrain::HeightSource> heights;   // nullptr: --terrain none
  std::unique_ptr<terrain::ImagerySource> imagery;  // nullptr: the hypsometric tint
};
// The sources of --terrain/--imagery, the configuration file and the defaults. Throws
// terrain::ConfigError and the sources' errors.
TerrainSources open_terrain_sources(const TerrainOptions& options, const WarnFunction& warn);

// The terrain height at a place from the source (NaN where it has none, or without a source).
double ground_height_at(terrain::HeightSource* source, double lat, double lon);

// The first camera: the request's (never changed), else one framing the tracks' points out of
// `keep_clear` (where the legend will be drawn), into `area` of the image (nullopt: all of it).
// Throws CLI::ValidationError for a camera the options make impossible, std::runtime_error when
// the tracks cannot be framed.
scene::Camera initial_camera(const CameraRequest& request, const scene::Lens& lens, const TrackPoints& tracks,
                              terrain::HeightSource* heights, const scene::KeptClearCorner& keep_clear = {},
                              const std::optional<scene::ImageArea>& area = std::nullopt);

}  // namespace trailray::app
