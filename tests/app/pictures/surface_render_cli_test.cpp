// `--surface` as a user runs it (issue "surface model beside the terrain"): a made-up place with a
// forest block (surface only) and a ridge (both models), written with GDAL at test time
// (surface_scene.py), and two tracks on the ground: one under the trees, one behind the ridge.
// The forest walk is classed under cover and the other in the open; drawn with the surface, the
// walk shows in full on its forest floor (the canopy cut away), while with the same surface as
// the only terrain it hides under the trees as the other hides behind the ridge.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <string>

#include "app/run_command.hpp"
#include "terrain/codecs/image_codec.hpp"
#include "terrain/tile_fixtures.hpp"
#include "test_support.hpp"

using nlohmann::json;
using trailray::test::run_command;
using trailray::test::shell_quote;
using trailray::test::TempDir;

namespace {

std::string program(const TempDir& home) {
  return "XDG_CONFIG_HOME=" + shell_quote((home.path() / "config").string()) +
         " XDG_CACHE_HOME=" + shell_quote((home.path() / "cache").string()) + " TRAILRAY_CONFIG= " +
         shell_quote(TRAILRAY_BINARY) + " ";
}

// Two straight tracks of 61 points at 601 m (1 m above the flat ground), north-south.
std::string tracks_gpx() {
  const auto track = [](const char* name, double lon, double from, double to) {
    std::string s = std::string("<trk><name>") + name + "</name><trkseg>";
    for (int i = 0; i <= 60; ++i)
      s += "<trkpt lat=\"" + std::to_string(from + (to - from) * i / 60.0) + "\" lon=\"" + std::to_string(lon) +
           "\"><ele>601</ele></trkpt>";
    return s + "</trkseg></trk>";
  };
  return "<gpx version=\"1.1\" creator=\"test\">" + track("Forest", 7.855, 46.702, 46.708) +
         track("Ridge", 7.865, 46.705, 46.709) + "</gpx>";
}

struct Opaque {
  std::size_t red = 0, blue = 0;  // pixels of the tracks' own colours, barely blended
};
Opaque opaque_pixels(const std::string& png) {
  std::ifstream in(png, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  const std::string bytes = s.str();
  const auto image =
      trailray::terrain::decode_image(std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
  Opaque o;
  for (std::size_t i = 0; i + 2 < image.samples8.size(); i += image.channels) {
    const int r = image.samples8[i], g = image.samples8[i + 1], b = image.samples8[i + 2];
    o.red += (r > g + 110 && r > b + 110) ? 1 : 0;
    o.blue += (b > r + 110 && b > g + 70) ? 1 : 0;
  }
  return o;
}

}  // namespace

TEST(SurfaceRenderCli, AWalkUnderTheTreesShowsOnItsFloorARidgeStillHides) {
  TempDir home;
  const std::string dir = home.path().string();
  const auto made = run_command("/usr/bin/python3 " +
                                shell_quote(std::string(TRAILRAY_SOURCE_DIR) + "/tests/app/surface_scene.py") + " " +
                                shell_quote(dir) + " 2>&1");
  ASSERT_EQ(made.status, 0) << "surface_scene.py needs python3-gdal and numpy (scripts/setup.sh): " << made.out;
  const std::string ground = dir + "/ground.tif", surface = dir + "/surface.tif", gpx = dir + "/tracks.gpx";
  std::ofstream(gpx) << tracks_gpx();

  // The classes: the forest walk under cover, the other in the open.
  const auto classed = run_command(program(home) + "elevation --json --terrain " + shell_quote(ground) +
                                   " --surface " + shell_quote(surface) + " " + shell_quote(gpx));
  ASSERT_EQ(classed.status, 0) << classed.out;
  std::size_t forest_covered = 0, ridge_open = 0;
  const json doc = json::parse(classed.out);
  for (const json& p : doc["points"]) {
    const int track = p["track"].get<int>();
    const std::string cover = p["cover"].get<std::string>();
    forest_covered += track == 0 && cover == "covered" ? 1 : 0;
    ridge_open += track == 1 && cover == "open" ? 1 : 0;
  }
  EXPECT_EQ(forest_covered, 61u);
  EXPECT_EQ(ridge_open, 61u);

  // From the south, looking north down the forest walk and at the ridge's southern face.
  const std::string view = " --imagery none --size 640x360 --look-at 46.705,7.860,650 --distance 2000 --heading 0 "
                           "--pitch -20 --color '#ff0000' --color '#0000ff' " + shell_quote(gpx);
  const std::string cut = dir + "/cut.png", canopy = dir + "/canopy.png", bare = dir + "/bare.png";
  const auto drawn = run_command(program(home) + "render --terrain " + shell_quote(ground) + " --surface " +
                                 shell_quote(surface) + view + " -o " + shell_quote(cut) + " 2>&1");
  ASSERT_EQ(drawn.status, 0) << drawn.out;
  ASSERT_EQ(run_command(program(home) + "render --terrain " + shell_quote(surface) + view + " -o " +
                        shell_quote(canopy) + " 2>&1")
                .status,
            0);
  ASSERT_EQ(run_command(program(home) + "render --terrain " + shell_quote(ground) + view + " -o " +
                        shell_quote(bare) + " 2>&1")
                .status,
            0);
  const Opaque with_cut = opaque_pixels(cut), under_canopy = opaque_pixels(canopy), no_trees = opaque_pixels(bare);
  // The walk: in full with the canopy cut away (as without trees at all), hidden under the canopy.
  EXPECT_GT(with_cut.red, 120u);
  EXPECT_GT(with_cut.red, no_trees.red * 6 / 10) << with_cut.red << " against " << no_trees.red;
  EXPECT_GT(with_cut.red * 2, under_canopy.red * 5) << with_cut.red << " against " << under_canopy.red;
  // Behind the ridge: the surface changes nothing (the part the ridge hides stays ghosted).
  EXPECT_GT(no_trees.blue, 30u);
  EXPECT_NEAR(double(with_cut.blue), double(no_trees.blue), 0.1 * double(no_trees.blue) + 5.0);
  EXPECT_NEAR(double(under_canopy.blue), double(no_trees.blue), 0.1 * double(no_trees.blue) + 5.0);
}
