#include "app/options/terrain_options.hpp"

#include <CLI/CLI.hpp>
#include <cctype>

namespace trailray::app {
namespace {

// The check accepts any case ("TMS"); the value keeps the user's spelling, so it is lowered
// before parsing (scheme_of).
void add_scheme_option(CLI::App& cmd, const std::string& name, std::string& value, const std::string& what) {
  cmd.add_option(name, value,
                 "Row order of " + what +
                     ": xyz (from the north) or tms (from the south); default: its metadata, "
                     "else xyz")
      ->check(CLI::IsMember({"xyz", "tms"}, CLI::ignore_case))
      ->type_name("xyz|tms");
}

std::optional<terrain::TileScheme> scheme_of(std::string value) {
  for (char& c : value) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return terrain::parse_tile_scheme(value);
}

}  // namespace

void add_terrain_options(CLI::App& cmd, TerrainOptions& o) {
  cmd.add_option("--terrain", o.terrain,
                 "Elevation source: a raster file (GeoTIFF, .hgt, VRT, ...), a {z}/{x}/{y} tile folder, an .mbtiles "
                 "file, an http(s) URL template with {z} {x} {y} {-y} {s}, one remote raster (an http(s) URL without "
                 "placeholders, /vsicurl/..., /vsis3/...: read by range requests), or none (default: the config "
                 "file's, else the AWS Terrain Tiles)")
      ->type_name("SRC");
  cmd.add_option("--terrain-encoding", o.terrain_encoding,
                 "How tile pixels encode heights (default: the source's metadata, else guessed from its name, "
                 "else terrarium)")
      ->check(CLI::IsMember({"terrarium", "mapbox", "alpinemaps", "float"}, CLI::ignore_case))
      ->type_name("terrarium|mapbox|alpinemaps|float");
  add_scheme_option(cmd, "--terrain-scheme", o.terrain_scheme, "a tile folder");
  cmd.add_option("--terrain-zoom", o.terrain_zoom,
                 "The finest tile level to use (default: the source's finest; fewer downloads when lower)")
      ->check(CLI::Range(0, 24))
      ->type_name("Z");
  cmd.add_flag("--offline", o.offline, "Never touch the network: online sources answer from the disk cache only");
  cmd.add_option("--config", o.config_file,
                 "Configuration file (default: $TRAILRAY_CONFIG, else ~/.config/trailray/config.toml)")
      ->type_name("FILE");
}

void add_imagery_option(CLI::App& cmd, TerrainOptions& o) {
  cmd.add_option("--imagery", o.imagery,
                 "Imagery for the ground's colour: a raster file, a {z}/{x}/{y} tile folder, an .mbtiles file, an "
                 "http(s) URL template, one remote raster (a URL without placeholders, /vsicurl/...), or none: a tint by height (default: the config file's, else EOX Sentinel-2 "
                 "cloudless)")
      ->type_name("SRC");
  add_scheme_option(cmd, "--imagery-scheme", o.imagery_scheme, "an imagery tile folder");
  cmd.add_option("--surface", o.surface,
                 "A surface model beside --terrain (canopy and buildings: a DSM beside a DTM), any source --terrain "
                 "takes: drawn instead of the terrain, the canopy cut away along the tracks under cover; the tracks "
                 "still stand on the terrain (--color-by cover: open, under cover, below the ground)")
      ->type_name("SRC");
  cmd.add_option("--overlay", o.overlay,
                 "Drawn over the imagery, with its legend: a heatmap of `trailray heatmap` (OUT.tif, OUT.mbtiles, "
                 "OUT/), or any imagery source with transparency")
      ->type_name("SRC");
  cmd.add_option("--overlay-opacity", o.overlay_opacity, "The overlay's opacity, 0..1 (default 1: as its tiles say)")
      ->check(CLI::Range(0.0, 1.0))
      ->type_name("F");
  cmd.add_option("--overlay-colormap", o.overlay_colormap,
                 "Colours of a counts GeoTIFF overlay (tiles carry their own): warm (default), magma, viridis, turbo, "
                 "cividis")
      ->type_name("NAME");
}

terrain::TerrainConfig resolve_terrain_config(const TerrainOptions& o) {
  terrain::TerrainConfig c = terrain::load_terrain_config(o.config_file);
  if (!o.terrain.empty()) {
    terrain::SourceSettings s;
    s.source = o.terrain;
    c.terrain = s;
  }
  if (!o.imagery.empty()) {
    terrain::SourceSettings s;
    s.source = o.imagery;
    c.imagery = s;
  }
  if (!o.imagery_scheme.empty()) c.imagery.scheme = scheme_of(o.imagery_scheme);
  if (!o.terrain_encoding.empty()) c.terrain.encoding = terrain::parse_height_encoding(o.terrain_encoding);
  if (!o.terrain_scheme.empty()) c.terrain.scheme = scheme_of(o.terrain_scheme);
  if (o.offline) c.network.offline = true;
  return c;
}

}  // namespace trailray::app
