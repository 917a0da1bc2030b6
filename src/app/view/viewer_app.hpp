#pragma once
// `trailray view`: the window, its frame loop and the scripted runs. Each frame: input (camera
// gestures, keys, dropped files), the scene drawn by the same renderer as `trailray render`
// without waiting for tiles (they stream in coarse-to-fine, a loading indicator counts them),
// blitted into the window, then the panels, the tooltip and the markers on top.
//
// Scripted (`--frames N`, `--script FILE`, `--screenshot OUT.png`): the same loop, driven by the
// commands instead of a person; pictures wait for the view's tiles, so they are complete.

#include <optional>
#include <string>
#include <vector>

#include "app/options/camera_options.hpp"
#include "app/options/photo_options.hpp"
#include "app/options/terrain_options.hpp"
#include "scene/camera/camera.hpp"
#include "scene/style.hpp"
#include "track/io/load.hpp"
#include "track/metrics.hpp"
#include "track/statistics.hpp"
#include "track/summary.hpp"

namespace trailray::app::view {

struct ViewerOptions {
  std::vector<std::string> tracks;
  scene::Lens lens;  // the window's size and the field of view
  CameraRequest camera;
  scene::Style style;
  std::optional<double> sun_time_unix;  // --time; nullopt: the tracks' day at noon
  track::ReadOptions read;
  track::AnalysisOptions analysis;
  TerrainOptions terrain;
  bool verbose = false;
  int frames = 0;                           // > 0: render this many frames, then (screenshot and) exit
  std::string script;                       // commands to run, then exit
  std::string screenshot;                   // written at the end of a scripted run
  double timeout_s = 120.0;                 // for a scripted picture's tiles
  std::vector<std::string> label_files;     // --labels: place labels
  std::string places_file;                  // --places: OpenStreetMap places labelled, summits listed
  bool no_waypoints = false;                // --no-waypoints: pins and labels hidden (the panel shows them again)
  bool score = false;                       // --score: the first IGC track's XC score drawn
  std::string score_rules = "xcontest";     // --score-rules
  std::string task_file;                    // --task: a task drawn
  std::vector<std::string> airspace_files;  // --airspace: OpenAir files drawn as volumes
  bool thermals = false;                    // --thermals (resolved: on by default with --color-by phase)
  bool moving_frame = true;                 // false (--no-moving-frame): the full frame while the camera moves too
  PhotoArgs photos;                         // --photos: pins with thumbnails; a click shows one larger
};

// Opens the window and runs until it is closed (or the script ends). Throws RenderError when
// there is no display, std::runtime_error for sources and files that stop the start, ScriptError
// for the script; returns the exit status.
int run_viewer(const ViewerOptions& options);

}  // namespace trailray::app::view
