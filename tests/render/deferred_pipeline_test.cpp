// The deferred pipeline end to end (G-buffer -> SSAO -> compose with atmosphere), headless and
// small: ambient occlusion darkens a valley floor, not a ridge top; each switch changes the
// picture; far ground is hazier than near ground; the sky brightens towards the horizon; the
// packed distance encoding (no float targets) draws what the float one draws.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "geo/tile_id.hpp"
#include "gl_test_support.hpp"
#include "scene/camera/camera.hpp"
#include "render/gl/gl_capabilities.hpp"
#include "render/renderer.hpp"
#include "scene_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;
using test::keep_image;
using test::luminance;
using test::mean_luminance;
using test::sun_from;
using Pixel = std::array<std::uint8_t, 4>;

double colour_distance(const Pixel& a, const Pixel& b) {
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) sum += std::pow(double(a[c]) - double(b[c]), 2.0);
  return std::sqrt(sum);
}

// Fraction of pixels where some channel differs by more than `tolerance`.
double fraction_differing(const scene::RgbaImage& a, const scene::RgbaImage& b, int tolerance) {
  std::size_t differing = 0;
  for (std::uint32_t y = 0; y < a.height; ++y)
    for (std::uint32_t x = 0; x < a.width; ++x) {
      const Pixel p = a.pixel(x, y), q = b.pixel(x, y);
      for (int c = 0; c < 3; ++c)
        if (std::abs(int(p[c]) - int(q[c])) > tolerance) {
          ++differing;
          break;
        }
    }
  return static_cast<double>(differing) / (double(a.width) * a.height);
}

// North-south V valleys every 4 km: floors at 1000 m on kLon and 4 km apart, ridge tops at
// 2600 m halfway between, straight 0.8 slopes (39 degrees) in between.
constexpr double kLat = 46.5, kLon = 10.0;
double metres_per_degree_lon() { return 111320.0 * std::cos(kLat * M_PI / 180.0); }

struct ValleysSource : test::EastProfileSource {
  ValleysSource()
      : EastProfileSource("valleys", kLat, kLon, [](double east_m) {
          const double from_floor = std::abs(std::fmod(std::fmod(east_m + 2000.0, 4000.0) + 4000.0, 4000.0) - 2000.0);
          return 1000.0 + 0.8 * from_floor;
        }) {}
};

class DeferredPipelineTest : public GlTest {};

// 480x270: the occlusion runs at half resolution (ssao_pass.hpp), and at 240x135 the valley
// floor's dip would be a few of its texels wide.
TEST_F(DeferredPipelineTest, AmbientOcclusionDarkensTheValleyFloorNotTheRidgeTop) {
  ValleysSource valleys;
  test::SceneDrawer renderer(&valleys, nullptr);
  const auto camera =
      scene::camera_at({{kLat, kLon + 1000.0 / metres_per_degree_lon(), 10000.0}, 0.0, -90.0}, scene::Lens{45.0, 480, 270}, 1000.0);
  ASSERT_TRUE(camera.ok()) << camera.error;
  const auto floor = camera.value->project(scene::ecef_from({kLat, kLon, 1000.0}));
  const auto ridge = camera.value->project(scene::ecef_from({kLat, kLon + 2000.0 / metres_per_degree_lon(), 2600.0}));
  ASSERT_TRUE(floor && ridge);

  scene::Scene options = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
  options.sun_direction_ecef = sun_from(kLat, kLon, 180.0, 89.0);  // both flat spots lit alike
  options.style.shading.atmosphere = false;  // the two lie at different distances: no haze to tell them apart
  const test::Drawn with_ao = renderer.draw(*camera.value, options);
  options.style.shading.ssao = false;
  const test::Drawn without_ao = renderer.draw(*camera.value, options);
  keep_image(with_ao.image, "valleys_ssao.png");
  keep_image(without_ao.image, "valleys_no_ssao.png");

  const double floor_ratio = mean_luminance(with_ao.image, floor->x_px, floor->y_px, 2) /
                             mean_luminance(without_ao.image, floor->x_px, floor->y_px, 2);
  const double ridge_ratio = mean_luminance(with_ao.image, ridge->x_px, ridge->y_px, 2) /
                             mean_luminance(without_ao.image, ridge->x_px, ridge->y_px, 2);
  EXPECT_GT(ridge_ratio, 0.98) << "a ridge top is open to the sky";
  EXPECT_LT(floor_ratio, ridge_ratio - 0.03) << "floor " << floor_ratio << ", ridge " << ridge_ratio;
}

TEST_F(DeferredPipelineTest, EachSwitchChangesThePicture) {
  ValleysSource valleys;
  test::SceneDrawer renderer(&valleys, nullptr);
  const auto camera = scene::camera_at({{kLat - 0.1, kLon, 3000.0}, 10.0, -12.0}, scene::Lens{45.0, 160, 90}, 1000.0);
  ASSERT_TRUE(camera.ok()) << camera.error;
  scene::Scene options = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
  options.sun_direction_ecef = sun_from(kLat, kLon, 220.0, 35.0);
  const test::Drawn all = renderer.draw(*camera.value, options);
  options.style.shading.ssao = false;
  const test::Drawn no_ssao = renderer.draw(*camera.value, options);
  options.style.shading.ssao = true;
  options.style.shading.atmosphere = false;
  const test::Drawn no_atmosphere = renderer.draw(*camera.value, options);
  keep_image(all.image, "switches_all.png");
  keep_image(no_ssao.image, "switches_no_ssao.png");
  keep_image(no_atmosphere.image, "switches_no_atmosphere.png");
  EXPECT_GT(fraction_differing(all.image, no_ssao.image, 2), 0.01);
  EXPECT_GT(fraction_differing(all.image, no_atmosphere.image, 2), 0.5);
  // Without ambient occlusion nothing gets darker... and with it, nothing gets brighter.
  double brighter = 0.0;
  for (std::uint32_t y = 0; y < 90; ++y)
    for (std::uint32_t x = 0; x < 160; ++x)
      brighter = std::max(brighter, luminance(all.image.pixel(x, y)) - luminance(no_ssao.image.pixel(x, y)));
  EXPECT_LE(brighter, 1.0);
}

