#include "app/options/waypoint_options.hpp"

#include <CLI/CLI.hpp>

#include "app/options/places_options.hpp"

#include "track/scoring/rules.hpp"

namespace trailray::app {

void add_waypoint_options(CLI::App& command, WaypointArgs& args) {
  command
      .add_option("--labels", args.label_files,
                  "Place labels (peaks, huts) from a points file, drawn as small pins with their names: a CSV "
                  "with a header naming name, lat, lon and ele columns (any order; comma, semicolon or tab), "
                  "or the waypoints of a GPX or GeoJSON file. Repeatable")
      ->type_name("FILE")
      ->allow_extra_args(false);  // one file per --labels: the words after it are tracks
  add_places_option(command, args.places_file, PlacesUse::labels);
  command.add_flag("--no-waypoints", args.no_waypoints,
                   "No pins or labels for the files' waypoints (GPX wpt, KML points, FIT course points) or places");
  command.add_flag("--score", args.score,
                   "Score the first IGC track as `trailray score` does and draw it: the turnpoints as pins, the "
                   "scored legs as a line on the ground, the closing gap of a closed route in its own colour");
  command
      .add_option("--task", args.task_file,
                  "A competition task (XCTrack .xctsk, its XCTSK: QR text, or an IGC file's C-record declaration) "
                  "drawn: the turnpoint cylinders (from the ground to 300 m above the highest track point), the "
                  "optimised route on the ground, the turnpoints as pins")
      ->type_name("FILE");
  command.add_option("--score-rules", args.score_rules, "The rule set --score uses")
      ->type_name("NAME")
      ->check(CLI::IsMember(track::scoring::rule_set_names()))
      ->capture_default_str();
  CLI::Option* on = command.add_flag(
      "--thermals", args.thermals,
      "Mark each thermal of the flights (climbing circles, see `trailray flight`) with a pin at its top labelled "
      "with its mean climb and its entry and exit altitudes, '+2.4 m/s \u00b7 1650\u21922380 m' (default: on with "
      "--color-by phase)");
  CLI::Option* off =
      command.add_flag("--no-thermals", args.no_thermals, "No thermal markers, also with --color-by phase");
  on->excludes(off);
}

}  // namespace trailray::app
