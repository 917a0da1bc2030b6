// `trailray render` of a track lying on the ground, as a user runs it: a GPX without elevations
// over --terrain none puts its points on the neutral ground, so the ground runs through the
// middle of the tube. Seen obliquely, the tube is opaque over its whole silhouette, the near
// side too, where the rays meet the ground before the tube (it used to be a translucent ghost
// there), and --occlusion changes nothing, as nothing of it is hidden.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "app/track_cli_support.hpp"
#include "scene/camera/camera.hpp"

namespace trailray::test {
namespace {

constexpr double kLat = 46.70, kLon = 7.85;
constexpr std::uint32_t kWidth = 320, kHeight = 180;
constexpr double kDistanceM = 200.0, kPitchDeg = -20.0, kTubeM = 8.0;

// Runs `trailray render` and reads the picture back (a failed run fails the test).
Picture render_to(const RenderEnv& env, const std::string& args, const std::string& name) {
  const std::string out = env.file(name);
  const auto r = run_command(env.prefix() + args + " -o " + shell_quote(out) + " 2>&1");
  EXPECT_EQ(r.status, 0) << args << "\n" << r.out;
  if (r.status != 0) return {};
  const char* folder = std::getenv("TRAILRAY_TEST_IMAGE_DIR");  // for a person to look at
  if (folder != nullptr && *folder != '\0') {
    std::error_code ec;
    std::filesystem::copy_file(out, std::filesystem::path(folder) / ("track_cli_" + name),
                               std::filesystem::copy_options::overwrite_existing, ec);
  }
  return read_picture(out);
}

// A straight hike east without elevations, 600 m long (wider than the picture), its middle at
// (kLat, kLon), 8 m wide in red, looked at from the south, 20 degrees down from 200 m.
TEST(TrackGroundCli, ATrackWithoutElevationsOnTheNeutralGroundIsAnOpaqueTube) {
  RenderEnv env;
  const auto points = east_line(kLat, kLon, -300.0, 25, 25.0, kNoValue, 10.0, kNoValue);
  const std::string gpx = env.write_gpx("flat.gpx", {{"Flat", {points}}});
  const std::string common = shell_quote(gpx) + " --terrain none --no-ssao --no-atmosphere --size 320x180" +
                             " --time 2024-06-18T10:00:00Z --color '#ff0000' --width 8m" +
                             " --look-at 46.70,7.85,0 --distance 200 --heading 0 --pitch -20 --occlusion ";
  const Picture on = render_to(env, common + "on", "ground_on.png");
  const Picture off = render_to(env, common + "off", "ground_off.png");
  ASSERT_EQ(on.width, kWidth);
  ASSERT_EQ(off.width, kWidth);
  EXPECT_TRUE(on.rgba == off.rgba) << "--occlusion changed the picture: part of the tube was drawn as hidden";

  // The camera the command builds, and the tube's axis: the points' line on the ellipsoid (the
  // neutral ground is at 0 m, the points' lowest height, with no heights at all).
  const auto camera = scene::camera_looking_at({{kLat, kLon, 0.0}, kDistanceM, 0.0, kPitchDeg},
                                                {scene::kDefaultVerticalFovDeg, kWidth, kHeight}, 0.0);
  ASSERT_TRUE(camera.ok()) << camera.error;
  const glm::dvec3 centre = scene::ecef_from({kLat, kLon, 0.0});
  const scene::EnuAxes enu = scene::enu_axes_at(kLat, kLon);
  const double radius = 0.5 * kTubeM;
  const double pixel_angle = 2.0 * std::tan(0.5 * scene::kDefaultVerticalFovDeg * M_PI / 180.0) / kHeight;

  // Every fifth column: the ground's green and blue far below the tube, then each pixel whose
  // central ray passes more than 0.6 px inside the tube's silhouette keeps under a tenth of them
  // (red over grey: the opaque tube, however lit; a ghost keeps about half).
  int inside = 0, through_ground = 0, wrong = 0;
  for (std::uint32_t x = 2; x < kWidth; x += 5) {
    const Picture::Rgb ground = on.at(x, kHeight - 3);
    const double ground_gb = ground.g + ground.b;
    ASSERT_GT(ground_gb, 100.0) << "column " << x << " does not end on the grey ground";
    for (std::uint32_t y = 0; y < kHeight; ++y) {
      const scene::Ray ray = camera.value->ray_through_pixel(x + 0.5, y + 0.5);
      const glm::dvec3 eye = ray.origin, d = ray.direction;
      const glm::dvec3 w = eye - centre;
      const glm::dvec3 d_across = d - enu.east * glm::dot(d, enu.east), w_across = w - enu.east * glm::dot(w, enu.east);
      const double across2 = glm::dot(d_across, d_across);
      const double t = -glm::dot(w_across, d_across) / across2;
      const double miss = glm::length(w_across + d_across * t);
      const double pixel_m = pixel_angle * t * glm::dot(d, camera.value->axes().forward);
      if (miss > radius - 0.6 * pixel_m) continue;
      ++inside;
      const double entry = t - std::sqrt((radius * radius - miss * miss) / across2);
      through_ground += glm::dot(eye + d * entry - centre, enu.up) < 0.0 ? 1 : 0;
      const Picture::Rgb p = on.at(x, y);
      if (p.g + p.b > 0.1 * ground_gb && ++wrong <= 8)
        ADD_FAILURE() << "pixel (" << x << ", " << y << ") is " << p.r << "," << p.g << "," << p.b
                      << ": not the opaque tube over ground " << ground.r << "," << ground.g << "," << ground.b;
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(inside, 200) << "the tube is not in the picture";
  EXPECT_GT(through_ground, inside / 5) << "too little of the tube seen through the ground to judge";
}

}  // namespace
}  // namespace trailray::test
