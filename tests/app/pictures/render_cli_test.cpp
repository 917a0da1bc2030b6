// `trailray render` as a user runs it: a PNG of the requested size with terrain in it from the
// shared Interlaken DEM and flight, the neutral ground with --terrain none, option errors,
// --no-shadows, the --profile table.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "app/options/camera_options.hpp"
#include "app/run_command.hpp"
#include "terrain/codecs/image_codec.hpp"
#include "terrain/tile_fixtures.hpp"
#include "test_support.hpp"

using trailray::test::run_command;
using trailray::test::shell_quote;
using trailray::test::TempDir;

namespace {

struct Env {
  TempDir home;
  std::string prefix() const {
    return "XDG_CONFIG_HOME=" + shell_quote((home.path() / "config").string()) +
           " XDG_CACHE_HOME=" + shell_quote((home.path() / "cache").string()) +
           " TRAILRAY_CONFIG= " + shell_quote(TRAILRAY_BINARY) + " render --imagery none ";
  }
  std::string out() const { return (home.path() / "out.png").string(); }
};

trailray::terrain::DecodedImage read_png(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  const std::string bytes = s.str();
  return trailray::terrain::decode_image(std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
}

struct Rgb {
  int r, g, b;
};
Rgb pixel(const trailray::terrain::DecodedImage& image, std::uint32_t x, std::uint32_t y) {
  const std::size_t i = (std::size_t{y} * image.width + x) * image.channels;
  return {image.samples8[i], image.samples8[i + 1], image.samples8[i + 2]};
}
// The hypsometric tint of low and middle heights: more green than red and blue.
bool tinted(const Rgb& p) { return p.g > p.r + 5 && p.g > p.b + 5; }
bool grey(const Rgb& p) { return std::abs(p.r - p.g) <= 3 && std::abs(p.g - p.b) <= 6; }

}  // namespace

TEST(RenderCli, FramesTheInterlakenFlightOnTheSharedDem) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/interlaken_dhm25_wgs84.tif");
  TRAILRAY_REQUIRE_DATA(flight, "igc/goigc_0100_interlaken.igc");
  Env env;
  const auto r = run_command(env.prefix() + shell_quote(flight.string()) + " --terrain " + shell_quote(dem.string()) +
                             " --size 320x180 -o " + shell_quote(env.out()) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto image = read_png(env.out());
  ASSERT_EQ(image.width, 320u);
  ASSERT_EQ(image.height, 180u);
  ASSERT_GE(image.channels, 3u);
  // The framed flight is over the DEM: most of the picture is tinted terrain.
  std::size_t terrain = 0;
  for (std::uint32_t y = 0; y < 180; y += 4)
    for (std::uint32_t x = 0; x < 320; x += 4) terrain += tinted(pixel(image, x, y)) ? 1 : 0;
  EXPECT_GT(terrain, 80u * 45u / 2u) << "tinted pixels of 3600 sampled";
  EXPECT_EQ(r.out.find("neutral ground"), std::string::npos) << r.out;
}

TEST(RenderCli, TerrainNoneDrawsTheNeutralGroundUnderTheSky) {
  Env env;
  const auto r = run_command(
      env.prefix() + "--terrain none --camera 46.7,7.85,1500,0,-5 --size 160x90 --time 2024-06-18T11:00:00Z -o " +
      shell_quote(env.out()) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("neutral ground"), std::string::npos) << r.out;
  const auto image = read_png(env.out());
  ASSERT_EQ(image.width, 160u);
  ASSERT_EQ(image.height, 90u);
  const Rgb sky = pixel(image, 80, 0), ground = pixel(image, 80, 89);
  EXPECT_GT(sky.b, sky.r + 30) << "the top row is sky blue";
  EXPECT_TRUE(grey(ground)) << ground.r << "," << ground.g << "," << ground.b;
  EXPECT_FALSE(tinted(ground));
}

TEST(RenderCli, WrongOptionValuesGetMessages) {
  Env env;
  const std::string o = " -o " + shell_quote(env.out()) + " --terrain none";
  struct Case {
    std::string args, expected;
  };
  const Case cases[] = {
      {"--camera 46.7,7.85,1500,0,-5 --size 100", "WxH"},
      {"--camera 46.7,7.85,1500,0,-5 --size 0x90", "WxH"},
      {"--camera 46.7,7.85", "LAT,LON,ALT,HEADING,PITCH"},
      {"--camera 46.7,7.85,1500,0,-120", "pitch"},
      {"", "--camera LAT,LON,ALT,HEADING,PITCH or --look-at"},
      {"--camera 46.7,7.85,1500,0,-5 --look-at 46.7,7.85,1000", "exclude"},
      {"--camera 46.7,7.85,1500,0,-5 --distance 500", "--look-at"},
      {"--camera 46.7,7.85,1500,0,-5 --time yesterday", "ISO 8601"},
      {"--camera 46.7,7.85,1500,0,-5 --fov 200", "--fov"},
      {"--camera 46.7,7.85,1500,0,-5 --timeout 0", "--timeout"},
      {"--camera 46.7,7.85,1500,0,-5 --label-size 2", "--label-size"},
      {"--camera 46.7,7.85,1500,0,-5 --hidden-labels fade", "neither ghost nor hide"},
      {"--camera 46.7,7.85,1500,0,-5 --pixel-ratio 0", "--pixel-ratio"},
  };
  for (const Case& c : cases) {
    const auto r = run_command(env.prefix() + c.args + o + " 2>&1");
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.out;
    EXPECT_NE(r.out.find(c.expected), std::string::npos) << c.args << "\n" << r.out;
  }
  EXPECT_FALSE(std::filesystem::exists(env.out()));
}

TEST(RenderCli, ImageSizeParsing) {
  using trailray::app::parse_image_size;
  ASSERT_TRUE(parse_image_size("320x180"));
  EXPECT_EQ(parse_image_size("320x180")->width, 320u);
  EXPECT_EQ(parse_image_size("320X180")->height, 180u);
  for (const char* bad : {"", "x", "320", "320x", "x180", "0x10", "10x0", "-1x10", "16385x10", "10x10x10", "1.5x2"})
    EXPECT_FALSE(parse_image_size(bad)) << bad;
}

// Over the shared DEM with a low sun from the west-northwest: cast shadows darken part of the
// picture, and --no-shadows takes them away (nothing gets darker without them).
TEST(RenderCli, NoShadowsChangesThePicture) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/interlaken_dhm25_wgs84.tif");
  Env env;
  const std::string common = env.prefix() + "--terrain " + shell_quote(dem.string()) +
                             " --look-at 46.705,7.872,900 --distance 10500 --heading 18 --pitch -22"
                             " --time 2024-06-18T17:30:00Z --size 240x135 -o ";
  const std::string without = (env.home.path() / "no_shadows.png").string();
  const auto a = run_command(common + shell_quote(env.out()) + " 2>&1");
  ASSERT_EQ(a.status, 0) << a.out;
  const auto b = run_command(common + shell_quote(without) + " --no-shadows 2>&1");
  ASSERT_EQ(b.status, 0) << b.out;
  const auto shadowed = read_png(env.out()), plain = read_png(without);
  ASSERT_EQ(shadowed.width, plain.width);
  std::size_t darker = 0, brighter = 0;
  for (std::uint32_t y = 0; y < 135; ++y)
    for (std::uint32_t x = 0; x < 240; ++x) {
      const Rgb s = pixel(shadowed, x, y), p = pixel(plain, x, y);
      const int diff = (s.r + s.g + s.b) - (p.r + p.g + p.b);
      darker += diff < -15 ? 1 : 0;
      brighter += diff > 3 ? 1 : 0;
    }
  EXPECT_GT(darker, 240u * 135u / 50u) << "pixels in cast shadow";
  EXPECT_EQ(brighter, 0u) << "shadows only take light away";
}

