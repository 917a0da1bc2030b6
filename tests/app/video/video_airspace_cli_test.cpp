// `trailray video --airspace FILE`: the airspaces `render` and `view` draw are in the film too,
// read and placed by the same code (a tiny film without terrain, a second of it).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "app/track_cli_support.hpp"

namespace trailray::test {
namespace {

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A class D box 4-9 km north of the camera, 1000-3000 ft (as in airspace_cli_test).
const char* kBox =
    "AC D\nAN TEST BOX\nAL 1000 ft\nAH 3000 ft\n"
    "DP 46:42:30 N 007:48:00 E\nDP 46:42:30 N 007:54:00 E\nDP 46:45:00 N 007:54:00 E\nDP 46:45:00 N 007:48:00 E\n";

TEST(VideoAirspaceCli, AnAirspaceInViewIsInTheFilm) {
  RenderEnv env;
  // A hike east at the camera's place, 10 minutes, at 200 m (the neutral ground: the box's floor,
  // 305 m, is above it); the camera looks north over it at the box, no overlay over the frame.
  const std::string gpx =
      env.write_gpx("hike.gpx", {{"Hike", {east_line(46.70, 7.85, 0.0, 61, 25.0, 1718704800.0, 10.0, 200.0)}}});
  const std::string box = env.file("box.txt");
  std::ofstream(box) << kBox;
  const std::string command =
      "XDG_CONFIG_HOME=" + shell_quote(env.file("config")) + " XDG_CACHE_HOME=" + shell_quote(env.file("cache")) +
      " TRAILRAY_CONFIG= " + shell_quote(TRAILRAY_BINARY) + " video " + shell_quote(gpx) +
      " --terrain none --imagery none --no-ssao --time 2024-06-18T10:00:00Z --camera-mode fixed --camera 46.70,7.85,1500,0,-5"
      " --size 96x64 --gauges none --duration 1s --fps 3 --verbose ";
  const auto plain = run_command(command + "--frames-dir " + shell_quote(env.file("plain")) + " 2>&1");
  ASSERT_EQ(plain.status, 0) << plain.out;
  const auto drawn = run_command(command + "--airspace " + shell_quote(box) + " --frames-dir " +
                                 shell_quote(env.file("box")) + " 2>&1");
  ASSERT_EQ(drawn.status, 0) << drawn.out;
  EXPECT_NE(drawn.out.find(box + ": 1 of 1 airspaces drawn"), std::string::npos) << drawn.out;
  for (const char* frame : {"frame_000001.png", "frame_000003.png"}) {
    const std::string without = bytes_of((std::filesystem::path(env.file("plain")) / frame).string());
    ASSERT_GT(without.size(), 100u) << frame;
    EXPECT_TRUE(without != bytes_of((std::filesystem::path(env.file("box")) / frame).string()))
        << frame << " is the same with and without the airspace";
  }
}

}  // namespace
}  // namespace trailray::test
