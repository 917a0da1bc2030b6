// `trailray view` through its command line, in a window under Xvfb (Mesa's llvmpipe through EGL):
// the window shows the track, a scripted drag changes the view, hovering a known track point
// prints that point's values (an IGC flight's two altitudes too), the replay moves the marker, a
// broken file or script is reported.
// Small windows (480x270) keep the whole set to a few seconds per test on llvmpipe.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "app/view/viewer_ui.hpp"
#include "scene/text/legend.hpp"
#include "scene/text/text_raster.hpp"
#include "app/track_cli_support.hpp"
#include "ui/panel_layout.hpp"
#include "app/xvfb_command.hpp"

namespace trailray::test {
namespace {

constexpr double kLat = 46.70, kLon = 7.85;
constexpr double kT0 = 1718704800.0;  // 2024-06-18T10:00:00Z
constexpr std::uint32_t kWidth = 480, kHeight = 270;
const std::string kWindow =
    " --terrain none --no-ssao --no-atmosphere --size 480x270 --time 2024-06-18T10:00:00Z --color '#ff0000'";

// A hike east with a bend, 10 s and 25 m between points, climbing 2 m a point, heart rate
// 120 + (i mod 30): every point's values tell which point it is.
std::vector<GpxPoint> bent_hike() {
  std::vector<GpxPoint> points;
  for (int i = 0; i < 120; ++i) {
    GpxPoint p = offset_point(kLat, kLon, 25.0 * i, 300.0 * std::sin(i / 20.0));
    p.ele = 1000.0 + 2.0 * i;
    p.time = kT0 + 10.0 * i;
    p.heart_rate = 120 + i % 30;
    points.push_back(p);
  }
  return points;
}

struct ViewEnv : RenderEnv {
  std::string view() const {
    std::string p = prefix();
    p.replace(p.find(" render "), 8, " view ");
    return xvfb_command_prefix(file("Xauthority")) + p;
  }
  std::string script(const std::string& name, const std::string& text) const {
    const std::string path = file(name);
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  std::string hike() const { return write_gpx("hike.gpx", {GpxTrack{"Hike", {bent_hike()}}}); }
};

using Rgb = Picture::Rgb;
bool red(const Rgb& p) { return p.r >= 90 && p.r > 2 * p.g + 40 && p.r > 2 * p.b + 40; }

std::size_t count_red(const Picture& picture) {
  std::size_t n = 0;
  for (std::uint32_t y = 0; y < picture.height; ++y)
    for (std::uint32_t x = 0; x < picture.width; ++x) n += red(picture.at(x, y)) ? 1 : 0;
  return n;
}

bool red_near(const Picture& picture, double x, double y, int radius) {
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const double px = std::round(x) + dx, py = std::round(y) + dy;
      if (picture.inside(px, py) && red(picture.at(static_cast<std::uint32_t>(px), static_cast<std::uint32_t>(py))))
        return true;
    }
  return false;
}

CommandResult run_view(const ViewEnv& env, const std::string& args) { return run_command(env.view() + args + " 2>&1"); }

TEST(ViewCli, TheWindowShowsTheTrackWhereItsPointsProject) {
  ViewEnv env;
  const std::string out = env.file("view.png");
  const auto r = run_view(env, shell_quote(env.hike()) + kWindow + " --frames 3 --screenshot " + shell_quote(out));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("frames: 3, mean"), std::string::npos) << r.out;  // the frame times
  const Picture picture = read_picture(out);
  ASSERT_EQ(picture.width, kWidth);
  ASSERT_EQ(picture.height, kHeight);
  // The viewer starts framed like `render`: the same camera.
  const auto points = bent_hike();
  const scene::Camera camera = framing_camera(points, kWidth, kHeight);
  std::size_t projected = 0;
  for (std::size_t i = 3; i + 3 < points.size(); i += 4) {
    const auto at = camera.project(scene::ecef_from({points[i].lat, points[i].lon, points[i].ele}));
    ASSERT_TRUE(at.has_value());
    if (!picture.inside(at->x_px, at->y_px)) continue;
    ++projected;
    EXPECT_TRUE(red_near(picture, at->x_px, at->y_px, 3)) << "point " << i << " at " << at->x_px << "," << at->y_px;
  }
  EXPECT_GT(projected, 20u);
  EXPECT_GT(count_red(picture), 500u);
}

// A season: 3,000 tracks, all under way at the replay's time, each with its replay marker.
// ImGui indexes a draw list's vertices with 16 bits here: 3,000 discs of about 30 vertices each
// aborted the viewer; many markers are now small squares, thinned to one per screen cell.
TEST(ViewCli, ASeasonOfTracksOpensWithAMarkerEach) {
  ViewEnv env;
  std::vector<GpxTrack> season;
  for (int t = 0; t < 3000; ++t) {
    std::vector<GpxPoint> points;
    for (int i = 0; i < 3; ++i) {
      GpxPoint p = offset_point(kLat, kLon, 40.0 * (t % 60) + 10.0 * i, 40.0 * (t / 60));
      p.ele = 1000.0;
      p.time = kT0 - 60.0 + 60.0 * i;
      points.push_back(p);
    }
    season.push_back({"run " + std::to_string(t), {points}});
  }
  const std::string out = env.file("season.png");
  const auto r = run_view(
      env, shell_quote(env.write_gpx("season.gpx", season)) + kWindow + " --frames 2 --screenshot " + shell_quote(out));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_GT(count_red(read_picture(out)), 500u);
}

// Two red tracks, the short one south of the long one's west end and 500 m lower: framed without
// a legend, it would lie low left under the key of their names. The viewer's first view keeps it
// out of the key (seen in a screenshot, which has the key as `render` draws it), whole in the
// picture.
TEST(ViewCli, TheFirstViewKeepsTheTracksOutOfTheLegend) {
  ViewEnv env;
  const auto north = east_line(kLat, kLon, 0.0, 61, 50.0, kT0, 10.0, 1000.0);
  const auto south = east_line(kLat, kLon, 0.0, 21, 25.0, kT0, 10.0, 500.0, -1500.0);
  const std::string gpx = env.write_gpx("two.gpx", {{"North", {north}}, {"South", {south}}});
  const std::string out = env.file("two.png");
  const auto r = run_view(env, shell_quote(gpx) + kWindow + " --screenshot " + shell_quote(out));
  ASSERT_EQ(r.status, 0) << r.out;
  const Picture picture = read_picture(out);
  ASSERT_EQ(picture.width, kWidth);
  scene::RgbaImage blank{kWidth, kHeight, std::vector<std::uint8_t>(std::size_t{kWidth} * kHeight * 4, 128)};
  scene::TextRasterizer text;
  const scene::LegendLayout key =
      scene::draw_track_key(blank, text, {{"North", {1.0f, 0.0f, 0.0f}}, {"South", {1.0f, 0.0f, 0.0f}}});
  ASSERT_TRUE(key.drawn);

  std::vector<GpxPoint> all = north;
  all.insert(all.end(), south.begin(), south.end());
  const scene::Camera centred = framing_camera(all, kWidth, kHeight);
  std::size_t under = 0;
  for (const GpxPoint& p : south) {
    const auto at = centred.project(scene::ecef_from({p.lat, p.lon, p.ele}));
    if (at && key.panel.contains(int(at->x_px), int(at->y_px))) ++under;
  }
  ASSERT_GT(under, 3u) << "the tracks do not reach the key's corner: the test proves nothing";

  std::size_t red_in_panel = 0, red_on_edge = 0;
  for (std::uint32_t y = 0; y < picture.height; ++y)
    for (std::uint32_t x = 0; x < picture.width; ++x) {
      const Rgb p = picture.at(x, y);
      const bool in_swatch = std::any_of(key.swatches.begin(), key.swatches.end(), [&](const scene::PixelRect& s) {
        return scene::PixelRect{s.x - 1, s.y - 1, s.width + 2, s.height + 2}.contains(int(x), int(y));
      });
      // Red seen through the dark panel: dimmed, still far redder than green or blue.
      if (key.panel.contains(int(x), int(y)) && !in_swatch && p.r > p.g + 30 && p.r > p.b + 30) ++red_in_panel;
      if ((x < 2 || y < 2 || x + 2 >= picture.width || y + 2 >= picture.height) && red(p)) ++red_on_edge;
    }
  EXPECT_EQ(red_in_panel, 0u) << "track pixels under the legend";
  EXPECT_EQ(red_on_edge, 0u) << "a track runs off the picture";
  EXPECT_GT(count_red(picture), 500u);
}

// At 1280x720 the panels open as a column on the left and the chart along the bottom: the first
// view puts the track in the part of the window they leave free (seen in a screenshot of the
// scene, which has no panels), whole.
TEST(ViewCli, TheFirstViewPutsTheTrackWhereThePanelsLeaveTheWindowFree) {
  ViewEnv env;
  const std::string out = env.file("wide.png");
  const auto r = run_view(env, shell_quote(env.hike()) +
                                   " --terrain none --no-ssao --no-atmosphere --size 1280x720 --time "
                                   "2024-06-18T10:00:00Z --color '#ff0000' --screenshot " +
                                   shell_quote(out));
  ASSERT_EQ(r.status, 0) << r.out;
  const Picture picture = read_picture(out);
  ASSERT_EQ(picture.width, 1280u);
  using app::view::PanelLayout, app::view::default_panel_layout, app::view::kPanelTitleBarHeight;
  const PanelLayout panels = default_panel_layout(1280.0f, 720.0f, kPanelTitleBarHeight);
  std::size_t covered = 0, free = 0, on_edge = 0;
  for (std::uint32_t y = 0; y < picture.height; ++y)
    for (std::uint32_t x = 0; x < picture.width; ++x) {
      if (!red(picture.at(x, y))) continue;
      const auto fx = static_cast<float>(x), fy = static_cast<float>(y);
      const bool under_column = fx < panels.tracks.right();
      const bool under_chart = fy > panels.chart.y;
      const bool under_replay = fx > panels.replay.x && fy < panels.replay.bottom();
      (under_column || under_chart || under_replay ? covered : free) += 1;
      if (x == 0 || y == 0 || x + 1 == picture.width || y + 1 == picture.height) ++on_edge;
    }
  EXPECT_EQ(covered, 0u) << "track pixels where a panel opens";
  EXPECT_EQ(on_edge, 0u) << "the track runs off the picture";
  EXPECT_GT(free, 2000u) << "the track is drawn large in the free part";
}

TEST(ViewCli, AScriptedDragChangesTheView) {
  ViewEnv env;
  const std::string before = env.file("before.png"), after = env.file("after.png");
  const std::string script = env.script(
      "drag.txt", "print-camera\nscreenshot " + before + "\norbit 120 -20\nprint-camera\nscreenshot " + after + "\n");
  const auto r = run_view(env, shell_quote(env.hike()) + kWindow + " --script " + shell_quote(script));
  ASSERT_EQ(r.status, 0) << r.out;
  // Heading turns by 120 px * 0.25 degrees, the pitch rises by 20 * 0.25.
  const std::regex camera_line(R"(camera: pivot \S+ distance \S+ heading (\S+) pitch (\S+))");
  std::vector<std::pair<double, double>> angles;
  for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), camera_line); it != std::sregex_iterator(); ++it)
    angles.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]));
  ASSERT_EQ(angles.size(), 2u) << r.out;
  EXPECT_NEAR(std::remainder(angles[0].first - angles[1].first, 360.0), 30.0, 0.01);
  EXPECT_NEAR(angles[1].second - angles[0].second, 5.0, 0.01);
  const Picture a = read_picture(before), b = read_picture(after);
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  std::size_t differing = 0;
  for (std::uint32_t y = 0; y < a.height; ++y)
    for (std::uint32_t x = 0; x < a.width; ++x) differing += red(a.at(x, y)) != red(b.at(x, y)) ? 1 : 0;
  EXPECT_GT(differing, 200u) << "the track moved on screen";
}