// --snow whitens the ground from the snowline up: with the line at 1500 m the ridges of the
// Interlaken DEM (up to 2004 m) turn white and only get brighter; with the line above every
// summit nothing changes, so the cover follows altitude, not a global tint.
TEST(RenderCli, SnowCoversTheGroundAboveTheSnowline) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/interlaken_dhm25_wgs84.tif");
  Env env;
  const std::string common = env.prefix() + "--terrain " + shell_quote(dem.string()) +
                             " --look-at 46.705,7.872,900 --distance 10500 --heading 18 --pitch -22"
                             " --time 2024-06-18T13:30:00Z --size 240x135 -o ";
  auto render = [&](const std::string& name, const std::string& extra) {
    const std::string path = (env.home.path() / name).string();
    const auto r = run_command(common + shell_quote(path) + " " + extra + " 2>&1");
    EXPECT_EQ(r.status, 0) << r.out;
    return read_png(path);
  };
  const auto plain = render("plain.png", ""), low = render("low.png", "--snow --snowline 1500"),
             high = render("high.png", "--snow --snowline 6000");
  std::size_t whiter = 0, darker = 0, changed_high = 0;
  for (std::uint32_t y = 0; y < 135; ++y)
    for (std::uint32_t x = 0; x < 240; ++x) {
      const Rgb p = pixel(plain, x, y), l = pixel(low, x, y), h = pixel(high, x, y);
      const int diff = (l.r + l.g + l.b) - (p.r + p.g + p.b);
      whiter += diff > 30 ? 1 : 0;
      darker += diff < -3 ? 1 : 0;
      changed_high += std::abs((h.r + h.g + h.b) - (p.r + p.g + p.b)) > 3 ? 1 : 0;
    }
  EXPECT_GT(whiter, 240u * 135u / 100u) << "snow on the ridges";
  EXPECT_EQ(darker, 0u) << "snow only brightens the ground";
  EXPECT_EQ(changed_high, 0u) << "a snowline above every summit changes nothing";
}

