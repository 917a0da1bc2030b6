// `render --places`: OpenStreetMap places labelled around the tracks. A hike along the ridge of
// Vorder Grauspitz (Liechtenstein) with the Nominatim test file (Liechtenstein and Alabama): only
// the places near the track are read, and they change the picture.
#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>
#include <string>

#include "app/track_cli_support.hpp"
#include "test_support.hpp"
#include "track/places/osm_places_reader.hpp"

namespace trailray::test {
namespace {

const std::string kPlain =
    " --terrain none --no-ssao --no-atmosphere --no-shadows --legend off --size 480x270 "
    "--time 2024-06-18T10:00:00Z --color '#0000ff'";

// 3 km along the ridge west of Vorder Grauspitz (47.0527 N, 9.5813 E), at 2500 m.
std::vector<GpxPoint> ridge() { return east_line(47.0527, 9.5413, 0.0, 60, 50.0, kNoValue, 0.0, 2500.0); }

std::size_t differing_pixels(const Picture& a, const Picture& b) {
  std::size_t n = 0;
  for (std::uint32_t y = 0; y < a.height; ++y)
    for (std::uint32_t x = 0; x < a.width; ++x) {
      const auto p = a.at(x, y), q = b.at(x, y);
      n += std::abs(p.r - q.r) + std::abs(p.g - q.g) + std::abs(p.b - q.b) > 60;
    }
  return n;
}

TEST(PlacesRenderCli, PlacesAroundTheTrackAreDrawnTheRestLeftOut) {
  TRAILRAY_REQUIRE_DATA(osm, "osm/nominatim_apidb-test-data.pbf");
  RenderEnv env;
  const std::string gpx = env.write_gpx("ridge.gpx", {GpxTrack{"Ridge", {ridge()}}});
  const std::string with = env.file("with.png"), without = env.file("without.png");
  auto r = run_command(env.prefix() + shell_quote(gpx) + kPlain + " --verbose --places " + shell_quote(osm.string()) +
                       " -o " + shell_quote(with) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"((\d+) places from )"))) << r.out;
  const std::size_t drawn = std::stoul(m[1]);
  // The file's places: Alabama's are 7,000 km away, and most of Liechtenstein more than 5 km.
  const std::size_t all = track::places::read_osm_places(osm.string()).size();
  EXPECT_GT(drawn, 5u);
  EXPECT_LT(drawn * 2, all) << drawn << " of " << all;
  r = run_command(env.prefix() + shell_quote(gpx) + kPlain + " -o " + shell_quote(without) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  // Labels and pins: hundreds of pixels.
  EXPECT_GT(differing_pixels(read_picture(with), read_picture(without)), 300u);

  // --hidden-labels hide and --no-waypoints take them as they take the others'.
  r = run_command(env.prefix() + shell_quote(gpx) + kPlain + " --hidden-labels hide --no-waypoints --places " +
                  shell_quote(osm.string()) + " -o " + shell_quote(env.file("none.png")) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(differing_pixels(read_picture(env.file("none.png")), read_picture(without)), 0u);
}

TEST(PlacesRenderCli, TheOptionIsInEveryDrawingCommandAndABadFileIsAnError) {
  for (const std::string command : {"render", "view", "video", "serve", "stats"}) {
    const auto r = run_command(shell_quote(TRAILRAY_BINARY) + " " + command + " --help 2>&1");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("--places"), std::string::npos) << command << " --help lacks --places";
  }
  RenderEnv env;
  const std::string gpx = env.write_gpx("ridge.gpx", {GpxTrack{"Ridge", {ridge()}}});
  const std::string bad = env.file("bad.osm");
  std::ofstream(bad) << "<osm><node id='1' lat='47.05' lon='9.5'";
  const auto r = run_command(env.prefix() + shell_quote(gpx) + kPlain + " --places " + shell_quote(bad) + " -o " +
                             shell_quote(env.file("x.png")) + " 2>&1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("bad.osm: cannot read OpenStreetMap data"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace trailray::test
