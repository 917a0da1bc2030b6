#include "app/terrain_options.hpp"

namespace trailray::app {

void add_terrain_options(CLI::App& cmd, TerrainOptions& o) {
  cmd.add_option("--terrain", o.terrain,
                 "Elevation source: a raster file (GeoTIFF, .hgt, VRT, ...), a {z}/{x}/{y} tile folder, an .mbtiles "
                 "file, an http(s) URL template with {z} {x} {y} {-y} {s}, or none (default: the config file's, "
                 "else the AWS Terrain Tiles)")
      ->type_name("SRC");
  cmd.add_option("--terrain-encoding", o.terrain_encoding,
                 "How tile pixels encode heights (default: the source's metadata, else guessed from its name, "
                 "else terrarium)")
      ->check(CLI::IsMember({"terrarium", "mapbox", "alpinemaps", "float"}, CLI::ignore_case))
      ->type_name("terrarium|mapbox|alpinemaps|float");
  cmd.add_option("--terrain-scheme", o.terrain_scheme,
                 "Row order of a tile folder: xyz (from the north) or tms (from the south); default: its metadata, "
                 "else xyz")
      ->check(CLI::IsMember({"xyz", "tms"}, CLI::ignore_case))
      ->type_name("xyz|tms");
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
                 "http(s) URL template, or none: a tint by height (default: the config file's, else EOX Sentinel-2 "
                 "cloudless)")
      ->type_name("SRC");
  cmd.add_option("--imagery-scheme", o.imagery_scheme,
                 "Row order of an imagery tile folder: xyz (from the north) or tms (from the south); default: its "
                 "metadata, else xyz")
      ->check(CLI::IsMember({"xyz", "tms"}, CLI::ignore_case))
      ->type_name("xyz|tms");
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
  if (!o.imagery_scheme.empty())
    c.imagery.scheme = o.imagery_scheme == "tms" || o.imagery_scheme == "TMS" ? terrain::TileScheme::tms
                                                                              : terrain::TileScheme::xyz;
  if (!o.terrain_encoding.empty()) c.terrain.encoding = terrain::parse_height_encoding(o.terrain_encoding);
  if (!o.terrain_scheme.empty())
    c.terrain.scheme = o.terrain_scheme == "tms" || o.terrain_scheme == "TMS" ? terrain::TileScheme::tms
                                                                                : terrain::TileScheme::xyz;
  if (o.offline) c.network.offline = true;
  return c;
}

}  // namespace trailray::app
