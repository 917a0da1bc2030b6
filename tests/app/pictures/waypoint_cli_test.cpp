// Waypoints, place labels and routes through the command line: the options are in --help, a
// waypoint's pin is drawn where it projects (and not with --no-waypoints), a bad --labels file
// or --route-color is reported, and in the viewer hovering a pin prints its tooltip and
// select-waypoint flies to it.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "app/track_cli_support.hpp"
#include "app/view/viewer_ui.hpp"
#include "app/xvfb_command.hpp"
#include "scene/style.hpp"
#include "ui/waypoint_view.hpp"

namespace trailray::test {
namespace {

constexpr double kLat = 46.70, kLon = 7.85;
constexpr std::uint32_t kWidth = 480, kHeight = 270;
const std::string kPlain =
    " --terrain none --no-ssao --no-atmosphere --no-shadows --legend off --size 480x270 "
    "--time 2024-06-18T10:00:00Z --color '#0000ff'";

std::vector<GpxPoint> line() { return east_line(kLat, kLon, 0.0, 60, 25.0, kNoValue, 0.0, 1000.0); }

// The waypoint: above the line's middle, 40 m north of it, at 1000 m.
GpxPoint waypoint_point() {
  GpxPoint p = offset_point(kLat, kLon, 750.0, 40.0);
  p.ele = 1000.0;
  return p;
}

// A GPX with the line as its track and one waypoint named "Hut".
std::string write_with_waypoint(const RenderEnv& env) {
  std::string text = gpx_text({GpxTrack{"Line", {line()}}});
  const GpxPoint w = waypoint_point();
  std::ostringstream wpt;
  wpt.precision(10);
  wpt << " <wpt lat=\"" << w.lat << "\" lon=\"" << w.lon << "\"><ele>1000</ele><name>Hut</name>"
      << "<desc>a mountain hut</desc></wpt>\n <trk>";
  text.replace(text.find(" <trk>"), 6, wpt.str());
  const std::string path = env.file("with_wpt.gpx");
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

bool pin_red(const Picture::Rgb& p) { return p.r >= 90 && p.r > 2 * p.g + 40 && p.r > 2 * p.b + 40; }

// Red pixels within `radius` of (x, y).
int red_around(const Picture& picture, double x, double y, int radius) {
  int n = 0;
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const double px = std::round(x) + dx, py = std::round(y) + dy;
      if (picture.inside(px, py) && pin_red(picture.at(static_cast<std::uint32_t>(px), static_cast<std::uint32_t>(py))))
        ++n;
    }
  return n;
}

std::size_t red_pixels(const Picture& picture) {
  std::size_t n = 0;
  for (std::uint32_t y = 0; y < picture.height; ++y)
    for (std::uint32_t x = 0; x < picture.width; ++x) n += pin_red(picture.at(x, y));
  return n;
}

// Where the pin's ball appears with render's camera for the line.
glm::dvec2 pin_pixel() {
  const scene::Camera camera = framing_camera(line(), kWidth, kHeight);
  scene::Waypoint w;
  const GpxPoint p = waypoint_point();
  w.marker_ecef = scene::ecef_from({p.lat, p.lon, p.ele});
  const auto at = app::view::pin_screen_position(camera, w, scene::PinStyle{});
  if (!at) throw std::runtime_error("the waypoint is behind the camera");
  return *at;
}

TEST(WaypointCli, TheOptionsAreInTheHelpOfRenderAndView) {
  for (const std::string command : {"render", "view"}) {
    const auto r = run_command(shell_quote(TRAILRAY_BINARY) + " " + command + " --help 2>&1");
    ASSERT_EQ(r.status, 0) << r.out;
    for (const char* option : {"--labels", "--no-waypoints", "--route-color"})
      EXPECT_NE(r.out.find(option), std::string::npos) << command << " --help lacks " << option;
  }
}

TEST(WaypointCli, RenderDrawsThePinWhereTheWaypointIsAndNotWithNoWaypoints) {
  RenderEnv env;
  const std::string gpx = write_with_waypoint(env);
  const std::string out = env.file("pin.png"), hidden = env.file("hidden.png");
  auto r = run_command(env.prefix() + shell_quote(gpx) + kPlain + " -o " + shell_quote(out) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  r = run_command(env.prefix() + shell_quote(gpx) + kPlain + " --no-waypoints -o " + shell_quote(hidden) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  const Picture with = read_picture(out), without = read_picture(hidden);
  const glm::dvec2 at = pin_pixel();
  EXPECT_GT(red_around(with, at.x, at.y, 4), 10) << "the ball at " << at.x << ", " << at.y;
  // Nothing red elsewhere: the pin is all the red there is (the track is blue).
  EXPECT_EQ(static_cast<std::size_t>(red_around(with, at.x, at.y, 14)), red_pixels(with));
  EXPECT_EQ(red_pixels(without), 0u);
}

TEST(WaypointCli, PlaceLabelsFromACsvAndItsErrors) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("line.gpx", {GpxTrack{"Line", {line()}}});
  const GpxPoint w = waypoint_point();
  const std::string csv = env.file("places.csv");
  {
    std::ofstream f(csv);
    f.precision(10);
    f << "name,lon,lat,ele\nHut," << w.lon << "," << w.lat << ",1000\n";
  }
  const std::string out = env.file("places.png");
  // Places are white by default: draw the one place and check the picture differs where it is.
  auto r = run_command(env.prefix() + shell_quote(gpx) + kPlain + " --labels " + shell_quote(csv) + " -o " +
                       shell_quote(out) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  const std::string plain = env.file("plain.png");
  r = run_command(env.prefix() + shell_quote(gpx) + kPlain + " -o " + shell_quote(plain) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  const Picture with = read_picture(out), without = read_picture(plain);
  const glm::dvec2 at = pin_pixel();
  int brighter = 0;
  for (int dy = -20; dy <= 20; ++dy)
    for (int dx = -10; dx <= 10; ++dx) {
      const double x = std::round(at.x) + dx, y = std::round(at.y) + dy;
      if (!with.inside(x, y)) continue;
      const auto a = with.at(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
      const auto b = without.at(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
      brighter += a.r + a.g + a.b > b.r + b.g + b.b + 60;
    }
  EXPECT_GT(brighter, 5) << "a white ball near " << at.x << ", " << at.y;

  const std::string bad = env.file("bad.csv");
  std::ofstream(bad) << "name,lat,lon\nA,46.7,7.85\nB,north,7.85\n";
  r = run_command(env.prefix() + shell_quote(gpx) + kPlain + " --labels " + shell_quote(bad) + " -o " +
                  shell_quote(env.file("x.png")) + " 2>&1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("bad.csv:3: "), std::string::npos) << r.out;
}

TEST(WaypointCli, AFileOfWaypointsAloneIsDrawnAsItsPinsFramed) {
  RenderEnv env;
  const GpxPoint w = waypoint_point();
  const std::string gpx = env.file("only.gpx");
  {
    std::ofstream f(gpx);
    f.precision(10);
    f << "<?xml version=\"1.0\"?><gpx version=\"1.1\" creator=\"t\"><wpt lat=\"" << w.lat << "\" lon=\"" << w.lon
      << "\"><ele>1000</ele><name>Hut</name></wpt></gpx>\n";
  }
  const std::string out = env.file("only.png");
  const auto r = run_command(env.prefix() + shell_quote(gpx) + kPlain + " -o " + shell_quote(out) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  const Picture picture = read_picture(out);
  // Framed on the waypoint: its pin near the middle of the picture, and all the red there is.
  const std::size_t red = red_pixels(picture);
  EXPECT_GT(red, 20u);
  EXPECT_EQ(static_cast<std::size_t>(red_around(picture, kWidth / 2.0, kHeight / 2.0, 40)), red);

  const std::string empty = env.file("empty.gpx");
  std::ofstream(empty) << "<?xml version=\"1.0\"?><gpx version=\"1.1\" creator=\"t\"></gpx>\n";
  const auto e = run_command(env.prefix() + shell_quote(empty) + kPlain + " -o " + shell_quote(out) + " 2>&1");
  EXPECT_NE(e.status, 0);
  EXPECT_NE(e.out.find("has no track, route or waypoint to draw"), std::string::npos) << e.out;
}

TEST(WaypointCli, ABadRouteColourIsAUsageError) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("line.gpx", {GpxTrack{"Line", {line()}}});
  const auto r = run_command(env.prefix() + shell_quote(gpx) + kPlain + " --route-color yellowish -o " +
                             shell_quote(env.file("x.png")) + " 2>&1");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("--route-color"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("yellowish"), std::string::npos) << r.out;
}

TEST(WaypointCli, TheViewerHoversAPinAndFliesToIt) {
  RenderEnv env;
  const std::string gpx = write_with_waypoint(env);
  const glm::dvec2 at = pin_pixel();
  const std::string script = env.file("pins.txt");
  std::ofstream(script) << "print-waypoints\nhover " << at.x << " " << at.y
                        << "\nprint-hover\nselect-waypoint 0\nprint-camera\n";
  std::string view = env.prefix();
  view.replace(view.find(" render "), 8, " view ");
  const auto r = run_command(xvfb_command_prefix(env.file("Xauthority")) + view + shell_quote(gpx) + kPlain +
                             " --script " + shell_quote(script) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  // On the chart of its track (40 m from it), near the line's middle point (30 of 60).
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(waypoint 0 'Hut' waypoint pin at \S+ \S+, chart point (\d+))")))
      << r.out;
  EXPECT_NEAR(std::stod(m[1]), 30.0, 1.0);
  EXPECT_NE(r.out.find("hover: waypoint 0 'Hut'"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  elevation: 1000 m"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  a mountain hut"), std::string::npos) << r.out;
  // The flight ends looking at the waypoint.
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(camera: pivot ([-\d.]+),([-\d.]+),)"))) << r.out;
  const GpxPoint w = waypoint_point();
  EXPECT_NEAR(std::stod(m[1]), w.lat, 1e-5);
  EXPECT_NEAR(std::stod(m[2]), w.lon, 1e-5);
}

}  // namespace
}  // namespace trailray::test
