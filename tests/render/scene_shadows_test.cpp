// The sun's cascaded shadows in the whole frame (shadow maps rendered from the terrain tiles,
// looked up by the compose pass), headless and small: a ridge lit by a low sun from the west
// shades the valley floor east of it and nothing else; the lit slope gets no acne; a sun below
// the horizon does no shadow work.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "geo/tile_id.hpp"
#include "gl_test_support.hpp"
#include "scene/camera/camera.hpp"
#include "render/renderer.hpp"
#include "scene_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;
using test::keep_image;
using test::mean_luminance;
using test::sun_from;

// A north-south ridge at kLon: flat valleys at 1000 m, the crest 800 m higher, slopes 2 km wide
// on either side (22 degrees). A sun 12 degrees up in the west throws the crest's shadow
// 800 m / tan(12 deg) = 3.76 km east of the crest: over the east valley's floor from 2 to 3.76 km.
constexpr double kLat = 46.5, kLon = 10.0;
constexpr double kSunElevationDeg = 12.0;
double degrees_per_km() { return 1.0 / (111.320 * std::cos(kLat * M_PI / 180.0)); }

struct RidgeSource : test::EastProfileSource {
  RidgeSource()
      : EastProfileSource("ridge", kLat, kLon, [](double east_m) {
          return 1000.0 + 800.0 * std::max(0.0, 1.0 - std::abs(east_m / 1000.0) / 2.0);
        }) {}
};

class SceneShadowsTest : public GlTest {
 protected:
  // Looking straight down from 9 km over the crest: about 6 km either side in view.
  static scene::Camera overhead() {
    auto made = scene::camera_at({{kLat, kLon, 9000.0}, 0.0, -90.0}, scene::Lens{45.0, 240, 135}, 1000.0);
    if (!made.ok()) throw std::runtime_error(made.error);
    return *made.value;
  }
  // The pixel of the ground `east_km` east of the crest (negative: west).
  static terrain::ScreenPoint ground_at(const scene::Camera& camera, double east_km) {
    const double height = 1000.0 + 800.0 * std::max(0.0, 1.0 - std::abs(east_km) / 2.0);
    const auto p = camera.project(scene::ecef_from({kLat, kLon + east_km * degrees_per_km(), height}));
    if (!p) throw std::runtime_error("ground point out of view");
    return *p;
  }
};

TEST_F(SceneShadowsTest, ALowWestSunShadowsTheGroundJustEastOfTheRidgeAndNothingFarFromIt) {
  RidgeSource ridge;
  test::SceneDrawer renderer(&ridge, nullptr);
  const scene::Camera camera = overhead();
  scene::Scene options = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
  options.sun_direction_ecef = sun_from(kLat, kLon, 270.0, kSunElevationDeg);
  const test::Drawn shadowed = renderer.draw(camera, options);
  options.style.shading.shadows = false;
  const test::Drawn unshadowed = renderer.draw(camera, options);
  keep_image(shadowed.image, "ridge_low_sun_shadows.png");
  keep_image(unshadowed.image, "ridge_low_sun_no_shadows.png");
  EXPECT_TRUE(shadowed.report.shadows_drawn);
  EXPECT_FALSE(unshadowed.report.shadows_drawn);

  const auto ratio = [&](double east_km) {
    const terrain::ScreenPoint p = ground_at(camera, east_km);
    return mean_luminance(shadowed.image, p.x_px, p.y_px, 1) / mean_luminance(unshadowed.image, p.x_px, p.y_px, 1);
  };
  // In the crest's shadow: flat ground 2.5 and 3.2 km east, which the sun lights without shadows.
  EXPECT_LT(ratio(2.5), 0.85) << "2.5 km east of the crest";
  EXPECT_LT(ratio(3.2), 0.85) << "3.2 km east of the crest";
  // The shadow is as long as the crest's height and the sun's elevation make it (3.76 km): still
  // there at 3.5 km, gone at 4.1 km (a shadow detached from its caster or cut short would fail).
  EXPECT_LT(ratio(3.5), 0.85) << "3.5 km east of the crest";
  // Beyond the shadow's end, in the west valley and on the sunny slope: unchanged. The sunny
  // slope is where acne would show (it faces the sun at 34 degrees).
  for (const double east_km : {4.1, 4.8, -3.0, -1.0}) {
    EXPECT_GT(ratio(east_km), 0.98) << east_km << " km east of the crest";
    EXPECT_LT(ratio(east_km), 1.02) << east_km << " km east of the crest";
  }
}

TEST_F(SceneShadowsTest, TheShadowMovesWithTheSun) {
  RidgeSource ridge;
  test::SceneDrawer renderer(&ridge, nullptr);
  const scene::Camera camera = overhead();
  scene::Scene options = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
  options.sun_direction_ecef = sun_from(kLat, kLon, 90.0, kSunElevationDeg);  // from the east now
  const test::Drawn shadowed = renderer.draw(camera, options);
  options.style.shading.shadows = false;
  const test::Drawn unshadowed = renderer.draw(camera, options);
  const auto ratio = [&](double east_km) {
    const terrain::ScreenPoint p = ground_at(camera, east_km);
    return mean_luminance(shadowed.image, p.x_px, p.y_px, 1) / mean_luminance(unshadowed.image, p.x_px, p.y_px, 1);
  };
  EXPECT_LT(ratio(-2.8), 0.85) << "2.8 km west of the crest";
  EXPECT_GT(ratio(2.8), 0.98) << "2.8 km east of the crest";
}

TEST_F(SceneShadowsTest, ASunBelowTheHorizonDoesNoShadowWork) {
  RidgeSource ridge;
  test::SceneDrawer renderer(&ridge, nullptr);
  const scene::Camera camera = overhead();
  scene::Scene options = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
  options.sun_direction_ecef = sun_from(kLat, kLon, 270.0, -3.0);
  const test::Drawn night = renderer.draw(camera, options);
  EXPECT_FALSE(night.report.shadows_drawn);
  options.style.shading.shadows = false;
  const test::Drawn night_without = renderer.draw(camera, options);
  const terrain::ScreenPoint p = ground_at(camera, 2.8);
  EXPECT_EQ(night.image.pixel(static_cast<std::uint32_t>(p.x_px), static_cast<std::uint32_t>(p.y_px)),
            night_without.image.pixel(static_cast<std::uint32_t>(p.x_px), static_cast<std::uint32_t>(p.y_px)));
}

TEST_F(SceneShadowsTest, ProfiledFramesTimeEachPassOfTheFrame) {
  RidgeSource ridge;
  test::SceneDrawer renderer(&ridge, nullptr);
  const scene::Camera camera = overhead();
  FrameProfiler profiler(query_gl_capabilities(), 4);
  scene::Scene options = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
  options.sun_direction_ecef = sun_from(kLat, kLon, 270.0, 30.0);
  for (int frame = 0; frame < 3; ++frame) renderer.draw(camera, options, &profiler);
  profiler.finish();
  EXPECT_EQ(profiler.frames_ended(), 3u);
  for (const PassTimes& pass : profiler.times()) {
    const bool drawn = pass.name == "tiles" || pass.name == "ssao" || pass.name == "compose" || pass.name == "readback";
    // The same frame three times renders the shadow maps once (shadow_cache.hpp).
    EXPECT_EQ(pass.cpu_samples, drawn ? 3u : pass.name == "shadows" ? 1u : 0u) << pass.name;
  }
}

}  // namespace
}  // namespace trailray::render
