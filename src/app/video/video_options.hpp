#pragma once
// `trailray video`'s options: `render`'s (what to draw, the size, the camera as --camera/--look-at
// for a fixed camera) added by the same functions, and the film's own: its length and frame
// rate, the part of the tracks filmed, the camera's mode, the trail, the output.

#include <string>
#include <vector>

#include "app/options/picture_options.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

// `trailray video`: the picture's options shared with `render` (PictureArgs), and the film's own.
struct VideoArgs : PictureArgs {
  VideoArgs() : PictureArgs("1280x720") {}

  std::vector<std::string> tracks;
  std::string output, frames_dir;
  bool force = false;
  std::string mode;         // --camera-mode follow|orbit|fixed|path; empty: from the other options, else follow
  std::string camera_path;  // --camera-path FILE
  int follow = 1;           // --follow N: the track the camera follows (1-based)
  std::string duration, speed, from, to;
  double fps = 30.0;
  std::string trail = "all";
  std::string align = "clock";
  std::string gauges = "full";  // --gauges none|minimal|full (was --overlay: that is now the map's)
  int crf = 20;
  bool fast = false;  // --fast: no shadows, no SSAO
  double photo_seconds = 2.0;  // --photo-seconds: the film stops this long at each photo (0: never)
};

void add_video_options(CLI::App& command, VideoArgs& args);

enum class FilmCameraMode { follow, orbit, fixed, path };

// What CLI11 cannot check alone: -o or --frames-dir, the camera mode with its options, the CRF,
// the timeout. Throws CLI::ValidationError naming the option.
FilmCameraMode check_video_args(const VideoArgs& args);

}  // namespace trailray::app