// Flat neutral ground of one albedo under one sun, seen at a glancing angle: far ground is closer
// to the colour of the sky at the horizon than near ground; without the atmosphere near and far
// look the same.
TEST_F(DeferredPipelineTest, FarGroundIsHazierThanNearGround) {
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Lens lens{30.0, 160, 90};
  const auto camera = scene::camera_at({{47.0, 8.0, 1500.0}, 30.0, -8.0}, lens, 500.0);
  ASSERT_TRUE(camera.ok()) << camera.error;
  scene::Scene options = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
  options.neutral_ground_m = 500.0;
  options.sun_direction_ecef = sun_from(47.0, 8.0, 180.0, 60.0);
  options.style.shading.ssao = false;
  const test::Drawn hazy = renderer.draw(*camera.value, options);
  options.style.shading.atmosphere = false;
  const test::Drawn clear = renderer.draw(*camera.value, options);
  keep_image(hazy.image, "haze.png");
  keep_image(clear.image, "haze_off.png");
  const auto horizon = camera.value->horizon_row_px(80.0);
  ASSERT_TRUE(horizon);
  ASSERT_GT(*horizon, 10.0);
  ASSERT_LT(*horizon, 60.0);
  const auto far_row = static_cast<std::uint32_t>(*horizon + 3.0), sky_row = static_cast<std::uint32_t>(*horizon - 3.0);
  const Pixel sky = hazy.image.pixel(80, sky_row);
  const Pixel near = hazy.image.pixel(80, 89), far = hazy.image.pixel(80, far_row);
  EXPECT_LT(colour_distance(far, sky) + 20.0, colour_distance(near, sky))
      << "far (row " << far_row << ") should be nearer the sky's colour than near (row 89)";
  EXPECT_LE(colour_distance(clear.image.pixel(80, 89), clear.image.pixel(80, far_row)), 4.0);
  // Haze is bluish: the far ground's blue rises more than its red.
  EXPECT_GT(far[2] - clear.image.pixel(80, far_row)[2], far[0] - clear.image.pixel(80, far_row)[0]);
}

TEST_F(DeferredPipelineTest, TheSkyIsBrighterAtTheHorizonThanAtTheZenith) {
  test::SceneDrawer renderer(nullptr, nullptr);
  // Looking north, up from 2 to 72 degrees above the horizon, the sun behind in the south.
  const auto camera = scene::camera_at({{47.0, 8.0, 1500.0}, 0.0, 37.0}, scene::Lens{70.0, 90, 90}, 500.0);
  ASSERT_TRUE(camera.ok()) << camera.error;
  scene::Scene options = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
  options.neutral_ground_m = 500.0;
  options.sun_direction_ecef = sun_from(47.0, 8.0, 180.0, 40.0);
  const test::Drawn sky = renderer.draw(*camera.value, options);
  keep_image(sky.image, "sky.png");
  const Pixel low = sky.image.pixel(45, 88), high = sky.image.pixel(45, 1);
  EXPECT_GT(luminance(low), luminance(high) + 20.0);
  // Deeper blue overhead: more blue against red than near the horizon.
  EXPECT_GT(double(high[2]) / high[0], double(low[2]) / low[0]);
  for (std::uint32_t y = 1; y < 90; ++y)
    EXPECT_GE(luminance(sky.image.pixel(45, y)) + 1.0, luminance(sky.image.pixel(45, y - 1))) << "row " << y;

  options.style.shading.atmosphere = false;
  const test::Drawn flat = renderer.draw(*camera.value, options);
  EXPECT_EQ(flat.image.pixel(45, 88), flat.image.pixel(45, 1));
}

TEST_F(DeferredPipelineTest, PackedDistancesDrawWhatFloatDistancesDraw) {
  ValleysSource valleys;
  test::SceneDrawer renderer(&valleys, nullptr);
  EXPECT_EQ(renderer.renderer().distance_encoding(), distance_encoding_for(query_gl_capabilities()));
  const auto camera = scene::camera_at({{kLat - 0.1, kLon, 3000.0}, 10.0, -12.0}, scene::Lens{45.0, 160, 90}, 1000.0);
  ASSERT_TRUE(camera.ok()) << camera.error;
  scene::Scene options = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
  options.sun_direction_ecef = sun_from(kLat, kLon, 220.0, 35.0);
  renderer.renderer().set_distance_encoding(DistanceEncoding::packed_rgba8);
  const test::Drawn packed = renderer.draw(*camera.value, options);
  keep_image(packed.image, "packed_distance.png");
  // The terrain is there (the bottom row), under a sky (the top row).
  EXPECT_GT(colour_distance(packed.image.pixel(80, 0), packed.image.pixel(80, 89)), 20.0);
  // A context without float targets has only the packed path; with them, both must agree.
  if (query_gl_capabilities().color_buffer_float) {
    renderer.renderer().set_distance_encoding(DistanceEncoding::float32);
    const test::Drawn as_float = renderer.draw(*camera.value, options);
    EXPECT_LT(fraction_differing(as_float.image, packed.image, 2), 0.01);
  }
}

}  // namespace
}  // namespace trailray::render
