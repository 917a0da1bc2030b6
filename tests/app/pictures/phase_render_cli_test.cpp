// `trailray render --color-by phase` on a real flight: one thermal marker per thermal that gained
// height (as the flight analysis of the file finds them), drawn in their orange; --no-thermals
// leaves them out; the warm climb colours and the gliding blue are in the picture.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "app/run_command.hpp"
#include "terrain/codecs/image_codec.hpp"
#include "terrain/tile_fixtures.hpp"
#include "test_support.hpp"
#include "track/flight/flight_analysis.hpp"
#include "track/io/load.hpp"

using trailray::test::run_command;
using trailray::test::shell_quote;
using trailray::test::TempDir;

namespace {

std::string render_command(const TempDir& home) {
  return "XDG_CONFIG_HOME=" + shell_quote((home.path() / "config").string()) +
         " XDG_CACHE_HOME=" + shell_quote((home.path() / "cache").string()) +
         " TRAILRAY_CONFIG= " + shell_quote(TRAILRAY_BINARY) +
         " render --imagery none --terrain none --size 480x270 --verbose ";
}

trailray::terrain::DecodedImage read_png(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  const std::string bytes = s.str();
  return trailray::terrain::decode_image(std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
}

struct Counts {
  std::size_t blue = 0, warm = 0;
};
Counts colours(const trailray::terrain::DecodedImage& image) {
  Counts c;
  for (std::size_t i = 0; i + 2 < image.samples8.size(); i += image.channels) {
    const int r = image.samples8[i], g = image.samples8[i + 1], b = image.samples8[i + 2];
    c.blue += (b > r + 60 && b > g + 20) ? 1 : 0;
    c.warm += (r > b + 90 && r > 150) ? 1 : 0;
  }
  return c;
}

}  // namespace

TEST(PhaseRenderCli, MarksEachThermalThatGainedHeight) {
  TRAILRAY_REQUIRE_DATA(flight, "igc/goigc_0192_kitzbuehel.igc");
  const auto read = trailray::track::load_track_file(flight.string());
  ASSERT_TRUE(read.ok());
  std::size_t gained = 0;
  for (const auto& f : trailray::track::flight::analyse_flights(read.file.tracks.at(0)).flights)
    for (const auto& th : f.thermals) gained += th.gain_m > 0.0 ? 1 : 0;
  ASSERT_GT(gained, 0u) << "the flight has thermals";

  TempDir home;
  const std::string with = (home.path() / "with.png").string(), without = (home.path() / "without.png").string();
  const auto marked = run_command(render_command(home) + shell_quote(flight.string()) + " --color-by phase -o " +
                                  shell_quote(with) + " 2>&1");
  ASSERT_EQ(marked.status, 0) << marked.out;
  EXPECT_NE(marked.out.find(std::to_string(gained) + " thermal markers"), std::string::npos) << marked.out;
  const auto plain = run_command(render_command(home) + shell_quote(flight.string()) +
                                 " --color-by phase --no-thermals -o " + shell_quote(without) + " 2>&1");
  ASSERT_EQ(plain.status, 0) << plain.out;
  EXPECT_EQ(plain.out.find("thermal marker"), std::string::npos) << plain.out;
  const auto a = read_png(with), b = read_png(without);
  ASSERT_EQ(a.samples8.size(), b.samples8.size());
  EXPECT_NE(a.samples8, b.samples8) << "the markers and their labels are drawn";
  const Counts c = colours(b);
  EXPECT_GT(c.blue, 500u) << "the glides in blue";
  EXPECT_GT(c.warm, 50u) << "the thermals in warm colours";

  const auto both = run_command(render_command(home) + shell_quote(flight.string()) + " --thermals --no-thermals -o " +
                                shell_quote(without) + " 2>&1");
  EXPECT_EQ(both.status, 2) << both.out;
}
