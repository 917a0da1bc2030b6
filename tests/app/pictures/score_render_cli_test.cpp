// `trailray render --score`: the XC score of a real flight drawn over it (legs in magenta), and
// the option's errors.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "app/run_command.hpp"
#include "terrain/codecs/image_codec.hpp"
#include "terrain/tile_fixtures.hpp"
#include "test_support.hpp"

using trailray::test::run_command;
using trailray::test::shell_quote;
using trailray::test::TempDir;

namespace {

std::string render_command(const TempDir& home) {
  return "XDG_CONFIG_HOME=" + shell_quote((home.path() / "config").string()) +
         " XDG_CACHE_HOME=" + shell_quote((home.path() / "cache").string()) +
         " TRAILRAY_CONFIG= " + shell_quote(TRAILRAY_BINARY) + " render --imagery none --terrain none --size 480x270 ";
}

trailray::terrain::DecodedImage read_png(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  const std::string bytes = s.str();
  return trailray::terrain::decode_image(std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
}

// Pixels close to the scored legs' magenta (kScoredLegsColor) after shading.
std::size_t magenta_pixels(const trailray::terrain::DecodedImage& image) {
  std::size_t n = 0;
  for (std::size_t i = 0; i + 2 < image.samples8.size(); i += image.channels) {
    const int r = image.samples8[i], g = image.samples8[i + 1], b = image.samples8[i + 2];
    n += (r > 150 && b > 120 && g < 90) ? 1 : 0;
  }
  return n;
}

}  // namespace

TEST(ScoreRenderCli, DrawsTheScoredTriangleOverTheFlight) {
  TRAILRAY_REQUIRE_DATA(flight, "igc/scoring/xcscore_tri.igc");
  TempDir home;
  const std::string with = (home.path() / "with.png").string(), without = (home.path() / "without.png").string();
  const auto plain =
      run_command(render_command(home) + shell_quote(flight.string()) + " -o " + shell_quote(without) + " 2>&1");
  ASSERT_EQ(plain.status, 0) << plain.out;
  const auto scored = run_command(render_command(home) + shell_quote(flight.string()) +
                                  " --score --score-rules xcontest -o " + shell_quote(with) + " 2>&1");
  ASSERT_EQ(scored.status, 0) << scored.out;
  const auto a = read_png(without), b = read_png(with);
  ASSERT_EQ(a.samples8.size(), b.samples8.size());
  EXPECT_NE(a.samples8, b.samples8);
  EXPECT_GT(magenta_pixels(b), magenta_pixels(a) + 50) << "the legs are drawn in magenta";
}

TEST(ScoreRenderCli, UnknownRulesAndNoIgcAreErrors) {
  TempDir home;
  const auto gpx = home.path() / "t.gpx";
  std::ofstream(gpx) << R"(<?xml version="1.0"?><gpx version="1.1" creator="t"><trk><trkseg>)"
                     << R"(<trkpt lat="46.0" lon="7.0"><ele>1000</ele></trkpt>)"
                     << R"(<trkpt lat="46.01" lon="7.01"><ele>1010</ele></trkpt>)"
                     << "</trkseg></trk></gpx>";
  const std::string out = " -o " + shell_quote((home.path() / "o.png").string()) + " 2>&1";
  const auto bad_rules =
      run_command(render_command(home) + shell_quote(gpx.string()) + " --score --score-rules nosuch" + out);
  EXPECT_NE(bad_rules.status, 0);
  EXPECT_NE(bad_rules.out.find("--score-rules"), std::string::npos) << bad_rules.out;
  const auto no_igc = run_command(render_command(home) + shell_quote(gpx.string()) + " --score" + out);
  EXPECT_NE(no_igc.status, 0);
  EXPECT_NE(no_igc.out.find("--score needs an IGC file"), std::string::npos) << no_igc.out;
}
