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

#include "app/track_cli_support.hpp"
#include "scene/camera/camera.hpp"

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

TEST(VideoCli, AFolderOfFramesIsReplacedWholeOnlyWithForce) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("hike.gpx", {{"Hike", {straight_hike()}}});
  const std::string folder = env.file("frames");
  const std::string command =
      video(env) + shell_quote(gpx) + kFilm + " --size 64x48 --fps 4 --frames-dir " + shell_quote(folder);
  ASSERT_EQ(run_command(command + " --duration 2s 2>&1").status, 0);
  const auto count = [&] {
    std::size_t n = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) n += entry.path().extension() == ".png";
    return n;
  };
  EXPECT_EQ(count(), 8u);
  const auto refused = run_command(command + " --duration 1s 2>&1");
  EXPECT_EQ(refused.status, 1) << refused.out;
  EXPECT_NE(refused.out.find("--force"), std::string::npos) << refused.out;
  EXPECT_EQ(count(), 8u);
  // A shorter film replaces all of the earlier one's frames.
  ASSERT_EQ(run_command(command + " --duration 1s --force 2>&1").status, 0);
  EXPECT_EQ(count(), 4u);
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

// The frames of a film of `gpx` seen by a fixed camera 3 km south of (lat, lon) at 1000 m, pitch
// -40 (no overlay, tracks blue: the only red is the markers'); and that camera.
struct FixedFilm {
  std::vector<Picture> frames;
  scene::Camera camera;
};
FixedFilm fixed_film(const RenderEnv& env, const std::string& tracks, double lat, double lon, const std::string& args) {
  const std::string folder = env.file("frames");
  std::filesystem::remove_all(folder);
  const auto r = run_command(video(env) + tracks + kFilm + " --gauges none --size 320x180 --color '#0000ff' " +
                             "--camera-mode fixed --look-at " + fmt::format("{:.6f},{:.6f},1000", lat, lon) +
                             " --distance 3000 --heading 0 --pitch -40 --frames-dir " + shell_quote(folder) + " " +
                             args + " 2>&1");
  EXPECT_EQ(r.status, 0) << r.out;
  auto camera = scene::camera_looking_at({{lat, lon, 1000.0}, 3000.0, 0.0, -40.0},
                                         {scene::kDefaultVerticalFovDeg, 320, 180}, 1000.0);
  if (!camera.ok()) throw std::runtime_error(camera.error);
  FixedFilm film{{}, *camera.value};
  for (int k = 1; std::filesystem::exists(std::filesystem::path(folder) / fmt::format("frame_{:06d}.png", k)); ++k)
    film.frames.push_back(read_picture((std::filesystem::path(folder) / fmt::format("frame_{:06d}.png", k)).string()));
  return film;
}

// Whether a marker stands at point `p` in a frame.
bool marker_at(const FixedFilm& film, std::size_t frame, const GpxPoint& p) {
  const auto at = film.camera.project(scene::ecef_from({p.lat, p.lon, p.ele}));
  return at.has_value() && frame < film.frames.size() && marker_above(film.frames[frame], *at);
}

TEST(VideoCli, TheMarkerStandsWhereTheTrackIsAtTheFramesTime) {
  RenderEnv env;
  const auto points = straight_hike();
  const std::string gpx = env.write_gpx("hike.gpx", {{"Hike", {points}}});
  // 5 frames over the hike's 600 s: every 150 s, points 0, 15, 30, 45, 60.
  const FixedFilm film = fixed_film(env, shell_quote(gpx), points[30].lat, points[30].lon, "--duration 1s --fps 5");
  ASSERT_EQ(film.frames.size(), 5u);
  for (std::size_t k : {0u, 2u, 4u}) {
    EXPECT_TRUE(marker_at(film, k, points[k * 15])) << "frame " << k;
    // ... and not where the track is at another frame's time.
    EXPECT_FALSE(marker_at(film, k, points[k == 0 ? 60 : 0])) << "frame " << k;
  }
}

TEST(VideoCli, SeveralTracksOnOneClockOrEachFromItsStart) {
  RenderEnv env;
  // Two hikes side by side, the second 600 m north and 300 m east of the first (so no marker
  // stands in the column above another's point), starting 300 s after it.
  const auto first = straight_hike();
  const GpxPoint north = offset_point(kLat, kLon, 300.0, 600.0);
  const auto second = east_line(north.lat, north.lon, 0.0, 61, 25.0, kT0 + 300.0, 10.0, 1000.0);
  const std::string tracks = shell_quote(env.write_gpx("a.gpx", {{"A", {first}}})) + " " +
                             shell_quote(env.write_gpx("b.gpx", {{"B", {second}}}));
  const GpxPoint middle = offset_point(kLat, kLon, 900.0, 300.0);
  // On one clock: 4 frames over 900 s, at 0, 300, 600, 900 s. At 300 s A is halfway and B starts.
  const FixedFilm clock = fixed_film(env, tracks, middle.lat, middle.lon, "--duration 1s --fps 4 --align clock");
  ASSERT_EQ(clock.frames.size(), 4u);
  EXPECT_TRUE(marker_at(clock, 1, first[30]));
  EXPECT_TRUE(marker_at(clock, 1, second[0]));
  EXPECT_FALSE(marker_at(clock, 1, second[30]));
  EXPECT_TRUE(marker_at(clock, 2, first[60]));
  EXPECT_TRUE(marker_at(clock, 2, second[30]));
  // Each from its own start: 3 frames over 600 s; halfway, both are halfway.
  const FixedFilm start = fixed_film(env, tracks, middle.lat, middle.lon, "--duration 1s --fps 3 --align start");
  ASSERT_EQ(start.frames.size(), 3u);
  EXPECT_TRUE(marker_at(start, 1, first[30]));
  EXPECT_TRUE(marker_at(start, 1, second[30]));
  EXPECT_FALSE(marker_at(start, 1, second[0]));
}

