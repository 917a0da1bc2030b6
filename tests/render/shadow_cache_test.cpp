// The shadow maps are rendered again only when what they hold changes (shadow_cache.hpp): a frame
// that reuses them is the frame a fresh renderer draws, byte for byte; moving the sun renders
// them again and moves the shadow; a change the maps do not depend on (the atmosphere) keeps
// them; a moving frame (FrameOptions::reuse_shadow_maps) keeps them for another camera.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gl_test_support.hpp"
#include "render/renderer.hpp"
#include "scene/camera/camera.hpp"
#include "scene_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;
using test::keep_image;
using test::sun_from;

// A north-south ridge: valleys at 1000 m, the crest 800 m higher, slopes 2 km wide.
constexpr double kLat = 46.5, kLon = 10.0;

struct RidgeSource : test::EastProfileSource {
  RidgeSource()
      : EastProfileSource("ridge", kLat, kLon, [](double east_m) {
          return 1000.0 + 800.0 * std::max(0.0, 1.0 - std::abs(east_m / 1000.0) / 2.0);
        }) {}
};

scene::Camera view_from(double heading_deg) {
  auto made = scene::camera_at({{kLat - 0.05, kLon, 6000.0}, heading_deg, -40.0}, scene::Lens{45.0, 240, 135}, 1000.0);
  if (!made.ok()) throw std::runtime_error(made.error);
  return *made.value;
}

scene::Scene low_sun(double azimuth_deg) {
  scene::Scene s = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
  s.sun_direction_ecef = sun_from(kLat, kLon, azimuth_deg, 12.0);
  return s;
}

std::size_t bytes_differing(const scene::RgbaImage& a, const scene::RgbaImage& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) n += a.rgba[i] != b.rgba[i] ? 1 : 0;
  return n;
}

class ShadowCacheTest : public GlTest {};

TEST_F(ShadowCacheTest, AFrameWithCachedMapsIsTheFreshlyRenderedFrame) {
  RidgeSource ridge;
  test::SceneDrawer drawer(&ridge, nullptr);
  const scene::Camera camera = view_from(0.0);
  const test::Drawn first = drawer.draw(camera, low_sun(270.0));
  const test::Drawn again = drawer.draw(camera, low_sun(270.0));
  EXPECT_TRUE(first.report.shadows_drawn);
  EXPECT_TRUE(first.report.shadow_maps_rendered);
  EXPECT_TRUE(again.report.shadows_drawn);
  EXPECT_FALSE(again.report.shadow_maps_rendered) << "nothing changed: the maps are reused";

  test::SceneDrawer fresh(&ridge, nullptr);
  const test::Drawn reference = fresh.draw(camera, low_sun(270.0));
  ASSERT_EQ(again.image.rgba.size(), reference.image.rgba.size());
  EXPECT_EQ(bytes_differing(again.image, reference.image), 0u);
  // Asked for (render --profile), they are rendered again, to the same picture.
  scene::Scene lit = low_sun(270.0);
  lit.terrain = &drawer.terrain();
  ImageTarget target;
  FrameOptions whole;
  whole.render_shadow_maps = true;
  EXPECT_TRUE(drawer.renderer().draw(lit, camera, target, whole).shadow_maps_rendered);
  EXPECT_EQ(bytes_differing(target.image, reference.image), 0u);
  // And the shadows are there: without them the picture differs.
  scene::Scene unshadowed = low_sun(270.0);
  unshadowed.style.shading.shadows = false;
  EXPECT_GT(bytes_differing(fresh.draw(camera, unshadowed).image, reference.image), 1000u);
}

