#pragma once
// Where terrain and imagery come from, how the network is used and where tiles are cached: the
// built-in defaults, overridden by a TOML file ($TRAILRAY_CONFIG, else
// $XDG_CONFIG_HOME/trailray/config.toml, else ~/.config/trailray/config.toml), overridden by
// command-line flags (the app applies those). README.md documents every key.
//
//   [terrain]                                  # [imagery] takes the same keys but `encoding`
//   source = "https://.../{z}/{x}/{y}.png"     # a path (GDAL raster, tile folder, .mbtiles),
//                                              # an http(s) URL template, or "none"
//   encoding = "terrarium"                     # terrarium | mapbox | alpinemaps | float
//   scheme = "xyz"                             # xyz | tms (tile folders)
//   min_zoom = 0
//   max_zoom = 15
//   subdomains = "a,b,c"                       # for {s}
//   attribution = "..."
//   headers = { Authorization = "Bearer ${MY_TOKEN}" }   # ${VAR} read from the environment
//
//   [network]
//   offline = false
//   connect_timeout_s = 10
//   timeout_s = 30
//   retries = 3
//   max_parallel = 6
//
//   [cache]
//   folder = "/path"                           # default $XDG_CACHE_HOME/trailray/tiles
//   max_size_mb = 1024

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "terrain/codecs/height_encoding.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain {

// A configuration file that cannot be read or has a wrong value: "FILE:LINE:COL: message".
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SourceSettings {
  std::string source;  // path, URL template or "none"
  std::optional<HeightEncoding> encoding;
  std::optional<TileScheme> scheme;
  std::optional<int> min_zoom, max_zoom;
  std::string subdomains = "a,b,c";
  std::string attribution;
  std::vector<std::pair<std::string, std::string>> headers;  // values may hold ${VAR}
};

struct NetworkSettings {
  bool offline = false;
  double connect_timeout_s = 10.0;
  double timeout_s = 30.0;
  int retries = 3;
  int max_parallel = 6;
};

struct CacheSettings {
  std::filesystem::path folder;  // empty: the XDG default
  std::uint64_t max_bytes = std::uint64_t{1024} << 20;
};

struct TerrainConfig {
  SourceSettings terrain, imagery;
  NetworkSettings network;
  CacheSettings cache;
  std::filesystem::path file;  // the file read, empty when none
};

// The defaults: elevation from the AWS Terrain Tiles (Terrarium PNG, zoom 0..15, free, no key),
// imagery from EOX's Sentinel-2 cloudless 2016 mosaic (JPEG, zoom 0..14, CC BY 4.0).
TerrainConfig default_terrain_config();

// $TRAILRAY_CONFIG, else the XDG location (which need not exist).
std::filesystem::path default_config_path();

// The defaults overridden by `file` (or by default_config_path() when `file` is empty; a missing
// default file is fine, a missing explicit one is a ConfigError). Unknown keys are errors too: a
// typo should not silently fall back to a default.
TerrainConfig load_terrain_config(const std::filesystem::path& file = {});

// The defaults overridden by the TOML `text`; `file` names it in errors.
TerrainConfig parse_terrain_config(std::string_view text, const std::filesystem::path& file);

}  // namespace trailray::terrain
