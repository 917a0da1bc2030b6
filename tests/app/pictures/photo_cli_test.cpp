// Photos through the command line (`--photos`): a photo of one flat colour, made at test time
// with its GPS position written by the exiv2 tool onto a track's point, is drawn by `render` as
// its thumbnail right above the point's pin, in its colour; `video` stops at it for
// --photo-seconds (the film grows by that many frames) and shows it large in the pause.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "app/track_cli_support.hpp"
#include "app/xvfb_command.hpp"
#include "scene/camera/camera.hpp"

namespace trailray::test {
namespace {

constexpr double kLat = 46.70, kLon = 7.85;
constexpr double kT0 = 1718704800.0;  // 2024-06-18T10:00:00Z
constexpr std::uint32_t kWidth = 480, kHeight = 270;
const std::string kPlain =
    " --terrain none --no-ssao --no-atmosphere --no-shadows --legend off --size 480x270 "
    "--time 2024-06-18T10:00:00Z --color '#0000ff'";

// A straight walk east, 1.5 km: 61 points 25 m apart, 10 s apart, at 1000 m.
std::vector<GpxPoint> walk() { return east_line(kLat, kLon, 0.0, 61, 25.0, kT0, 10.0, 1000.0); }

// "46/1 42/1 123456/10000": an angle as EXIF's degrees, minutes and seconds.
std::string exif_angle(double degrees) {
  degrees = std::abs(degrees);
  const int d = static_cast<int>(degrees);
  const int m = static_cast<int>((degrees - d) * 60.0);
  const long s = std::lround(((degrees - d) * 60.0 - m) * 60.0 * 10000.0);
  return std::to_string(d) + "/1 " + std::to_string(m) + "/1 " + std::to_string(s) + "/10000";
}

// A JPEG of one colour (r, g, b) with its GPS position at (lat, lon), written by the exiv2 tool.
std::string write_photo(const RenderEnv& env, const std::string& name, double lat, double lon,
                        std::array<std::uint8_t, 3> rgb) {
  terrain::DecodedImage image;
  image.format = terrain::ImageFormat::jpeg;
  image.width = 400;
  image.height = 300;
  image.channels = 3;
  image.samples8.resize(std::size_t{400} * 300 * 3);
  for (std::size_t i = 0; i < image.samples8.size(); ++i) image.samples8[i] = rgb[i % 3];
  const std::vector<unsigned char> bytes = terrain::encode_jpeg(image, 92);
  const std::string path = env.file(name);
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  const auto r = run_command("exiv2 -M" + shell_quote("set Exif.GPSInfo.GPSLatitude " + exif_angle(lat)) + " -M" +
                             shell_quote(std::string("set Exif.GPSInfo.GPSLatitudeRef ") + (lat >= 0 ? "N" : "S")) +
                             " -M" + shell_quote("set Exif.GPSInfo.GPSLongitude " + exif_angle(lon)) + " -M" +
                             shell_quote(std::string("set Exif.GPSInfo.GPSLongitudeRef ") + (lon >= 0 ? "E" : "W")) +
                             " " + shell_quote(path) + " 2>&1");
  if (r.status != 0) throw std::runtime_error("exiv2 could not write the photo's GPS: " + r.out);
  return path;
}

bool red(const Picture::Rgb& p) { return p.r > 200 && p.g < 60 && p.b < 60; }

struct Box {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1, count = 0;
};
Box red_box(const Picture& picture) {
  Box b;
  for (std::uint32_t y = 0; y < picture.height; ++y)
    for (std::uint32_t x = 0; x < picture.width; ++x)
      if (red(picture.at(x, y))) {
        b.x0 = std::min(b.x0, static_cast<int>(x));
        b.y0 = std::min(b.y0, static_cast<int>(y));
        b.x1 = std::max(b.x1, static_cast<int>(x));
        b.y1 = std::max(b.y1, static_cast<int>(y));
        ++b.count;
      }
  return b;
}

TEST(PhotoCli, TheOptionsAreInTheHelpOfRenderVideoAndView) {
  for (const std::string command : {"render", "video", "view"}) {
    const auto r = run_command(shell_quote(TRAILRAY_BINARY) + " " + command + " --help 2>&1");
    ASSERT_EQ(r.status, 0) << r.out;
    for (const char* option : {"--photos", "--photo-tz", "--photo-time-offset"})
      EXPECT_NE(r.out.find(option), std::string::npos) << command << " --help lacks " << option;
  }
  const auto r = run_command(shell_quote(TRAILRAY_BINARY) + " video --help 2>&1");
  EXPECT_NE(r.out.find("--photo-seconds"), std::string::npos);
}

TEST(PhotoCli, RenderDrawsThePhotosThumbnailRightAboveItsPointInItsColour) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("walk.gpx", {GpxTrack{"Walk", {walk()}}});
  const GpxPoint at = walk()[30];  // the middle fix
  const std::string photo = write_photo(env, "red.jpg", at.lat, at.lon, {255, 0, 0});
  const std::string out = env.file("photo.png"), plain = env.file("plain.png");
  auto r = run_command(env.prefix() + shell_quote(gpx) + kPlain + " --photos " + shell_quote(photo) + " -o " +
                       shell_quote(out) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  r = run_command(env.prefix() + shell_quote(gpx) + kPlain + " -o " + shell_quote(plain) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  const Picture with = read_picture(out), without = read_picture(plain);
  EXPECT_EQ(red_box(without).count, 0);
  const Box box = red_box(with);
  // The 72 x 54 thumbnail, less the frame's blend at its edges, and nothing else red.
  EXPECT_GE(box.count, 70 * 52);
  EXPECT_EQ(box.count, (box.x1 - box.x0 + 1) * (box.y1 - box.y0 + 1)) << "a solid rectangle";
  EXPECT_NEAR(box.x1 - box.x0 + 1, 72, 2);
  EXPECT_NEAR(box.y1 - box.y0 + 1, 54, 2);
  // Centred over the point's pixel with render's camera, above it.
  const scene::Camera camera = framing_camera(walk(), kWidth, kHeight);
  const auto point = camera.project(scene::ecef_from({at.lat, at.lon, at.ele}));
  ASSERT_TRUE(point);
  EXPECT_NEAR((box.x0 + box.x1) / 2.0, point->x_px, 3.0);
  EXPECT_LT(box.y1, point->y_px - 10);
  EXPECT_GT(box.y1, point->y_px - 60);
}

TEST(PhotoCli, RenderWarnsForAPhotoItCannotPlaceAndDrawsTheRest) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("walk.gpx", {GpxTrack{"Walk", {walk()}}});
  const GpxPoint at = walk()[30];
  const std::string photo = write_photo(env, "red.jpg", at.lat, at.lon, {255, 0, 0});
  const std::string far = write_photo(env, "far.jpg", at.lat + 1.0, at.lon, {0, 255, 0});
  const std::string out = env.file("photo.png");
  const auto r = run_command(env.prefix() + shell_quote(gpx) + kPlain + " --photos " + shell_quote(photo) +
                             " --photos " + shell_quote(far) + " -o " + shell_quote(out) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("far.jpg: not placed"), std::string::npos) << r.out;
  EXPECT_GE(red_box(read_picture(out)).count, 70 * 52);
}

// `trailray video` with its own (empty) config and cache, PNG frames.
std::string video(const RenderEnv& env) {
  return "XDG_CONFIG_HOME=" + shell_quote(env.file("config")) + " XDG_CACHE_HOME=" + shell_quote(env.file("cache")) +
         " TRAILRAY_CONFIG= " + shell_quote(TRAILRAY_BINARY) + " video ";
}

std::size_t png_count(const std::string& dir) {
  std::size_t n = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) n += e.path().extension() == ".png";
  return n;
}

TEST(PhotoCli, TheFilmStopsAtThePhotoAndShowsIt) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("walk.gpx", {GpxTrack{"Walk", {walk()}}});
  const GpxPoint at = walk()[30];  // halfway through the walk's ten minutes
  const std::string photo = write_photo(env, "red.jpg", at.lat, at.lon, {255, 0, 0});
  const std::string film = " --terrain none --imagery none --fast --no-atmosphere --size 240x136 --fps 10 --duration 2s "
                           "--gauges none --legend off --time 2024-06-18T10:00:00Z ";
  const std::string plain_dir = env.file("plain"), paused_dir = env.file("paused");
  auto r = run_command(video(env) + shell_quote(gpx) + film + "--frames-dir " + shell_quote(plain_dir) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  r = run_command(video(env) + shell_quote(gpx) + film + "--photos " + shell_quote(photo) +
                  " --photo-seconds 1.5 --frames-dir " + shell_quote(paused_dir) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(png_count(plain_dir), 20u);
  EXPECT_EQ(png_count(paused_dir), 20u + 15u) << "1.5 s at 10 fps more";
  // The photo's time is the middle fix's: the clock reaches it at frame 10 (0-based: index 9 or
  // 10 of the 20), which is then held for 15 frames showing the photo large.
  int shown = 0, first = -1;
  for (int i = 1; i <= 35; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "/frame_%06d.png", i);
    const Picture frame = read_picture(paused_dir + name);
    const bool large = red(frame.at(120, 64)) && red(frame.at(80, 50)) && red(frame.at(160, 80));
    if (large && first < 0) first = i;
    shown += large;
  }
  EXPECT_EQ(shown, 15);
  EXPECT_GE(first, 10);
  EXPECT_LE(first, 12);
  r = run_command(video(env) + shell_quote(gpx) + film + "--photos " + shell_quote(photo) +
                  " --photo-seconds 0 --frames-dir " + shell_quote(env.file("none")) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(png_count(env.file("none")), 20u) << "--photo-seconds 0: no stop";
}

TEST(PhotoCli, TheViewerListsThePhotoShowsItLargerAndFliesToIt) {
  RenderEnv env;
  const std::string gpx = env.write_gpx("walk.gpx", {GpxTrack{"Walk", {walk()}}});
  const GpxPoint at = walk()[30];
  const std::string photo = write_photo(env, "red.jpg", at.lat, at.lon, {255, 0, 0});
  const std::string script = env.file("photo.txt"), small = env.file("small.png"), large = env.file("large.png");
  std::ofstream(script) << "print-waypoints\nscreenshot " << small << "\nselect-waypoint 0\nprint-camera\nscreenshot "
                        << large << "\n";
  std::string view = env.prefix();
  view.replace(view.find(" render "), 8, " view ");
  std::string big = kPlain;
  big.replace(big.find("480x270"), 7, "960x720");
  // A window tall enough for the photo four times larger above its pin (a photo takes at most 45 %
  // of the short side).
  const auto r = run_command(xvfb_command_prefix(env.file("Xauthority")) + view + shell_quote(gpx) + big +
                             " --photos " + shell_quote(photo) + " --script " + shell_quote(script) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("'red.jpg'"), std::string::npos) << r.out;
  // The flight ends looking at the photo's point.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(camera: pivot ([-\d.]+),([-\d.]+),)"))) << r.out;
  EXPECT_NEAR(std::stod(m[1]), at.lat, 1e-5);
  EXPECT_NEAR(std::stod(m[2]), at.lon, 1e-5);
  // The thumbnail (72 px wide) before; the photo four times larger once selected.
  const Box before = red_box(read_picture(small)), after = red_box(read_picture(large));
  EXPECT_NEAR(before.x1 - before.x0 + 1, 72, 2);
  EXPECT_NEAR(after.x1 - after.x0 + 1, 4 * 72, 4);
  EXPECT_NEAR(after.y1 - after.y0 + 1, 4 * 54, 4);
}

}  // namespace
}  // namespace trailray::test
