// `trailray render --color-by density` of several GPX files: three tracks that share a stretch 20 m
// apart and one alone; where the three overlap the picture shows magma's bright end (3 tracks),
// the lone track its dark end (1, itself). A radius under their spacing makes the shared stretch
// dark too; a radius out of range is a usage error naming the option.
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>
#include <vector>

#include "app/track_cli_support.hpp"
#include "scene/camera/camera.hpp"

namespace trailray::test {
namespace {

constexpr double kLat = 46.70, kLon = 7.85;
constexpr std::uint32_t kWidth = 480, kHeight = 270;
const std::string kPicture =
    " --terrain none --no-ssao --no-atmosphere --no-shadows --legend off --size 480x270 --time 2024-06-18T10:00:00Z";

GpxPoint at(double east, double north) {
  GpxPoint p = offset_point(kLat, kLon, east, north);
  p.ele = 1000.0;
  return p;
}

// From (east0, north0) to (east1, north1), a point every 20 m or so (the end left out).
void line(std::vector<GpxPoint>& out, double east0, double north0, double east1, double north1) {
  const double length = std::hypot(east1 - east0, north1 - north0);
  const int steps = std::max(1, static_cast<int>(length / 20.0));
  for (int i = 0; i < steps; ++i) {
    const double f = static_cast<double>(i) / steps;
    out.push_back(at(east0 + (east1 - east0) * f, north0 + (north1 - north0) * f));
  }
}

// Track k: its own leg in (400 m from the others'), the shared stretch 20 k m north, its own leg out.
std::vector<GpxPoint> shared_track(int k) {
  std::vector<GpxPoint> points;
  const double own = -600.0 - 400.0 * k, shared = 20.0 * k;
  line(points, -2000, own, -1000, own);
  line(points, -1000, own, -800, shared);
  line(points, -800, shared, 800, shared);
  line(points, 800, shared, 1000, own);
  line(points, 1000, own, 2000, own);
  points.push_back(at(2000, own));
  return points;
}

std::vector<GpxPoint> lone_track() {
  std::vector<GpxPoint> points;
  line(points, -2000, 1200, 2000, 1200);
  points.push_back(at(2000, 1200));
  return points;
}

int brightness(const Picture::Rgb& p) { return p.r + p.g + p.b; }

// The darkest and brightest pixel within `radius` of where a point is drawn.
std::pair<int, int> darkest_brightest(const Picture& picture, const scene::Camera& camera, const GpxPoint& p,
                                      int radius = 2) {
  const auto seen = camera.project(scene::ecef_from({p.lat, p.lon, p.ele}));
  EXPECT_TRUE(seen && picture.inside(seen->x_px, seen->y_px));
  if (!seen) return {0, 0};
  int darkest = INT_MAX, brightest = 0;
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const double x = std::round(seen->x_px) + dx, y = std::round(seen->y_px) + dy;
      if (!picture.inside(x, y)) continue;
      const int b = brightness(picture.at(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)));
      darkest = std::min(darkest, b);
      brightest = std::max(brightest, b);
    }
  return {darkest, brightest};
}

struct Scene {
  RenderEnv env;
  std::string files;
  std::vector<GpxPoint> all;
  Scene() {
    for (int k = 0; k < 3; ++k) {
      const auto points = shared_track(k);
      files += " " + shell_quote(env.write_gpx("shared" + std::to_string(k) + ".gpx", {{"", {points}}}));
      all.insert(all.end(), points.begin(), points.end());
    }
    const auto lone = lone_track();
    files += " " + shell_quote(env.write_gpx("lone.gpx", {{"", {lone}}}));
    all.insert(all.end(), lone.begin(), lone.end());
  }
  Picture render(const std::string& options, const std::string& name) const {
    const std::string out = env.file(name);
    const auto r = run_command(env.prefix() + files + kPicture + options + " -o " + shell_quote(out) + " 2>&1");
    EXPECT_EQ(r.status, 0) << options << "\n" << r.out;
    return r.status == 0 ? read_picture(out) : Picture{};
  }
};

TEST(DensityRenderCli, OverlappingTracksAreBrightALoneTrackDark) {
  const Scene s;
  const Picture picture = s.render(" --color-by density", "density.png");
  ASSERT_EQ(picture.width, kWidth);
  const scene::Camera camera = framing_camera(s.all, kWidth, kHeight);
  // Magma: 3 tracks (the top of the range 1..3) pale yellow, 1 track (the bottom) near black.
  const auto [shared_dark, shared_bright] = darkest_brightest(picture, camera, at(0, 20));
  const auto [lone_dark, lone_bright] = darkest_brightest(picture, camera, at(0, 1200));
  const auto [leg_dark, leg_bright] = darkest_brightest(picture, camera, at(-1500, -600));
  EXPECT_GT(shared_dark, 330) << "the shared stretch: bright, not a dark pixel on it";
  EXPECT_LT(lone_dark, 120) << "the lone track: dark";
  EXPECT_LT(leg_dark, 120) << "a shared track's own leg, 400 m from the others: dark";
  EXPECT_GT(shared_bright, lone_bright);

  // 10 m: the shared stretch's tracks (20 m apart) no longer count each other.
  const Picture narrow = s.render(" --color-by density --density-radius 10", "narrow.png");
  const auto [narrow_dark, narrow_bright] = darkest_brightest(narrow, camera, at(0, 20));
  EXPECT_LT(narrow_dark, 120) << "the shared stretch with a 10 m radius";
  (void)narrow_bright;
  (void)leg_bright;
}

TEST(DensityRenderCli, ARadiusOutOfRangeIsAUsageError) {
  const Scene s;
  for (const std::string radius : {"0.5", "-3", "1e6", "nan"}) {
    const auto r = run_command(s.env.prefix() + s.files + kPicture + " --color-by density --density-radius " + radius +
                               " -o " + shell_quote(s.env.file("x.png")) + " 2>&1");
    EXPECT_TRUE(r.status == 1 || r.status == 2) << radius << ": " << r.out;
    EXPECT_NE(r.out.find("--density-radius"), std::string::npos) << r.out;
  }
}

}  // namespace
}  // namespace trailray::test
