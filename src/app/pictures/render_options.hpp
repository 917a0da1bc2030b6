#pragma once
// `trailray render`'s options: what to draw (tracks, terrain, style), from where (camera), into
// what (size, output) and how to report (verbose, profile).

#include <string>
#include <vector>

#include "app/options/picture_options.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

// `trailray render`: the picture's options shared with `video` (PictureArgs), and its own.
struct RenderArgs : PictureArgs {
  RenderArgs() : PictureArgs("1920x1080") {}

  std::vector<std::string> tracks;
  std::string output;
  bool profile = false;
  int frames = 1;
};

void add_render_options(CLI::App& command, RenderArgs& args);

// The checks CLI11 cannot make (--frames with --profile, a positive --timeout). Throws
// CLI::ValidationError naming the option.
void check_render_args(const RenderArgs& args);

}  // namespace trailray::app
