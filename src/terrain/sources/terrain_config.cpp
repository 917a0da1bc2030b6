#include "terrain/sources/terrain_config.hpp"

#include <toml++/toml.h>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

namespace trailray::terrain {
namespace {

std::string where(const std::filesystem::path& file, const toml::source_region& r) {
  std::ostringstream s;
  s << file.string() << ':' << r.begin.line << ':' << r.begin.column;
  return s.str();
}

[[noreturn]] void fail(const std::filesystem::path& file, const toml::node& node, const std::string& message) {
  throw ConfigError(where(file, node.source()) + ": " + message);
}

void check_keys(const std::filesystem::path& file, const toml::table& table, const std::set<std::string>& known,
                const std::string& section) {
  for (const auto& [key, value] : table)
    if (!known.contains(std::string(key.str())))
      throw ConfigError(where(file, key.source()) + ": unknown key `" + std::string(key.str()) + "`" +
                        (section.empty() ? "" : " in [" + section + "]"));
}

std::string get_string(const std::filesystem::path& file, const toml::node& node, const std::string& key) {
  if (auto v = node.value<std::string>()) return *v;
  fail(file, node, "`" + key + "` must be a string");
}

double get_number(const std::filesystem::path& file, const toml::node& node, const std::string& key, double lo,
                  double hi) {
  std::optional<double> v = node.value<double>();
  if (!v || !(*v >= lo && *v <= hi))
    fail(file, node, "`" + key + "` must be a number from " + std::to_string(lo) + " to " + std::to_string(hi));
  return *v;
}

int get_int(const std::filesystem::path& file, const toml::node& node, const std::string& key, int lo, int hi) {
  std::optional<std::int64_t> v = node.value<std::int64_t>();
  if (!v || *v < lo || *v > hi)
    fail(file, node, "`" + key + "` must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
  return static_cast<int>(*v);
}

void read_source(const std::filesystem::path& file, const toml::table& t, SourceSettings& s, bool heights,
                 const std::string& section) {
  std::set<std::string> keys{"source", "scheme", "min_zoom", "max_zoom", "subdomains", "attribution", "headers"};
  if (heights) keys.insert("encoding");
  check_keys(file, t, keys, section);
  if (auto* n = t.get("source")) s.source = get_string(file, *n, "source");
  if (auto* n = t.get("encoding")) {
    const std::string name = get_string(file, *n, "encoding");
    s.encoding = parse_height_encoding(name);
    if (!s.encoding) fail(file, *n, "unknown encoding `" + name + "` (terrarium, mapbox, alpinemaps, float)");
  }
  if (auto* n = t.get("scheme")) {
    s.scheme = parse_tile_scheme(get_string(file, *n, "scheme"));
    if (!s.scheme) fail(file, *n, "`scheme` must be \"xyz\" or \"tms\"");
  }
  if (auto* n = t.get("min_zoom")) s.min_zoom = get_int(file, *n, "min_zoom", 0, geo::kMaxTileZoom);
  if (auto* n = t.get("max_zoom")) s.max_zoom = get_int(file, *n, "max_zoom", 0, geo::kMaxTileZoom);
  if (auto* n = t.get("subdomains")) s.subdomains = get_string(file, *n, "subdomains");
  if (auto* n = t.get("attribution")) s.attribution = get_string(file, *n, "attribution");
  if (auto* n = t.get("headers")) {
    const toml::table* h = n->as_table();
    if (!h)
      fail(file, *n, "`headers` must be a table of strings, e.g. headers = { Authorization = \"Bearer ${TOKEN}\" }");
    s.headers.clear();
    for (const auto& [key, value] : *h)
      s.headers.emplace_back(std::string(key.str()), get_string(file, value, "headers." + std::string(key.str())));
  }
}

}  // namespace

TerrainConfig default_terrain_config() {
  TerrainConfig c;
  c.terrain.source = "https://s3.amazonaws.com/elevation-tiles-prod/terrarium/{z}/{x}/{y}.png";
  c.terrain.encoding = HeightEncoding::terrarium;
  c.terrain.min_zoom = 0;
  c.terrain.max_zoom = 15;
  c.terrain.attribution = "Terrain Tiles (Mapzen, AWS Open Data): SRTM, GMTED2010, NED, ETOPO1 and others";
  c.imagery.source = "https://tiles.maps.eox.at/wmts/1.0.0/s2cloudless_3857/default/g/{z}/{y}/{x}.jpg";
  c.imagery.min_zoom = 0;
  c.imagery.max_zoom = 14;
  c.imagery.attribution =
      "Sentinel-2 cloudless - https://s2maps.eu by EOX IT Services GmbH (Contains modified Copernicus Sentinel data "
      "2016 & 2017)";
  return c;
}

std::filesystem::path default_config_path() {
  if (const char* p = std::getenv("TRAILRAY_CONFIG"); p && *p) return p;
  if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x == '/')
    return std::filesystem::path(x) / "trailray/config.toml";
  if (const char* h = std::getenv("HOME"); h && *h) return std::filesystem::path(h) / ".config/trailray/config.toml";
  return {};
}

TerrainConfig load_terrain_config(const std::filesystem::path& explicit_file) {
  TerrainConfig c = default_terrain_config();
  const char* from_env = std::getenv("TRAILRAY_CONFIG");
  const bool must_exist = !explicit_file.empty() || (from_env && *from_env);
  const std::filesystem::path file = explicit_file.empty() ? default_config_path() : explicit_file;
  if (file.empty()) return c;
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) {
    if (must_exist) throw ConfigError(file.string() + ": configuration file not found");
    return c;
  }
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw ConfigError(file.string() + ": cannot read the configuration file");
  return parse_terrain_config(text.str(), file);
}

