#pragma once
// How tracks are drawn, spelled the same in `render` and (later) `view`: --width, --color-by,
// --colormap, --range, --color, --legend, --occlusion, --occluded-alpha, --occlusion-fade,
// --curtain. Parsing checks every value and names the option in its error.

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

#include "scene/colormap.hpp"
#include "render/passes/track_pass.hpp"
#include "track/color_values.hpp"

namespace trailray::app {

struct TrackStyleArgs {
  std::string width = "5px";
  std::string color_by = "solid";
  std::string colormap;  // empty: turbo, or diverging for signed metrics (vspeed)
  std::string range;     // empty: the robust automatic range
  std::vector<std::string> colors;
  std::string legend = "on";
  std::string occlusion = "on";
  double occluded_alpha = 0.45;
  std::string occlusion_fade = "100:1000";
  bool curtain = false;
};

struct TrackStyle {
  render::TrackSceneSettings settings;  // colormap and value range set; the range may be replaced
  track::ColorMetric metric = track::ColorMetric::solid;
  std::optional<track::ValueRange> range;  // --range, else nullopt (automatic)
  std::vector<glm::vec3> colors;           // --color, sRGB: none, one for all, or one per track
  bool legend = true;
};

void add_track_style_options(CLI::App& command, TrackStyleArgs& args);

// Throws CLI::ValidationError naming the option.
TrackStyle parse_track_style(const TrackStyleArgs& args);

}  // namespace trailray::app