TEST(ViewCli, HoveringAKnownTrackPointPrintsItsValues) {
  ViewEnv env;
  const auto points = bent_hike();
  const scene::Camera camera = framing_camera(points, kWidth, kHeight);
  const std::size_t target = 60;
  const auto at = camera.project(scene::ecef_from({points[target].lat, points[target].lon, points[target].ele}));
  ASSERT_TRUE(at.has_value());
  const std::string script =
      env.script("hover.txt", "hover " + std::to_string(at->x_px) + " " + std::to_string(at->y_px) +
                                  "\nprint-hover\nhover 2 2\nprint-hover\n");
  const auto r = run_view(env, shell_quote(env.hike()) + kWindow + " --script " + shell_quote(script));
  ASSERT_EQ(r.status, 0) << r.out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(hover: track 0 'Hike' point (\d+))"))) << r.out;
  const std::size_t point = std::stoul(m[1]);
  EXPECT_LE(point > target ? point - target : target - point, 1u) << "picked the point under the cursor";
  // Its own values: time, altitude, heart rate of that point of the file.
  EXPECT_NE(r.out.find("time: " + iso8601(kT0 + 10.0 * static_cast<double>(point)).replace(10, 1, " ").substr(0, 19) +
                       " UTC"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("altitude: " + std::to_string(1000 + 2 * point) + " m"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("heart rate: " + std::to_string(120 + point % 30) + " bpm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("speed: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("hover: none"), std::string::npos) << "a corner far from the track hovers nothing\n" << r.out;
}

// The hike as an IGC flight (B records from 10:00:00 UTC, 10 s apart): GNSS altitude the hike's,
// pressure altitude 100 m lower.
std::string igc_hike(const ViewEnv& env, const std::vector<GpxPoint>& points) {
  std::string text = "AXXX001\r\nHFDTE180624\r\n";
  const auto degrees_minutes = [](double v, int& deg, int& milli_min) {
    deg = static_cast<int>(std::floor(v));
    milli_min = static_cast<int>(std::lround((v - deg) * 60000.0));
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    const int t = 10 * 3600 + 10 * static_cast<int>(i);
    int lat_d = 0, lat_m = 0, lon_d = 0, lon_m = 0;
    degrees_minutes(points[i].lat, lat_d, lat_m);
    degrees_minutes(points[i].lon, lon_d, lon_m);
    const long gnss = std::lround(points[i].ele);
    char b[64];
    std::snprintf(b, sizeof b, "B%02d%02d%02d%02d%05dN%03d%05dEA%05ld%05ld\r\n", t / 3600, t / 60 % 60, t % 60, lat_d,
                  lat_m, lon_d, lon_m, gnss - 100, gnss);
    text += b;
  }
  return env.script("hike.igc", text);
}

// Both altitudes reach the viewer whichever --igc-altitude picks for the 3D track (the hover
// finds the point where that altitude projects; print-hover lists both).
TEST(ViewCli, AnIgcFlightHasBothAltitudesAndIgcAltitudePicksTheDrawnOne) {
  ViewEnv env;
  const auto points = bent_hike();
  const std::string flight = igc_hike(env, points);
  for (const bool pressure : {false, true}) {
    SCOPED_TRACE(pressure ? "pressure" : "auto");
    auto drawn = points;
    if (pressure)
      for (GpxPoint& p : drawn) p.ele -= 100.0;
    const scene::Camera camera = framing_camera(drawn, kWidth, kHeight);
    const auto at = camera.project(scene::ecef_from({drawn[60].lat, drawn[60].lon, drawn[60].ele}));
    ASSERT_TRUE(at.has_value());
    const std::string script = env.script(
        "igc_hover.txt", "hover " + std::to_string(at->x_px) + " " + std::to_string(at->y_px) + "\nprint-hover\n");
    const auto r = run_view(env, shell_quote(flight) + kWindow + (pressure ? " --igc-altitude pressure" : "") +
                                     " --script " + shell_quote(script));
    ASSERT_EQ(r.status, 0) << r.out;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(hover: track 0 '[^']*' point (\d+))"))) << r.out;
    const int point = std::stoi(m[1]);
    EXPECT_LE(std::abs(point - 60), 1);
    const int gnss = 1000 + 2 * point;
    EXPECT_NE(r.out.find("\n  altitude: " + std::to_string(pressure ? gnss - 100 : gnss) + " m"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("\n  pressure altitude: " + std::to_string(gnss - 100) + " m"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\n  GNSS altitude: " + std::to_string(gnss) + " m"), std::string::npos) << r.out;
  }
}

TEST(ViewCli, ReplayMovesTheMarker) {
  ViewEnv env;
  const std::string script = env.script("play.txt", "print-marker\nplay 5\nprint-marker\nplay 20\nprint-marker\n");
  const auto r = run_view(env, shell_quote(env.hike()) + kWindow + " --script " + shell_quote(script));
  ASSERT_EQ(r.status, 0) << r.out;
  const std::regex marker_line(R"(marker: track 0 point (\d+) at (\S+) (\S+))");
  std::vector<std::tuple<int, double, double>> markers;
  for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), marker_line); it != std::sregex_iterator(); ++it)
    markers.emplace_back(std::stoi((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]));
  ASSERT_EQ(markers.size(), 3u) << r.out;
  // The default speed is 10x: 5 s of play is 50 s of track time, 5 points of 10 s.
  EXPECT_EQ(std::get<0>(markers[0]), 0);
  EXPECT_NEAR(std::get<0>(markers[1]), 5, 1);  // on point 5, or at the end of the segment before it
  EXPECT_NEAR(std::get<0>(markers[2]), 25, 1);
  // On screen it moves east along the track (to the right in this framing), never back.
  EXPECT_GT(
      std::hypot(std::get<1>(markers[1]) - std::get<1>(markers[0]), std::get<2>(markers[1]) - std::get<2>(markers[0])),
      5.0);
  EXPECT_GT(
      std::hypot(std::get<1>(markers[2]) - std::get<1>(markers[1]), std::get<2>(markers[2]) - std::get<2>(markers[1])),
      20.0);
}

TEST(ViewCli, AFileThatCannotBeReadIsReportedAndTheOthersStay) {
  ViewEnv env;
  const std::string broken = env.script("broken.gpx", "<gpx><trk><trkseg><trkpt lat=\"x\"");
  const std::string out = env.file("view.png");
  const auto r = run_view(
      env, shell_quote(env.hike()) + " " + shell_quote(broken) + kWindow + " --screenshot " + shell_quote(out));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("broken.gpx"), std::string::npos) << r.out;
  EXPECT_GT(count_red(read_picture(out)), 500u);
}

TEST(ViewCli, ScriptErrorsNameTheFileAndLine) {
  ViewEnv env;
  const std::string script = env.script("bad.txt", "wait 1\n\norbit left 3\n");
  const auto r = run_view(env, shell_quote(env.hike()) + kWindow + " --script " + shell_quote(script));
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("bad.txt:3: 'left' is not a number"), std::string::npos) << r.out;
  const std::string select = env.script("select.txt", "select 4\n");
  const auto s = run_view(env, shell_quote(env.hike()) + kWindow + " --script " + shell_quote(select));
  EXPECT_EQ(s.status, 1) << s.out;
  EXPECT_NE(s.out.find("select.txt:1: select 4: there is 1 track"), std::string::npos) << s.out;
}

TEST(ViewCli, WithoutADisplayItSaysHowToGetOne) {
  ViewEnv env;
  std::string command = env.prefix();
  command.replace(command.find(" render "), 8, " view ");
  const auto r =
      run_command("env -u DISPLAY -u WAYLAND_DISPLAY " + command + shell_quote(env.hike()) + " --terrain none 2>&1");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("no display"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("xvfb-run"), std::string::npos) << r.out;
}

// `view --score` draws what `render --score` draws: the scored legs in magenta on the ground.
TEST(ViewCli, ScoreDrawsTheScoredLegs) {
  TRAILRAY_REQUIRE_DATA(flight, "igc/scoring/xcscore_tri.igc");
  ViewEnv env;
  const auto magenta = [](const Picture& p) {
    std::size_t n = 0;
    for (std::uint32_t y = 0; y < p.height; ++y)
      for (std::uint32_t x = 0; x < p.width; ++x) {
        const Rgb c = p.at(x, y);
        n += (c.r > 150 && c.b > 120 && c.g < 90) ? 1 : 0;
      }
    return n;
  };
  const std::string plain = env.file("plain.png"), scored = env.file("scored.png");
  const auto a = run_view(env, shell_quote(flight.string()) + kWindow + " --screenshot " + shell_quote(plain));
  ASSERT_EQ(a.status, 0) << a.out;
  const auto b = run_view(env, shell_quote(flight.string()) + kWindow + " --score --screenshot " + shell_quote(scored));
  ASSERT_EQ(b.status, 0) << b.out;
  EXPECT_GT(magenta(read_picture(scored)), magenta(read_picture(plain)) + 50);
}

}  // namespace
}  // namespace trailray::test
