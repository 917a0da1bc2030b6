// `--airspace FILE` as a user runs it: in `render` the airspaces around the camera tint the
// picture and the note says how many were drawn, a broken file stops with FILE:LINE, an unknown
// record is a warning; in `view` hovering a wall prints the airspace's name, class and limits.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "app/run_command.hpp"
#include "app/xvfb_command.hpp"
#include "terrain/tile_fixtures.hpp"
#include "test_support.hpp"

using trailray::test::run_command;
using trailray::test::shell_quote;
using trailray::test::TempDir;
using trailray::test::xvfb_command_prefix;

namespace {

struct Env {
  TempDir home;
  std::string command(const std::string& args) const {
    return "XDG_CONFIG_HOME=" + shell_quote((home.path() / "config").string()) +
           " XDG_CACHE_HOME=" + shell_quote((home.path() / "cache").string()) +
           " TRAILRAY_CONFIG= " + shell_quote(TRAILRAY_BINARY) +
           " render --imagery none --terrain none --camera 46.70,7.85,1500,0,-5 --size 64x48 " + args + " 2>&1";
  }
  std::string path(const std::string& name) const { return (home.path() / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name)) << text;
    return path(name);
  }
};

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A class D box 4-9 km north of the camera, 1000-3000 ft, with a record nobody knows.
const char* kBox =
    "AC D\nAN TEST BOX\nAL 1000 ft\nAH 3000 ft\nXX what\n"
    "DP 46:42:30 N 007:48:00 E\nDP 46:42:30 N 007:54:00 E\nDP 46:45:00 N 007:54:00 E\nDP 46:45:00 N 007:48:00 E\n";

}  // namespace

TEST(RenderAirspaceCli, AnAirspaceInViewChangesThePictureAndIsCounted) {
  Env env;
  const auto plain = run_command(env.command("-o " + shell_quote(env.path("plain.png"))));
  ASSERT_EQ(plain.status, 0) << plain.out;
  const std::string file = env.write("box.txt", kBox);
  const auto drawn =
      run_command(env.command("--verbose --airspace " + shell_quote(file) + " -o " + shell_quote(env.path("box.png"))));
  ASSERT_EQ(drawn.status, 0) << drawn.out;
  EXPECT_NE(drawn.out.find(file + ": 1 of 1 airspaces drawn"), std::string::npos) << drawn.out;
  EXPECT_NE(drawn.out.find(file + ":5:1: unknown OpenAir record 'XX'"), std::string::npos) << drawn.out;
  EXPECT_NE(bytes_of(env.path("plain.png")), bytes_of(env.path("box.png")));
}

TEST(ViewAirspaceCli, HoveringAWallPrintsTheAirspaceAndTheSkyNothing) {
  Env env;
  // A box 1 km wide up to 300 m around the point looked at from 1.4 km south, 10 degrees down:
  // the view's centre meets its south wall 900 m away (84 m up) before the ground; the top row
  // looks 12.5 degrees up, over its ceiling.
  const std::string file = env.write("box.txt",
                                     "AC D\nAN BOX\nAL GND\nAH 300m MSL\n"
                                     "DP 46:41:44 N 007:50:36 E\nDP 46:41:44 N 007:51:24 E\n"
                                     "DP 46:42:16 N 007:51:24 E\nDP 46:42:16 N 007:50:36 E\n");
  const std::string script = env.write("hover.txt", "hover 240 135\nprint-hover\nhover 240 1\nprint-hover\n");
  const std::string command =
      "XDG_CONFIG_HOME=" + shell_quote(env.path("config")) + " XDG_CACHE_HOME=" + shell_quote(env.path("cache")) +
      " TRAILRAY_CONFIG= " + xvfb_command_prefix(env.path("Xauthority")) + shell_quote(TRAILRAY_BINARY) +
      " view --imagery none --terrain none --look-at 46.70,7.85,0 --distance 1400 --heading 0 --pitch -10"
      " --size 480x270 --airspace " +
      shell_quote(file) + " --script " + shell_quote(script) + " 2>&1";
  const auto r = run_command(command);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("hover: airspace 0 'BOX'\n  BOX\n  class: D\n  floor: GND\n  ceiling: 300m MSL"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("hover: none"), std::string::npos) << "over the ceiling\n" << r.out;
}

TEST(RenderAirspaceCli, ABrokenFileStopsWithItsLine) {
  Env env;
  const std::string file = env.write("bad.txt", "AC D\nAN BAD\nAL 1000 ft\nAH 3000 ft\nDP 46:4x:00 N 007:50:00 E\n");
  const auto r = run_command(env.command("--airspace " + shell_quote(file) + " -o " + shell_quote(env.path("x.png"))));
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find(file + ":5:"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(env.path("x.png")));
}