TEST(VideoCli, TheSameInputsGiveTheSameFilm) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("hike.gpx", {{"Hike", {straight_hike()}}});
  const std::string command = video(env) + shell_quote(gpx) + kFilm + " --size 64x48 --duration 1s --fps 6 ";
  const auto bytes = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  // The frames first (the renderer), then the films (the encoder too).
  for (const char* folder : {"frames_a", "frames_b"})
    ASSERT_EQ(run_command(command + "--frames-dir " + shell_quote(env.file(folder)) + " 2>&1").status, 0);
  for (int k = 1; k <= 6; ++k) {
    const std::string name = fmt::format("frame_{:06d}.png", k);
    const std::string a = bytes((std::filesystem::path(env.file("frames_a")) / name).string());
    EXPECT_GT(a.size(), 100u);
    EXPECT_TRUE(a == bytes((std::filesystem::path(env.file("frames_b")) / name).string())) << name;
  }
  ASSERT_EQ(run_command(command + "-o " + shell_quote(env.file("a.mp4")) + " 2>&1").status, 0);
  ASSERT_EQ(run_command(command + "-o " + shell_quote(env.file("b.mp4")) + " 2>&1").status, 0);
  const std::string a = bytes(env.file("a.mp4"));
  EXPECT_GT(a.size(), 100u);
  EXPECT_TRUE(a == bytes(env.file("b.mp4")));
}

// A real flight followed at 320x180: with x264's macroblock-tree rate control the same frames
// gave a different H.264 stream from run to run here (not at 64x48, not through the ffmpeg
// program): the encoder must not depend on what else is in the process's memory.
TEST(VideoCli, TheSameFlightGivesTheSameH264File) {
  TRAILRAY_REQUIRE_DATA(flight, "igc/goigc_0100_interlaken.igc");
  RenderEnv env;
  const std::string command = video(env) + shell_quote(flight.string()) +
                              " --terrain none --imagery none --fast --size 320x180 --duration 1s --fps 10 -o ";
  std::string first;
  for (const char* name : {"a.mp4", "b.mp4", "c.mp4"}) {
    ASSERT_EQ(run_command(command + shell_quote(env.file(name)) + " 2>&1").status, 0) << name;
    std::ifstream in(env.file(name), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    EXPECT_GT(bytes.size(), 1000u) << name;
    if (first.empty()) first = bytes;
    EXPECT_TRUE(bytes == first) << name << " differs from a.mp4";
  }
}

TEST(VideoCli, CtrlCLeavesNoFile) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("hike.gpx", {{"Hike", {straight_hike()}}});
  const std::string out = env.file("long.mp4");
  // A film far longer than the 2 s it is given.
  const auto r = run_command("timeout --preserve-status -s INT 2 env " + video(env) + shell_quote(gpx) + kFilm +
                             " --size 160x90 --duration 10m --fps 30 -o " + shell_quote(out) + " 2>&1");
  EXPECT_EQ(r.status, 130) << r.out;
  EXPECT_NE(r.out.find("interrupted"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(out));
  for (const auto& entry : std::filesystem::directory_iterator(env.home.path()))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
}

TEST(VideoCli, ACameraPathFilmsAndABrokenOneNamesFileAndLine) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("hike.gpx", {{"Hike", {straight_hike()}}});
  const std::string path = env.file("path.txt");
  std::ofstream(path) << "0s look-at 46.70,7.86,1000 3000 0 -40\n1s look-at 46.70,7.86,1000 2000 90 -30\n";
  const std::string out = env.file("path.mp4");
  const std::string common = video(env) + shell_quote(gpx) + kFilm + " --size 64x48 --duration 1s --fps 4 ";
  const auto r = run_command(common + "--camera-path " + shell_quote(path) + " -o " + shell_quote(out) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(probe(out).frames, 4);
  std::ofstream(path) << "0s look-at 46.70,7.86,1000 3000 0 -40\n\n1s look-at 46.70,7.86 2000 90 -30\n";
  const auto broken =
      run_command(common + "--camera-path " + shell_quote(path) + " --force -o " + shell_quote(out) + " 2>&1");
  EXPECT_EQ(broken.status, 1) << broken.out;
  EXPECT_NE(broken.out.find(path + ":3:"), std::string::npos) << broken.out;
}

}  // namespace
}  // namespace trailray::test
