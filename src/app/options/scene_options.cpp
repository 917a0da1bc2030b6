#include "app/options/scene_options.hpp"

#include <CLI/CLI.hpp>

namespace trailray::app {

void add_scene_options(CLI::App& cmd, SceneArgs& args) {
  add_terrain_options(cmd, args.terrain);
  add_imagery_option(cmd, args.terrain);
  add_track_style_options(cmd, args.style);
  add_waypoint_options(cmd, args.waypoints);
  add_photo_options(cmd, args.photos);
  add_airspace_options(cmd, args.airspace);
  add_label_options(cmd, args.style);
  add_track_options(cmd, args.track_options);
}

}  // namespace trailray::app