TerrainConfig parse_terrain_config(std::string_view text, const std::filesystem::path& file) {
  TerrainConfig c = default_terrain_config();
  toml::table root;
  try {
    root = toml::parse(text, file.string());
  } catch (const toml::parse_error& e) {
    throw ConfigError(where(file, e.source()) + ": " + std::string(e.description()));
  }
  c.file = file;
  check_keys(file, root, {"terrain", "imagery", "network", "cache"}, "");
  auto section = [&](const char* name) -> const toml::table* {
    const toml::node* n = root.get(name);
    if (!n) return nullptr;
    if (!n->is_table()) fail(file, *n, std::string("`") + name + "` must be a section ([" + name + "])");
    return n->as_table();
  };
  if (auto* t = section("terrain")) {
    // A new source does not inherit the default's encoding, zooms or attribution.
    if (t->contains("source")) c.terrain = SourceSettings{};
    read_source(file, *t, c.terrain, true, "terrain");
  }
  if (auto* t = section("imagery")) {
    if (t->contains("source")) c.imagery = SourceSettings{};
    read_source(file, *t, c.imagery, false, "imagery");
  }
  if (auto* t = section("network")) {
    check_keys(file, *t, {"offline", "connect_timeout_s", "timeout_s", "retries", "max_parallel"}, "network");
    if (auto* n = t->get("offline")) {
      if (!n->is_boolean()) fail(file, *n, "`offline` must be true or false");
      c.network.offline = n->value<bool>().value_or(false);
    }
    if (auto* n = t->get("connect_timeout_s"))
      c.network.connect_timeout_s = get_number(file, *n, "connect_timeout_s", 0.1, 3600);
    if (auto* n = t->get("timeout_s")) c.network.timeout_s = get_number(file, *n, "timeout_s", 0.1, 3600);
    if (auto* n = t->get("retries")) c.network.retries = get_int(file, *n, "retries", 0, 20);
    if (auto* n = t->get("max_parallel")) c.network.max_parallel = get_int(file, *n, "max_parallel", 1, 64);
  }
  if (auto* t = section("cache")) {
    check_keys(file, *t, {"folder", "max_size_mb"}, "cache");
    if (auto* n = t->get("folder")) c.cache.folder = get_string(file, *n, "folder");
    if (auto* n = t->get("max_size_mb"))
      c.cache.max_bytes = static_cast<std::uint64_t>(get_number(file, *n, "max_size_mb", 1, 1e7) * 1024 * 1024);
  }
  return c;
}

}  // namespace trailray::terrain
