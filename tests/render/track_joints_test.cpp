// The joints between a track's capsules, seen translucent: a polyline 100 m under the neutral
// ground, seen from above, is drawn only as the occluded "ghost" at a constant alpha (the
// occlusion fade pushed out of reach). Where two capsules overlap at a joint, a pixel blended
// twice would be redder than one blend can make it; a joint clipped too much would leave a hole
// on the centre line. Turns of 30, 90 and 179 degrees, a repeated point and an exact reversal.
#include <gtest/gtest.h>

#include <algorithm>
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
using test::pixel_of;
using test::track_alpha;

constexpr scene::GeoPosition kPlace{46.5, 10.0, 0.0};
const scene::Lens kLens{30.0, 320, 240};
constexpr double kGroundM = 1000.0, kTrackM = 900.0;
constexpr float kAlpha = 0.45f;

class TrackJointsTest : public GlTest {
 protected:
  // The picture with the tracks and without, from 300 m above the ground, 400 m above the track.
  test::WithAndWithout render(const std::vector<scene::TrackPolyline>& segments, const std::string& name) {
    test::SceneDrawer renderer(nullptr, nullptr);
    scene::TrackGeometry geometry;
    geometry.segments = segments;
    const scene::TrackSet buffer = test::track_set({test::track_of(geometry)});
    scene::Scene options = test::plain_scene(kPlace, kGroundM);
    options.style.tracks.width = {6.0, scene::TrackWidth::Unit::metres};
    options.style.tracks.occlusion.alpha = kAlpha;
    options.style.tracks.occlusion.fade_near_m = 1.0e6f;
    options.style.tracks.occlusion.fade_far_m = 2.0e6f;
    auto images = test::render_both(renderer, camera(), options, buffer);
    keep_image(images.with, name);
    return images;
  }
  static scene::Camera camera() { return test::looking_down({kPlace.lat_deg, kPlace.lon_deg, kGroundM + 300.0}, kLens, 20.0); }

  // No pixel more opaque than one ghost (8-bit rounding of the two pictures aside).
  static void expect_single_blend(const test::WithAndWithout& images) {
    double most = 0.0;
    std::uint32_t at_x = 0, at_y = 0;
    for (std::uint32_t y = 0; y < images.with.height; ++y)
      for (std::uint32_t x = 0; x < images.with.width; ++x) {
        const double a = track_alpha(images.with, images.without, x, y);
        if (a > most) most = a, at_x = x, at_y = y;
      }
    EXPECT_GT(most, kAlpha - 0.03) << "no ghost drawn at all";
    EXPECT_LT(most, kAlpha + 0.03) << "pixel (" << at_x << ", " << at_y << ") blended more than once: alpha " << most
                                   << " (twice would be " << 1.0 - (1.0 - kAlpha) * (1.0 - kAlpha) << ")";
  }

  // Every pixel on the centre line, sampled every 10 cm, holds exactly one ghost.
  static void expect_no_holes(const test::WithAndWithout& images, const LocalFrame& frame,
                              const std::vector<glm::dvec3>& path, const std::string& what) {
    const scene::Camera cam = camera();
    int holes = 0;
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      const double length = glm::length(path[i + 1] - path[i]);
      const int steps = std::max(1, static_cast<int>(length / 0.1));
      for (int k = 0; k <= steps; ++k) {
        const glm::dvec3 p = glm::mix(path[i], path[i + 1], static_cast<double>(k) / steps);
        std::uint32_t x = 0, y = 0;
        ASSERT_TRUE(pixel_of(cam, frame.point(p), x, y)) << what << ": leg " << i << " leaves the picture";
        const double a = track_alpha(images.with, images.without, x, y);
        if (std::abs(a - kAlpha) > 0.03 && ++holes <= 5)
          ADD_FAILURE() << what << ": alpha " << a << " at pixel (" << x << ", " << y << "), leg " << i << " at "
                        << k * 100 / steps << " %";
      }
    }
    EXPECT_EQ(holes, 0) << what;
  }
};

TEST_F(TrackJointsTest, TurnsOf30And90And179DegreesBlendOnceAndLeaveNoHoles) {
  const LocalFrame frame(kPlace);
  // East, then 30 degrees right, 90 right, 179 right (back almost along the last leg), 90 right.
  const std::vector<glm::dvec3> path = test::turning_path({-90, 40, kTrackM}, 90.0, 45.0, {30.0, 90.0, 179.0, 90.0});
  const auto images = render({test::polyline(frame, path)}, "track_joints_turns.png");
  expect_single_blend(images);
  expect_no_holes(images, frame, path, "turns");
}

TEST_F(TrackJointsTest, ARepeatedPointAndAnExactReversalBlendOnceAndLeaveNoHoles) {
  const LocalFrame frame(kPlace);
  const std::vector<glm::dvec3> repeated{{-90, -20, kTrackM}, {-40, -20, kTrackM}, {-40, -20, kTrackM},
                                         {-40, -70, kTrackM}, {-40, -70, kTrackM}, {10, -70, kTrackM}};
  // Out and back along the same line, then off to the side; and a spike: out, back, out again.
  const std::vector<glm::dvec3> reversal{{20, -70, kTrackM}, {80, -70, kTrackM}, {40, -70, kTrackM}, {40, -20, kTrackM},
                                         {40, 40, kTrackM},  {40, -20, kTrackM}, {90, -20, kTrackM}};
  const auto images =
      render({test::polyline(frame, repeated), test::polyline(frame, reversal)}, "track_joints_repeat_reverse.png");
  expect_single_blend(images);
  expect_no_holes(images, frame, repeated, "repeated points");
  expect_no_holes(images, frame, reversal, "reversals");
}

}  // namespace
}  // namespace trailray::render