TEST_F(ShadowCacheTest, MovingTheSunRendersTheMapsAgain) {
  RidgeSource ridge;
  test::SceneDrawer drawer(&ridge, nullptr);
  const scene::Camera camera = view_from(0.0);
  const test::Drawn west = drawer.draw(camera, low_sun(270.0));
  const test::Drawn west_again = drawer.draw(camera, low_sun(270.0));
  ASSERT_FALSE(west_again.report.shadow_maps_rendered);
  const test::Drawn east = drawer.draw(camera, low_sun(90.0));
  EXPECT_TRUE(east.report.shadow_maps_rendered);
  keep_image(west.image, "shadow_cache_west_sun.png");
  keep_image(east.image, "shadow_cache_east_sun.png");
  // The shadow moved to the other side: a large part of the picture changed, and it is the
  // picture a fresh renderer draws for that sun.
  EXPECT_GT(bytes_differing(west.image, east.image), west.image.rgba.size() / 20);
  test::SceneDrawer fresh(&ridge, nullptr);
  EXPECT_EQ(bytes_differing(east.image, fresh.draw(camera, low_sun(90.0)).image), 0u);
}

TEST_F(ShadowCacheTest, WhatTheMapsDoNotDependOnKeepsThem) {
  RidgeSource ridge;
  test::SceneDrawer drawer(&ridge, nullptr);
  const scene::Camera camera = view_from(0.0);
  drawer.draw(camera, low_sun(270.0));
  scene::Scene clear = low_sun(270.0);
  clear.style.shading.atmosphere = false;
  clear.style.shading.ssao = false;
  const test::Drawn drawn = drawer.draw(camera, clear);
  EXPECT_FALSE(drawn.report.shadow_maps_rendered);
  test::SceneDrawer fresh(&ridge, nullptr);
  EXPECT_EQ(bytes_differing(drawn.image, fresh.draw(camera, clear).image), 0u);
  // Turning the camera does change them (the cascades follow the view).
  EXPECT_TRUE(drawer.draw(view_from(20.0), clear).report.shadow_maps_rendered);
}

TEST_F(ShadowCacheTest, AMovingFrameReusesTheMapsOfAnotherCameraButNotOfAnotherSun) {
  RidgeSource ridge;
  test::SceneDrawer drawer(&ridge, nullptr);
  drawer.draw(view_from(0.0), low_sun(270.0));
  const auto draw_moving = [&](const scene::Camera& camera, const scene::Scene& lit) {
    scene::Scene s = lit;
    s.terrain = &drawer.terrain();
    ImageTarget target;
    FrameOptions moving;
    moving.reuse_shadow_maps = true;
    moving.ssao = false;
    test::Drawn drawn;
    drawn.report = drawer.renderer().draw(s, camera, target, moving);
    drawn.image = std::move(target.image);
    return drawn;
  };
  const test::Drawn turned = draw_moving(view_from(10.0), low_sun(270.0));
  EXPECT_TRUE(turned.report.shadows_drawn);
  EXPECT_FALSE(turned.report.shadow_maps_rendered) << "a moving frame keeps the last maps";
  // Still shadowed where the full frame is (the maps cover the view turned by 10 degrees): the
  // two pictures differ only by the shadows' edges and the ambient occlusion.
  const test::Drawn full = drawer.draw(view_from(10.0), low_sun(270.0));
  EXPECT_TRUE(full.report.shadow_maps_rendered) << "at rest the maps follow the camera";
  scene::Scene unshadowed = low_sun(270.0);
  unshadowed.style.shading.shadows = false;
  const test::Drawn dark = draw_moving(view_from(10.0), unshadowed);
  const auto mean_luminance = [](const scene::RgbaImage& image) {
    double sum = 0.0;
    for (std::uint32_t y = 0; y < image.height; ++y)
      for (std::uint32_t x = 0; x < image.width; ++x) sum += test::luminance(image.pixel(x, y));
    return sum / (image.width * image.height);
  };
  EXPECT_LT(mean_luminance(turned.image), mean_luminance(dark.image) - 2.0) << "the reused maps still shade";
  // Another sun: rendered even in a moving frame.
  EXPECT_TRUE(draw_moving(view_from(10.0), low_sun(90.0)).report.shadow_maps_rendered);
}

}  // namespace
}  // namespace trailray::render
