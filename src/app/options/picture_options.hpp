#pragma once
// The options every command that draws pictures of the scene shares (`render` and `video`): the
// picture's size and pixel ratio, the camera, the wait for tiles and --verbose, the shading, and
// the scene's options (app/options/scene_options: terrain and imagery, track style, waypoints,
// photos, airspace, labels, how the tracks are read and cleaned). Defined once, so the two
// commands cannot drift apart; each command's own options come beside them (RenderArgs,
// VideoArgs derive from PictureArgs).

#include <chrono>
#include <functional>
#include <string>
#include <utility>

#include "app/options/camera_options.hpp"
#include "app/options/scene_options.hpp"

namespace CLI {
class App;
}

namespace trailray::app {

// The scene's options (SceneArgs: style, terrain, waypoints, photos, airspace, track) and the
// picture's own.
struct PictureArgs : SceneArgs {
  explicit PictureArgs(std::string default_size) : size(std::move(default_size)) {}

  std::string size;          // --size WxH
  double pixel_ratio = 1.0;  // device pixels per label pixel (high-DPI output)
  CameraArgs camera;
  double timeout_s = 120.0;  // --timeout: seconds to wait for terrain tiles
  bool verbose = false;
};

// What the help says where the commands differ.
struct PictureHelp {
  std::string size;         // "Image size in pixels (default 1920x1080)"
  std::string pixel_ratio;  // "Device pixels per pixel of the labels ..."
  std::string timeout;      // "Seconds to wait for terrain tiles (default 120)"
  std::string verbose;      // "Log the GL context, camera, sun and tiles"
};

// Adds the picture's size, pixel ratio, camera, --timeout, --verbose and the shading, then the
// scene's options (add_scene_options), in the help in that order. `extra` (may be empty) adds the command's own options between the shading and the
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
