#pragma once
// `trailray render`'s options: what to draw (tracks, terrain, style), from where (camera), into
// what (size, output) and how to report (verbose, profile).

#include <CLI/CLI.hpp>

#include <chrono>
#include <string>
#include <vector>

#include "app/airspace_options.hpp"
#include "app/camera_options.hpp"
#include "app/style_options.hpp"
#include "app/terrain_options.hpp"
#include "app/waypoint_options.hpp"
#include "track/io/load.hpp"
#include "track/summary.hpp"

namespace trailray::app {

struct RenderArgs {
  std::vector<std::string> tracks;
  std::string output;
  std::string size = "1920x1080";
  double pixel_ratio = 1.0;  // device pixels per label pixel (high-DPI output)
  CameraArgs camera;
  StyleArgs style;
  double timeout_s = 120.0;
  bool verbose = false;
  bool profile = false;
  int frames = 1;
  track::ReadOptions read;
  track::AnalysisOptions analysis;
  TerrainOptions terrain;
  WaypointArgs waypoints;
  AirspaceArgs airspace;
};

void add_render_options(CLI::App& command, RenderArgs& args);

// The checks CLI11 cannot make (--frames with --profile, a positive --timeout). Throws
// CLI::ValidationError naming the option.
void check_render_args(const RenderArgs& args);

std::chrono::milliseconds timeout_of(const RenderArgs& args);

}  // namespace trailray::app
