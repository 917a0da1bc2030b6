#pragma once
// The options every command that draws pictures of the scene shares (`render` and `video`): the
// picture's size and pixel ratio, the camera, the look (shading, track style, labels), terrain and
// imagery, waypoints and airspace, how the tracks are read and cleaned, the wait for tiles and
// --verbose. Defined once, so the two commands cannot drift apart; each command's own options
// come beside them (RenderArgs, VideoArgs derive from PictureArgs).

#include <CLI/CLI.hpp>

#include <chrono>
#include <functional>
#include <string>
#include <utility>

#include "app/options/airspace_options.hpp"
#include "app/options/camera_options.hpp"
#include "app/options/photo_options.hpp"
#include "app/options/style_options.hpp"
#include "app/options/terrain_options.hpp"
#include "app/options/waypoint_options.hpp"
#include "track/io/load.hpp"
#include "track/summary.hpp"

namespace trailray::app {

struct PictureArgs {
  explicit PictureArgs(std::string default_size) : size(std::move(default_size)) {}

  std::string size;          // --size WxH
  double pixel_ratio = 1.0;  // device pixels per label pixel (high-DPI output)
  CameraArgs camera;
  StyleArgs style;
  double timeout_s = 120.0;  // --timeout: seconds to wait for terrain tiles
  bool verbose = false;
  track::ReadOptions read;
  track::AnalysisOptions analysis;
  TerrainOptions terrain;
  WaypointArgs waypoints;
  AirspaceArgs airspace;
  PhotoArgs photos;  // --photos, --photo-tz, --photo-time-offset
};

// What the help says where the commands differ.
struct PictureHelp {
  std::string size;         // "Image size in pixels (default 1920x1080)"
  std::string pixel_ratio;  // "Device pixels per pixel of the labels ..."
  std::string timeout;      // "Seconds to wait for terrain tiles (default 120)"
  std::string verbose;      // "Log the GL context, camera, sun and tiles"
};

// Adds the picture's size, pixel ratio, camera, --timeout and --verbose, then the look, terrain
// and imagery, waypoints, airspace, labels, reading and cleaning options, in the help in that
// order. `extra` (may be empty) adds the command's own options between the shading and the
// terrain, where they read best in --help.
void add_picture_options(CLI::App& command, PictureArgs& args, const PictureHelp& help,
                         const std::function<void()>& extra = {});

// Throws CLI::ValidationError naming the option: --pixel-ratio outside 0.25..8, a --timeout that
// is not a positive number of seconds (check_timeout_option).
void check_picture_args(const PictureArgs& args);

// --timeout of every command that waits for terrain tiles (render, video, view): throws
// CLI::ValidationError unless it is a positive, finite number of seconds.
void check_timeout_option(double seconds);

std::chrono::milliseconds timeout_of(const PictureArgs& args);

}  // namespace trailray::app
