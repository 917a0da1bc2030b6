// What makes a track's height above the ground readable: its shadow on the ground (the sun's
// shadow maps with the capsules as casters) and the curtain, a translucent wall from the track
// down to the ground. Both against the same scene without them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gl_test_support.hpp"
#include "render/renderer.hpp"
#include "render/passes/track_pass.hpp"
#include "scene_test_support.hpp"
#include "track_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;
using test::keep_image;
using test::kTrackRed;
using test::LocalFrame;
using test::mean_luminance;
using test::pixel_of;
using test::polyline;
using test::track_alpha;

constexpr scene::GeoPosition kPlace{46.5, 10.0, 0.0};
const scene::Lens kLens{30.0, 320, 240};

class TrackShadowCurtainTest : public GlTest {};

// An 8 m tube 50 m above flat ground, the sun 60 degrees up in the south: the shadow lies
// 50 / tan(60 deg) = 28.9 m north of the point under the track. There the ground darkens when
// the track casts shadows; 28.9 m south and 60 m north it does not.
TEST_F(TrackShadowCurtainTest, AFloatingTrackShadowsTheGroundAwayFromTheSun) {
  const LocalFrame frame(kPlace);
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Camera camera = test::looking_down({kPlace.lat_deg, kPlace.lon_deg, 1000.0}, kLens, 50.0);
  const scene::TrackSet buffer = test::track_set(
      {test::track_of(test::geometry_of({polyline(frame, {{-300, 0, 50}, {300, 0, 50}})}))});
  scene::Scene options = test::plain_scene(kPlace, 0.0);
  options.sun_direction_ecef = test::sun_from(kPlace.lat_deg, kPlace.lon_deg, 180.0, 60.0);
  options.style.shading.shadows = true;
  options.tracks = &buffer;
  options.style.tracks.width = {8.0, scene::TrackWidth::Unit::metres};
  options.style.tracks.cast_shadows = true;
  const test::Drawn shadowed = renderer.draw(camera, options);
  keep_image(shadowed.image, "track_shadow.png");
  ASSERT_TRUE(shadowed.report.shadows_drawn);
  options.style.tracks.cast_shadows = false;
  const scene::RgbaImage unshadowed = renderer.draw(camera, options).image;

  const double shadow_north = 50.0 / std::tan(60.0 * M_PI / 180.0);
  for (const double east : {-50.0, 0.0, 50.0}) {
    const auto lum = [&](const scene::RgbaImage& image, double north) {
      const auto p = camera.project(frame.point(east, north, 0.0));
      return p ? mean_luminance(image, p->x_px, p->y_px, 1) : -1.0;
    };
    const double dark = lum(shadowed.image, shadow_north), light = lum(unshadowed, shadow_north);
    EXPECT_LT(dark, light - 25.0) << east << " m east: no shadow where the sun puts it";
    EXPECT_NEAR(lum(shadowed.image, -shadow_north), lum(unshadowed, -shadow_north), 2.0)
        << east << " m east: a shadow on the sunny side";
    EXPECT_NEAR(lum(shadowed.image, 60.0), lum(unshadowed, 60.0), 2.0) << east << " m east: a shadow too far north";
  }
}

// A track 100 m above the ground seen from the south, slightly above it: with the curtain, the
// wall between the track and the ground turns towards the track's colour (never more opaque than
// the curtain's alpha); without the curtain, and above the track or past its end, nothing
// changes.
TEST_F(TrackShadowCurtainTest, TheCurtainHangsFromTheTrackToTheGround) {
  const LocalFrame frame(kPlace);
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Camera camera(frame.point(0, -400, 150), 0.0, -10.0, kLens, scene::DepthRange{10.0, 1.0e5});
  scene::TrackPolyline line = polyline(frame, {{-100, 0, 100}, {-30, 0, 100}, {40, 0, 100}, {100, 0, 100}});
  line.heights_above_ground_m = {100.0f, 100.0f, 100.0f, 100.0f};
  ASSERT_TRUE(TrackBuffer(test::geometry_of({line})).has_drops());
  const scene::TrackSet buffer = test::track_set({test::track_of(test::geometry_of({line}))});
  scene::Scene options = test::plain_scene(kPlace, 0.0);
  options.style.tracks.width = {3.0, scene::TrackWidth::Unit::metres};
  options.style.tracks.curtain_alpha = 0.3f;

  const std::vector<glm::dvec3> on_wall{{-80, 0, 20}, {-30, 0, 50}, {0, 0, 10}, {40, 0, 80}, {80, 0, 50}};
  const std::vector<glm::dvec3> off_wall{{0, 0, 115}, {-60, 0, 130}, {120, 0, 50}, {-120, 0, 20}};
  for (const bool curtain : {true, false}) {
    options.style.tracks.curtain = curtain;
    const auto images = test::render_both(renderer, camera, options, buffer);
    keep_image(images.with, curtain ? "track_curtain.png" : "track_no_curtain.png");
    for (const glm::dvec3& p : on_wall) {
      std::uint32_t x = 0, y = 0;
      ASSERT_TRUE(pixel_of(camera, frame.point(p), x, y));
      const double a = track_alpha(images.with, images.without, x, y);
      if (curtain) {
        EXPECT_GT(a, 0.1) << "no wall at (" << p.x << ", " << p.z << ") m";
        EXPECT_LT(a, options.style.tracks.curtain_alpha + 0.03)
            << "the wall blended twice at (" << p.x << ", " << p.z << ") m";
        EXPECT_GT(images.with.pixel(x, y)[0], images.with.pixel(x, y)[1]) << "the wall is not red";
      } else {
        EXPECT_LT(a, 0.02) << "a wall without the curtain at (" << p.x << ", " << p.z << ") m";
      }
    }
    for (const glm::dvec3& p : off_wall) {
      std::uint32_t x = 0, y = 0;
      ASSERT_TRUE(pixel_of(camera, frame.point(p), x, y));
      EXPECT_LT(track_alpha(images.with, images.without, x, y), 0.02)
          << (curtain ? "curtain" : "no curtain") << ": something drawn at (" << p.x << ", " << p.z << ") m";
    }
    // The tube itself stays opaque in front of its wall.
    std::uint32_t x = 0, y = 0;
    ASSERT_TRUE(pixel_of(camera, frame.point(0, 0, 100), x, y));
    EXPECT_GT(track_alpha(images.with, images.without, x, y), 0.9) << (curtain ? "curtain" : "no curtain");
  }
}

}  // namespace
}  // namespace trailray::render