// Real imagery over a real DEM: the shared AlpineMaps orthophotos (a TMS folder of z7 JPEGs)
// drape the Austria DEM only when their rows are read as TMS.
TEST(RenderCli, ImageryFromATmsFolderDrapesTheDem) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/austria_1km_wgs84.tif");
  TRAILRAY_REQUIRE_DATA(ortho, "tiles/alpinemaps_ortho");
  Env env;
  // Env's prefix says --imagery none: this test names its own imagery instead.
  std::string prefix = env.prefix();
  prefix.erase(prefix.find("--imagery none "), std::string("--imagery none ").size());
  const std::string common = prefix + "--terrain " + shell_quote(dem.string()) + " --imagery " +
                             shell_quote(ortho.string()) +
                             " --look-at 47.1,13.0,1500 --distance 90000 --heading 0 --pitch -30"
                             " --time 2024-06-18T10:00:00Z --size 160x90 --verbose -o " +
                             shell_quote(env.out());
  const auto tms = run_command(common + " --imagery-scheme tms 2>&1");
  ASSERT_EQ(tms.status, 0) << tms.out;
  const auto xyz = run_command(common + " 2>&1");
  ASSERT_EQ(xyz.status, 0) << xyz.out;
  auto imagery_tiles = [](const std::string& log) {
    const auto at = log.find(" with imagery)");
    if (at == std::string::npos) return -1;
    const auto start = log.rfind(' ', at - 1);
    return std::stoi(log.substr(start + 1, at - start - 1));
  };
  EXPECT_GT(imagery_tiles(tms.out), 0) << tms.out;
  EXPECT_EQ(imagery_tiles(xyz.out), 0) << xyz.out;  // read as XYZ the rows land elsewhere: no imagery here
  // --verbose also says what the terrain holds on the GPU: meshes for every tile drawn, and
  // textures for the imagery tiles.
  const std::regex gpu(
      R"(GPU memory for terrain: meshes ([0-9.]+) MiB \(([0-9]+) tiles\), imagery ([0-9.]+) MiB \(([0-9]+) tiles\))");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(tms.out, m, gpu)) << tms.out;
  EXPECT_GT(std::stod(m[1]), 0.0);
  EXPECT_GT(std::stoi(m[2]), 0);
  EXPECT_GT(std::stod(m[3]), 0.0);
  EXPECT_GE(std::stoi(m[4]), imagery_tiles(tms.out) > 0 ? 1 : 0);
}

// --profile --frames 3: the picture, and on standard error a table with a row per pass of the
// frame, with times where a pass ran and n/a where none does yet.
TEST(RenderCli, ProfilePrintsATableOfThePasses) {
  Env env;
  const std::string err = (env.home.path() / "stderr.txt").string();
  const auto r = run_command(env.prefix() +
                             "--terrain none --camera 46.7,7.85,1500,0,-5 --size 160x90 --time 2024-06-18T11:00:00Z "
                             "--profile --frames 3 -o " +
                             shell_quote(env.out()) + " 2>" + shell_quote(err));
  if (r.status != 0) {
    std::ifstream failed(err);
    FAIL() << "status " << r.status << ", standard error:\n" << std::string(std::istreambuf_iterator<char>(failed), {});
  }
  EXPECT_TRUE(std::filesystem::exists(env.out()));
  std::ifstream in(err);
  std::map<std::string, std::vector<std::string>> rows;
  std::string header;
  for (std::string line; std::getline(in, line);) {
    if (line.find("frames") != std::string::npos) header = line;
    std::istringstream words(line);
    std::string name, cell;
    words >> name;
    while (words >> cell) rows[name].push_back(cell);
  }
  EXPECT_NE(header.find("3 of 3 frames"), std::string::npos) << header;
  for (const char* pass : {"shadows", "tiles", "tracks", "ssao", "compose", "atmosphere", "overlays"}) {
    ASSERT_EQ(rows[pass].size(), 4u) << pass;
  }
  for (const char* timed : {"shadows", "tiles", "ssao", "compose"}) {
    const std::string& cpu_median = rows[timed][1];
    char* end = nullptr;
    const double ms = std::strtod(cpu_median.c_str(), &end);
    EXPECT_EQ(*end, '\0') << timed << ": " << cpu_median;
    EXPECT_GT(ms, 0.0) << timed;
  }
  for (const char* untimed : {"tracks", "atmosphere", "overlays"})
    for (const std::string& cell : rows[untimed]) EXPECT_EQ(cell, "n/a") << untimed;
}

