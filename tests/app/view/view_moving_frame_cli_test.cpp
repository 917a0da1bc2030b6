// `trailray view` while the camera moves and once it rests, under Xvfb: a scripted orbit and its
// way back give a reduced frame (half resolution scaled up: the same view, softer edges), and
// after the rest time the full frame again, the same as before the orbit; --no-moving-frame
// draws the full frame throughout. print-frame-times tells the moving frames from those at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <string>

#include "app/track_cli_support.hpp"
#include "app/xvfb_command.hpp"

namespace trailray::test {
namespace {

constexpr double kLat = 46.70, kLon = 7.85;
constexpr double kT0 = 1718704800.0;  // 2024-06-18T10:00:00Z

struct MovingEnv : RenderEnv {
  std::string view() const {
    std::string p = prefix();
    p.replace(p.find(" render "), 8, " view ");
    return xvfb_command_prefix(file("Xauthority")) + p;
  }
  std::string script(const std::string& text) const {
    const std::string path = file("script.txt");
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
};

struct Difference {
  double mean = 0.0;     // mean |a - b| over the channels, levels of 255
  double changed = 0.0;  // the share of pixels differing by more than 2 in some channel
};

Difference difference(const Picture& a, const Picture& b) {
  Difference d;
  const std::size_t n = std::size_t{a.width} * a.height;
  for (std::size_t i = 0; i < n; ++i) {
    int largest = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      const int e = std::abs(int(a.rgba[i * 4 + c]) - int(b.rgba[i * 4 + c]));
      d.mean += e;
      largest = std::max(largest, e);
    }
    d.changed += largest > 2 ? 1.0 : 0.0;
  }
  d.mean /= 3.0 * static_cast<double>(n);
  d.changed /= static_cast<double>(n);
  return d;
}

struct Shots {
  Picture before, moving, after;
  std::string out;
};

// Rests, orbits and comes back, shoots the window in the frame after (still moving: within the
// rest time), waits past the rest time and shoots again.
Shots orbit_and_rest(const std::string& extra) {
  MovingEnv env;
  const auto line = east_line(kLat, kLon, 0.0, 61, 50.0, kT0, 10.0, 1300.0);
  const std::string gpx = env.write_gpx("line.gpx", {{"Line", {line}}});
  const std::string before = env.file("before.png"), moving = env.file("moving.png"), after = env.file("after.png");
  const std::string script = env.script("hide-panels\nwait 8\nprint-frame-times\nwindow-screenshot " + before +
                                        "\norbit 40 0\norbit -40 0\nwindow-screenshot " + moving +
                                        "\nwait 8\nwindow-screenshot " + after + "\nprint-frame-times\n");
  const CommandResult r = run_command(env.view() + shell_quote(gpx) +
                                      " --terrain none --size 480x270 --time 2024-06-18T10:00:00Z --color '#ff0000' " +
                                      extra + " --script " + shell_quote(script) + " 2>&1");
  EXPECT_EQ(r.status, 0) << r.out;
  return {read_picture(before), read_picture(moving), read_picture(after), r.out};
}

TEST(ViewMovingFrame, ReducedWhileMovingAndTheFullFrameAtRest) {
  const Shots run = orbit_and_rest("");
  ASSERT_EQ(run.moving.width, 480u);
  ASSERT_EQ(run.moving.height, 270u);
  // Back at rest: the frame before the orbit.
  const Difference rested = difference(run.before, run.after);
  EXPECT_LT(rested.changed, 0.001) << "mean " << rested.mean;
  // Moving: the same view, softer (half the pixels scaled up, no ambient occlusion): close on
  // average, but many pixels off.
  const Difference moving = difference(run.before, run.moving);
  EXPECT_GT(moving.changed, 0.02) << "the moving frame is not reduced";
  EXPECT_LT(moving.mean, 8.0) << "the moving frame shows something else";
  // The frames of the second period: the two orbits and the frames within the rest time moving,
  // the rest at rest; none moving in the first.
  const std::regex times(R"(frames while moving: (none|\d+)[^;]*; frames at rest: (none|\d+))");
  std::vector<std::pair<std::string, std::string>> periods;
  for (auto it = std::sregex_iterator(run.out.begin(), run.out.end(), times); it != std::sregex_iterator(); ++it)
    periods.emplace_back((*it)[1], (*it)[2]);
  ASSERT_EQ(periods.size(), 2u) << run.out;
  EXPECT_EQ(periods[0].first, "none");
  ASSERT_NE(periods[1].first, "none");
  // 2 orbits, the shot after them, and 6 or 7 scripted frames of 1/30 s within the 0.2 s rest.
  EXPECT_GE(std::stoi(periods[1].first), 7);
  EXPECT_LE(std::stoi(periods[1].first), 10);
  EXPECT_NE(periods[1].second, "none");
}

TEST(ViewMovingFrame, TurnedOffTheFullFrameIsDrawnWhileMovingToo) {
  const Shots run = orbit_and_rest("--no-moving-frame");
  const Difference moving = difference(run.before, run.moving);
  EXPECT_LT(moving.changed, 0.001) << "mean " << moving.mean;
}

}  // namespace
}  // namespace trailray::test
