// `trailray video` as a user runs it, on tiny films without terrain (seconds on llvmpipe): ffprobe
// reads the codec, size and frame count of an MP4 and a WebM; an existing film is replaced only
// with --force; the marker stands where the track is at each frame's time; bad options are usage
// errors naming the option.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/camera.hpp"
#include "track_cli_support.hpp"

namespace trailray::test {
namespace {

constexpr double kLat = 46.70, kLon = 7.85;
constexpr double kT0 = 1718704800.0;  // 2024-06-18T10:00:00Z
const std::string kFilm = " --terrain none --imagery none --no-ssao --no-atmosphere --time 2024-06-18T10:00:00Z";

// The command line of `trailray video` with its own (empty) config and cache.
std::string video(const RenderEnv& env) {
  return "XDG_CONFIG_HOME=" + shell_quote(env.file("config")) + " XDG_CACHE_HOME=" + shell_quote(env.file("cache")) +
         " TRAILRAY_CONFIG= " + shell_quote(TRAILRAY_BINARY) + " video ";
}

// A straight hike east, 1.5 km: 61 points 25 m apart, 10 s apart (10 minutes), at 1000 m.
std::vector<GpxPoint> straight_hike() { return east_line(kLat, kLon, 0.0, 61, 25.0, kT0, 10.0, 1000.0); }

struct Probe {
  std::string codec;
  int width = 0, height = 0, frames = 0;
};
// What ffprobe reads of the first video stream (frames counted by decoding).
Probe probe(const std::string& path) {
  const auto r = run_command(
      "ffprobe -v error -select_streams v:0 -count_frames -show_entries "
      "stream=codec_name,width,height,nb_read_frames -of default=nw=1 " +
      shell_quote(path) + " 2>&1");
  Probe p;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    const auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = line.substr(0, eq), value = line.substr(eq + 1);
    if (key == "codec_name") p.codec = value;
    if (key == "width") p.width = std::stoi(value);
    if (key == "height") p.height = std::stoi(value);
    if (key == "nb_read_frames") p.frames = std::stoi(value);
  }
  return p;
}

bool have_ffprobe() { return run_command("ffprobe -version >/dev/null 2>&1").status == 0; }

TEST(VideoCli, Mp4HasH264TheSizeAndDurationTimesFpsFrames) {
  if (!have_ffprobe()) GTEST_FAIL() << "ffprobe is missing (scripts/setup.sh installs ffmpeg)";
  RenderEnv env;
  const std::string gpx = env.write_gpx("hike.gpx", {{"Hike", {straight_hike()}}});
  const std::string out = env.file("hike.mp4");
  const auto r = run_command(video(env) + shell_quote(gpx) + kFilm + " --size 64x48 --duration 1s --fps 10 -o " +
                             shell_quote(out) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  const Probe p = probe(out);
  EXPECT_EQ(p.codec, "h264");
  EXPECT_EQ(p.width, 64);
  EXPECT_EQ(p.height, 48);
  EXPECT_EQ(p.frames, 10);
  // No temporary file is left next to it.
  for (const auto& entry : std::filesystem::directory_iterator(env.home.path()))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
}

TEST(VideoCli, WebmHasVp9AndSpeedSetsTheLength) {
  if (!have_ffprobe()) GTEST_FAIL() << "ffprobe is missing (scripts/setup.sh installs ffmpeg)";
  RenderEnv env;
  const std::string gpx = env.write_gpx("hike.gpx", {{"Hike", {straight_hike()}}});
  const std::string out = env.file("hike.webm");
  // 600 s of track at 300x: 2 s of film, 8 frames at 4 fps.
  const auto r = run_command(video(env) + shell_quote(gpx) + kFilm + " --size 64x48 --speed 300x --fps 4 -o " +
                             shell_quote(out) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  const Probe p = probe(out);
  EXPECT_EQ(p.codec, "vp9");
  EXPECT_EQ(p.width, 64);
  EXPECT_EQ(p.frames, 8);
}

TEST(VideoCli, AnExistingFilmIsReplacedOnlyWithForce) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("hike.gpx", {{"Hike", {straight_hike()}}});
  const std::string out = env.file("hike.mp4");
  std::ofstream(out) << "an earlier film";
  const std::string command =
      video(env) + shell_quote(gpx) + kFilm + " --size 64x48 --duration 0.5s --fps 4 -o " + shell_quote(out);
  const auto refused = run_command(command + " 2>&1");
  EXPECT_EQ(refused.status, 1) << refused.out;
  EXPECT_NE(refused.out.find("--force"), std::string::npos) << refused.out;
  std::ifstream kept(out);
  std::string text;
  std::getline(kept, text);
  EXPECT_EQ(text, "an earlier film");
  const auto forced = run_command(command + " --force 2>&1");
  EXPECT_EQ(forced.status, 0) << forced.out;
  EXPECT_GT(std::filesystem::file_size(out), 100u);
}

TEST(VideoCli, WrongFilmOptionsAreUsageErrorsNamingTheOption) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("hike.gpx", {{"Hike", {straight_hike()}}});
  const std::string common = shell_quote(gpx) + kFilm + " --size 64x48 ";
  struct Case {
    std::string args, option;
  };
  const Case cases[] = {
      {"--duration 1s", "-o/--frames-dir"},
      {"--duration ten -o x.mp4", "--duration"},
      {"--speed 0x -o x.mp4", "--speed"},
      {"--duration 1s --speed 10x -o x.mp4", "--duration"},
      {"--fps 0 -o x.mp4", "--fps"},
      {"--from 1.5 -o x.mp4", "--from"},
      {"--from 0.6 --to 0.4 -o x.mp4", "--from/--to"},
      {"--trail sometimes -o x.mp4", "--trail"},
      {"--camera-mode drone -o x.mp4", "--camera-mode"},
      {"--follow 2 -o x.mp4", "--follow"},
      {"--align finish -o x.mp4", "--align"},
      {"-o x.avi", "--output"},
      {"--size 65x48 -o x.mp4", "--size"},
  };
  for (const Case& c : cases) {
    const auto r =
        run_command("cd " + shell_quote(env.home.path().string()) + " && " + video(env) + common + c.args + " 2>&1");
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.out;
    EXPECT_NE(r.out.find(c.option), std::string::npos) << c.args << "\n" << r.out;
  }
  EXPECT_FALSE(std::filesystem::exists(env.file("x.mp4")));
}

// The files' waypoint red (scene::PinStyle::waypoint_color, #e3002b): the marker's ball.
bool marker_red(const Picture::Rgb& p) { return p.r > 120 && p.g < 80 && p.b < 100 && p.r > 2 * p.b; }

// Whether the marker's ball is in the column above `at`: it rests a lift (18 px) above the point.
bool marker_above(const Picture& picture, const terrain::ScreenPoint& at) {
  for (int dy = -34; dy <= 4; ++dy)
    for (int dx = -6; dx <= 6; ++dx) {
      const double x = std::round(at.x_px) + dx, y = std::round(at.y_px) + dy;
      if (picture.inside(x, y) && marker_red(picture.at(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y))))
        return true;
    }
  return false;
}

