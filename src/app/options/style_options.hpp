#pragma once
// How a scene is drawn, as options spelled the same in every command that draws (`render`,
// `view`), parsed into the one scene::Style: the tracks (--width, --color-by, --colormap,
// --range, --density-radius, --color, --route-color, --legend, --occlusion, --occluded-alpha, --occlusion-fade,
// --curtain) and the shading (--time, --no-ssao, --no-atmosphere, --no-shadows, --snow, --snowline) and the labels
// (--no-labels, --label-size, --hidden-labels). Parsing checks
// every value and names the option in its error.

#include <optional>
#include <string>
#include <vector>

#include "scene/style.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

struct StyleArgs {
  // Tracks.
  std::string width = "5px";
  std::string color_by = "solid";
  std::string colormap;        // empty: turbo, or diverging for signed metrics (vspeed)
  std::string range;           // empty: the robust automatic range
  std::string density_radius;  // metres; empty: the metric's default (scene::default_neighbour_radius_m)
  std::vector<std::string> colors;
  std::string route_color;  // empty: scene::TrackStyle's
  std::string legend = "on";
  std::string occlusion = "on";
  double occluded_alpha = 0.45;
  std::string occlusion_fade = "100:1000";
  bool curtain = false;
  // Shading.
  std::string time;  // the sun's, ISO 8601; empty: the tracks' day at noon
  bool no_ssao = false, no_atmosphere = false, no_shadows = false, snow = false;
  double snowline_m = 2500.0;
  // Labels.
  bool no_labels = false;
  int label_size_px = 13;
  std::string hidden_labels = "ghost";
};

void add_track_style_options(CLI::App& command, StyleArgs& args);
void add_shading_options(CLI::App& command, StyleArgs& args);
// --no-labels, --label-size, --hidden-labels: the names of waypoints, places and tracks.
void add_label_options(CLI::App& command, StyleArgs& args);

// Throws CLI::ValidationError naming the option.
scene::Style parse_style(const StyleArgs& args);

// --time as unix seconds (nullopt: not given). Throws CLI::ValidationError for text that is not
// ISO 8601.
std::optional<double> parse_sun_time(const std::string& text);

}  // namespace trailray::app
