#pragma once
// Options about terrain and imagery sources, spelled the same in every command (DESIGN.md):
// --terrain, --terrain-encoding, --terrain-scheme, --terrain-zoom, --offline, --config. They
// override the configuration file (terrain/sources/terrain_config.hpp), which overrides the defaults.

#include <optional>
#include <string>

#include "terrain/sources/terrain_config.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

struct TerrainOptions {
  std::string config_file;
  std::string terrain;
  std::string terrain_encoding;
  std::string terrain_scheme;
  std::optional<int> terrain_zoom;
  bool offline = false;
  std::string imagery;  // --imagery, for commands that draw (add_imagery_option)
  std::string imagery_scheme;  // --imagery-scheme
  // --surface SRC: a surface model (canopy, buildings) drawn instead of the terrain, which the
  // tracks still stand on; along the tracks under cover the canopy is cut away (scene/tracks/canopy_cut).
  std::string surface;
  // --overlay SRC over the imagery (a heatmap: counts GeoTIFF, .mbtiles or folder `trailray
  // heatmap` wrote; or any imagery with transparency), its opacity and a count raster's colours.
  std::string overlay;
  float overlay_opacity = 1.0f;
  std::string overlay_colormap = "warm";
};

void add_terrain_options(CLI::App& command, TerrainOptions& options);
// --imagery SRC (same spellings as --terrain), --imagery-scheme and --overlay, --overlay-opacity,
// --overlay-colormap, --surface, for the commands that draw terrain.
void add_imagery_option(CLI::App& command, TerrainOptions& options);

// The configuration file (if any) with the flags applied. Throws terrain::ConfigError.
terrain::TerrainConfig resolve_terrain_config(const TerrainOptions& options);

}  // namespace trailray::app