TEST(VideoCli, TheMarkerStandsWhereTheTrackIsAtTheFramesTime) {
  RenderEnv env;
  const auto points = straight_hike();
  const std::string gpx = env.write_gpx("hike.gpx", {{"Hike", {points}}});
  const std::string frames = env.file("frames");
  // A fixed camera south of the middle of the hike; 5 frames over its 600 s: every 150 s.
  const GpxPoint middle = points[30];
  const std::string look_at = fmt::format("{:.6f},{:.6f},1000", middle.lat, middle.lon);
  const auto r =
      run_command(video(env) + shell_quote(gpx) + kFilm +
                  " --size 320x180 --duration 1s --fps 5 --color '#0000ff' --camera-mode fixed --look-at " + look_at +
                  " --distance 2500 --heading 0 --pitch -40 --frames-dir " + shell_quote(frames) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto camera = scene::camera_looking_at({{middle.lat, middle.lon, 1000.0}, 2500.0, 0.0, -40.0},
                                               {scene::kDefaultVerticalFovDeg, 320, 180}, 1000.0);
  ASSERT_TRUE(camera.ok()) << camera.error;
  // Frame k (1-based) shows the time k-1 quarters through: points 0, 15, 30, 45, 60.
  for (int k : {1, 3, 5}) {
    const Picture picture = read_picture((std::filesystem::path(frames) / fmt::format("frame_{:06d}.png", k)).string());
    const GpxPoint& here = points[static_cast<std::size_t>((k - 1) * 15)];
    const auto at = camera.value->project(scene::ecef_from({here.lat, here.lon, here.ele}));
    ASSERT_TRUE(at.has_value());
    EXPECT_TRUE(marker_above(picture, *at)) << "frame " << k << " at " << at->x_px << "," << at->y_px;
    // ... and not where the track is at another frame's time.
    const GpxPoint& elsewhere = points[k == 1 ? 60 : 0];
    const auto away = camera.value->project(scene::ecef_from({elsewhere.lat, elsewhere.lon, elsewhere.ele}));
    ASSERT_TRUE(away.has_value());
    EXPECT_FALSE(marker_above(picture, *away)) << "frame " << k;
  }
}

}  // namespace
}  // namespace trailray::test
