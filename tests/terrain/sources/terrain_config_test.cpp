#include "terrain/sources/terrain_config.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

#include "test_support.hpp"

namespace trailray::terrain {
namespace {

std::string error_of(std::string_view text) {
  try {
    parse_terrain_config(text, "c.toml");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(TerrainConfig, DefaultsAreTheDocumentedOnlineSources) {
  const TerrainConfig c = default_terrain_config();
  EXPECT_NE(c.terrain.source.find("terrarium/{z}/{x}/{y}.png"), std::string::npos);
  EXPECT_EQ(c.terrain.encoding, HeightEncoding::terrarium);
  EXPECT_EQ(c.terrain.max_zoom, 15);
  EXPECT_NE(c.imagery.source.find("s2cloudless"), std::string::npos);
  EXPECT_FALSE(c.network.offline);
  EXPECT_EQ(c.cache.max_bytes, std::uint64_t{1024} << 20);
}

TEST(TerrainConfig, EveryKeyIsRead) {
  const TerrainConfig c = parse_terrain_config(R"(
[terrain]
source = "https://example.org/{z}/{x}/{-y}.webp?key=${KEY}"
encoding = "mapbox"
scheme = "tms"
min_zoom = 2
max_zoom = 13
subdomains = "x,y"
attribution = "Example"
headers = { Authorization = "Bearer ${TOKEN}", "X-Client" = "trailray" }

[imagery]
source = "/data/ortho"
max_zoom = 17

[network]
offline = true
connect_timeout_s = 2.5
timeout_s = 12
retries = 5
max_parallel = 3

[cache]
folder = "/tmp/tiles"
max_size_mb = 20
)",
                                               "c.toml");
  EXPECT_EQ(c.terrain.source, "https://example.org/{z}/{x}/{-y}.webp?key=${KEY}");
  EXPECT_EQ(c.terrain.encoding, HeightEncoding::mapbox);
  EXPECT_EQ(c.terrain.scheme, TileScheme::tms);
  EXPECT_EQ(c.terrain.min_zoom, 2);
  EXPECT_EQ(c.terrain.max_zoom, 13);
  EXPECT_EQ(c.terrain.subdomains, "x,y");
  EXPECT_EQ(c.terrain.attribution, "Example");
  ASSERT_EQ(c.terrain.headers.size(), 2u);
  EXPECT_EQ(c.terrain.headers[0].first, "Authorization");
  EXPECT_EQ(c.terrain.headers[0].second, "Bearer ${TOKEN}");  // expanded per request, not here
  EXPECT_EQ(c.imagery.source, "/data/ortho");
  EXPECT_EQ(c.imagery.max_zoom, 17);
  EXPECT_TRUE(c.imagery.attribution.empty());  // a new source does not inherit the default's
  EXPECT_TRUE(c.network.offline);
  EXPECT_DOUBLE_EQ(c.network.connect_timeout_s, 2.5);
  EXPECT_DOUBLE_EQ(c.network.timeout_s, 12.0);
  EXPECT_EQ(c.network.retries, 5);
  EXPECT_EQ(c.network.max_parallel, 3);
  EXPECT_EQ(c.cache.folder, "/tmp/tiles");
  EXPECT_EQ(c.cache.max_bytes, std::uint64_t{20} << 20);
}

TEST(TerrainConfig, AKeyWithoutSourceKeepsTheDefaultSource) {
  const TerrainConfig c = parse_terrain_config("[terrain]\nmax_zoom = 12\n", "c.toml");
  EXPECT_EQ(c.terrain.source, default_terrain_config().terrain.source);
  EXPECT_EQ(c.terrain.encoding, HeightEncoding::terrarium);
  EXPECT_EQ(c.terrain.max_zoom, 12);
}

TEST(TerrainConfig, MistakesAreReportedWithFileLineAndColumn) {
  EXPECT_EQ(error_of("[terrain]\nsorce = \"x\"\n"), "c.toml:2:1: unknown key `sorce` in [terrain]");
  EXPECT_EQ(error_of("[terain]\n"), "c.toml:1:2: unknown key `terain`");
  EXPECT_EQ(error_of("[terrain]\nencoding = \"rgb\"\n"),
            "c.toml:2:12: unknown encoding `rgb` (terrarium, mapbox, alpinemaps, float)");
  EXPECT_EQ(error_of("[imagery]\nencoding = \"mapbox\"\n"), "c.toml:2:1: unknown key `encoding` in [imagery]");
  EXPECT_EQ(error_of("[terrain]\nmax_zoom = 99\n"), "c.toml:2:12: `max_zoom` must be a whole number from 0 to 30");
  EXPECT_EQ(error_of("[terrain]\nsource = 3\n"), "c.toml:2:10: `source` must be a string");
  EXPECT_EQ(error_of("[network]\noffline = \"yes\"\n"), "c.toml:2:11: `offline` must be true or false");
  EXPECT_NE(error_of("[network]\ntimeout_s = 0\n").find("c.toml:2:13: `timeout_s` must be a number"),
            std::string::npos);
  EXPECT_NE(error_of("[terrain]\nheaders = \"Bearer x\"\n").find("c.toml:2:11: `headers` must be a table"),
            std::string::npos);
  EXPECT_EQ(error_of("terrain = 5\n"), "c.toml:1:11: `terrain` must be a section ([terrain])");
  // Not TOML at all: the parser's own message, positioned.
  EXPECT_EQ(error_of("[terrain\n").rfind("c.toml:1:", 0), 0u) << error_of("[terrain\n");
}

TEST(TerrainConfig, FilesAreOptionalUnlessNamed) {
  test::TempFile empty_home("x", "");
  ::setenv("XDG_CONFIG_HOME", empty_home.path().parent_path().c_str(), 1);
  ::unsetenv("TRAILRAY_CONFIG");
  EXPECT_EQ(load_terrain_config().terrain.source, default_terrain_config().terrain.source);
  EXPECT_THROW(load_terrain_config("/no/such/config.toml"), ConfigError);
  test::TempFile file("config.toml", "[terrain]\nsource = \"none\"\n");
  ::setenv("TRAILRAY_CONFIG", file.str().c_str(), 1);
  EXPECT_EQ(default_config_path(), file.path());
  const TerrainConfig c = load_terrain_config();
  EXPECT_EQ(c.terrain.source, "none");
  EXPECT_EQ(c.file, file.path());
  ::setenv("TRAILRAY_CONFIG", "/no/such/config.toml", 1);
  EXPECT_THROW(load_terrain_config(), ConfigError);
  ::unsetenv("TRAILRAY_CONFIG");
  ::unsetenv("XDG_CONFIG_HOME");
}

}  // namespace
}  // namespace trailray::terrain
