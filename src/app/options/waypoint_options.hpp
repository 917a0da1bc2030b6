#pragma once
// Waypoints and place labels, spelled the same in `render` and `view`: --labels FILE (place
// labels from a CSV, GPX or GeoJSON points file, repeatable) and --no-waypoints (no pins and no
// labels for the files' waypoints or the places); --score [--score-rules NAME] (the XC score of the
// first IGC track drawn: turnpoint pins, the legs on the ground, the closing gap); --task FILE (a
// competition task: its cylinders, the optimised route on the ground, the turnpoints as pins);
// --thermals / --no-thermals (a pin at the top of each thermal of the flights, labelled with its
// climb: on by default with --color-by phase, off otherwise); --places FILE (OpenStreetMap places
// labelled around the tracks: app/options/places_options).

#include <string>
#include <vector>

#include "track/color_values.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

struct WaypointArgs {
  std::vector<std::string> label_files;  // --labels
  std::string places_file;               // --places: an OpenStreetMap file (empty: none)
  bool no_waypoints = false;
  bool score = false;                          // --score: the first IGC track's XC score drawn
  std::string score_rules = "xcontest";        // --score-rules
  std::string task_file;                       // --task: a task drawn (empty: none)
  bool thermals = false, no_thermals = false;  // --thermals, --no-thermals
  // Whether thermal markers are drawn for tracks coloured by `color_by`.
  bool thermals_for(track::ColorMetric color_by) const {
    return !no_thermals && (thermals || color_by == track::ColorMetric::phase);
  }
};

void add_waypoint_options(CLI::App& command, WaypointArgs& args);

}  // namespace trailray::app