TEST(RenderCli, FramesGoWithProfile) {
  Env env;
  const std::string o = " --terrain none --camera 46.7,7.85,1500,0,-5 --size 16x16 -o " + shell_quote(env.out());
  for (const std::string& args : {std::string("--frames 3"), std::string("--profile --frames 0")}) {
    const auto r = run_command(env.prefix() + args + o + " 2>&1");
    EXPECT_EQ(r.status, 2) << args << "\n" << r.out;
    EXPECT_NE(r.out.find("--frames"), std::string::npos) << args << "\n" << r.out;
  }
}

// Tracks on both sides of the Earth: the picture frames the largest group of tracks near each
// other (two in the Alps, not the one in New Zealand), with a warning that says so.
TEST(RenderCli, TracksFarApartFrameTheLargestGroupWithAWarning) {
  Env env;
  const auto gpx = [&](const std::string& name, double lat, double lon) {
    std::string text = R"(<gpx version="1.1"><trk><trkseg>)";
    for (int i = 0; i < 20; ++i)
      text += "<trkpt lat=\"" + std::to_string(lat + 0.001 * i) + "\" lon=\"" + std::to_string(lon) + "\"><ele>" +
              std::to_string(1500 + i) + "</ele></trkpt>";
    const std::string path = (env.home.path() / name).string();
    std::ofstream(path) << text << "</trkseg></trk></gpx>";
    return shell_quote(path);
  };
  const std::string files =
      gpx("interlaken.gpx", 46.7, 7.85) + " " + gpx("nz.gpx", -43.5, 172.6) + " " + gpx("engadin.gpx", 46.6, 10.0);
  const auto r = run_command(env.prefix() + "--terrain none --size 160x90 --verbose --time 2024-06-18T11:00:00Z -o " +
                             shell_quote(env.out()) + " " + files + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("too far apart for one view: it shows the 2 of 3"), std::string::npos) << r.out;
  // The camera (--verbose) looks at the Alps from a regional height.
  const std::smatch m = [&] {
    std::smatch found;
    std::regex_search(r.out, found, std::regex(R"(camera (-?[0-9.]+),(-?[0-9.]+),([0-9.]+) m)"));
    return found;
  }();
  ASSERT_EQ(m.size(), 4u) << r.out;
  EXPECT_NEAR(std::stod(m[1]), 46.0, 2.0);
  EXPECT_NEAR(std::stod(m[2]), 9.0, 2.0);
  EXPECT_LT(std::stod(m[3]), 400000.0);
}

TEST(RenderCli, WithoutTerrainNoImageryIsAskedFor) {
  // Imagery only colours the terrain: with --terrain none none is opened, so no server is asked
  // (nothing listens on port 1: asking would warn that it is unreachable), and the user is told.
  Env env;
  const std::string binary = "XDG_CONFIG_HOME=" + shell_quote((env.home.path() / "config").string()) +
                             " XDG_CACHE_HOME=" + shell_quote((env.home.path() / "cache").string()) +
                             " TRAILRAY_CONFIG= " + shell_quote(TRAILRAY_BINARY);
  const auto r = run_command(binary + " render --terrain none --imagery 'http://127.0.0.1:1/{z}/{x}/{y}.png'" +
                             " --camera 46.7,7.85,1500,0,-5 --size 160x90 -o " + shell_quote(env.out()) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("--terrain none: the ground is drawn plain"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("unreachable"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("imagery:"), std::string::npos) << r.out;
}
