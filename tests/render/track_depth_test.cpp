// Tracks, terrain and other tracks hide each other per pixel: two tracks crossing at different
// heights (the nearer wins wherever they overlap, whichever is drawn first), and a track running
// straight through a ridge (opaque where the camera sees it, a translucent ghost where the
// terrain hides it, the boundary where a ray marched on the CPU over the same terrain says).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "geo/wgs84.hpp"
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
using test::polyline;
using test::track_alpha;

constexpr scene::GeoPosition kPlace{46.5, 10.0, 0.0};
constexpr glm::vec3 kTrackBlue{0.0f, 0.0f, 1.0f};

bool reddish(const std::array<std::uint8_t, 4>& p) { return p[0] > p[2] + 30; }
bool bluish(const std::array<std::uint8_t, 4>& p) { return p[2] > p[0] + 30; }

class TrackDepthTest : public GlTest {};

// Red runs east-west, blue north-south, 8 m wide; one 50 m above the other, seen from above.
// Across the whole overlap (its middle and 3 m to either side along both tracks) the upper one's
// colour shows, with either track drawn first; away from the crossing each keeps its own colour.
TEST_F(TrackDepthTest, TheNearerOfTwoCrossingTracksWinsWhicheverIsDrawnFirst) {
  const LocalFrame frame(kPlace);
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Lens lens{30.0, 320, 240};
  const scene::Camera camera = test::looking_down({kPlace.lat_deg, kPlace.lon_deg, 1000.0}, lens, 10.0);
  scene::Scene options = test::plain_scene(kPlace, 0.0);
  options.style.tracks.width = {8.0, scene::TrackWidth::Unit::metres};
  for (const bool red_on_top : {false, true}) {
    const double red_m = red_on_top ? 850.0 : 800.0, blue_m = red_on_top ? 800.0 : 850.0;
    const scene::Track red = test::track_of(test::geometry_of({polyline(frame, {{-100, 0, red_m}, {100, 0, red_m}})}));
    const scene::Track blue =
        test::track_of(test::geometry_of({polyline(frame, {{0, -100, blue_m}, {0, 100, blue_m}})}), kTrackBlue);
    for (const bool red_first : {false, true}) {
      const std::string what =
          std::string(red_on_top ? "red" : "blue") + " on top, " + (red_first ? "red" : "blue") + " drawn first";
      const scene::TrackSet tracks = red_first ? test::track_set({red, blue}) : test::track_set({blue, red});
      options.tracks = &tracks;
      const scene::RgbaImage image = renderer.draw(camera, options).image;
      keep_image(image, std::string("track_crossing_") + (red_on_top ? "red" : "blue") + "_on_top.png");
      const double top_m = red_on_top ? red_m : blue_m;
      for (const double along : {-3.0, 0.0, 3.0})
        for (const glm::dvec3& p : {glm::dvec3{along, 0, top_m}, glm::dvec3{0, along, top_m}}) {
          std::uint32_t x = 0, y = 0;
          ASSERT_TRUE(pixel_of(camera, frame.point(p), x, y));
          const auto pixel = image.pixel(x, y);
          EXPECT_TRUE(red_on_top ? reddish(pixel) : bluish(pixel))
              << what << ": (" << p.x << ", " << p.y << ") m has " << +pixel[0] << "," << +pixel[1] << "," << +pixel[2];
        }
      std::uint32_t x = 0, y = 0;
      ASSERT_TRUE(pixel_of(camera, frame.point(30, 0, red_m), x, y));
      EXPECT_TRUE(reddish(image.pixel(x, y))) << what << ": the red track away from the crossing";
      ASSERT_TRUE(pixel_of(camera, frame.point(0, 30, blue_m), x, y));
      EXPECT_TRUE(bluish(image.pixel(x, y))) << what << ": the blue track away from the crossing";
    }
  }
}

// A north-south ridge: valleys at 1000 m, the crest at 1800 m, slopes 2 km wide.
constexpr double kRidgeLat = kPlace.lat_deg, kRidgeLon = kPlace.lon_deg;
double ridge_height_m(double east_m) { return 1000.0 + 800.0 * std::max(0.0, 1.0 - std::abs(east_m) / 2000.0); }
double ridge_metres_per_degree() { return 111320.0 * std::cos(kRidgeLat * M_PI / 180.0); }

// Whether the terrain hides `point` from `eye`: the straight line between them marched in 2 m
// steps, each step's height above the ellipsoid against the ridge below it (east measured as
// the source measures it, from the longitude).
bool ridge_hides(const glm::dvec3& eye, const glm::dvec3& point) {
  const double length = glm::length(point - eye);
  const int steps = static_cast<int>(length / 2.0);
  for (int i = 1; i < steps; ++i) {
    const glm::dvec3 q = glm::mix(eye, point, static_cast<double>(i) / steps);
    const geo::Geodetic g = geo::geodetic_from_ecef(q);
    if (g.height_m < ridge_height_m((g.lon_deg - kRidgeLon) * ridge_metres_per_degree())) return true;
  }
  return false;
}

// A level track at 1300 m runs east-west straight through the ridge (into its west slope at
// -1250 m east, out of its east slope at +1250 m), seen from the south-west, 600 m higher, so
// that the crest hides the part beyond the ridge. Along the track, every pixel on its centre
// line is the opaque tube where the CPU's ray sees the tube's near side and a ghost at the
// occluded alpha where it does not, except within a few pixels of where that changes.
TEST_F(TrackDepthTest, ATrackThroughARidgeIsOpaqueInFrontAndAGhostBehindIt) {
  test::EastProfileSource ridge("ridge", kRidgeLat, kRidgeLon, ridge_height_m);
  test::SceneDrawer renderer(&ridge, nullptr);
  const LocalFrame frame(kPlace);
  const scene::Lens lens{40.0, 400, 240};
  const glm::dvec3 eye = frame.point(-3500, -3000, 1900);
  // Towards the crest above the track: heading from the offsets, pitch from the drop.
  const glm::dvec3 to_target = glm::dvec3(0, 0, 1300) - glm::dvec3(-3500, -3000, 1900);
  const double heading = std::atan2(to_target.x, to_target.y) * 180.0 / M_PI;
  const double pitch = std::atan2(to_target.z, std::hypot(to_target.x, to_target.y)) * 180.0 / M_PI;
  const scene::Camera camera(eye, heading, pitch, lens, scene::DepthRange{50.0, 1.0e5});

  constexpr double kTrackM = 1300.0, kWidthPx = 5.0;
  constexpr float kAlpha = 0.45f;
  std::vector<glm::dvec3> line;
  for (double east = -3000.0; east <= 3000.0; east += 500.0) line.push_back({east, 0.0, kTrackM});
  const scene::TrackSet buffer = test::track_set({test::track_of(test::geometry_of({polyline(frame, line)}))});
  scene::Scene options = test::plain_scene(kPlace, 1000.0);
  options.style.tracks.width = {kWidthPx, scene::TrackWidth::Unit::pixels};
  options.style.tracks.occlusion.alpha = kAlpha;
  options.style.tracks.occlusion.fade_near_m = 1.0e5f;
  options.style.tracks.occlusion.fade_far_m = 2.0e5f;
  const auto images = test::render_both(renderer, camera, options, buffer);
  keep_image(images.with, "track_through_ridge.png");

  // Along the track every 5 m: its pixel, and whether the CPU sees the tube's near side there.
  const double pixel_angle = 2.0 * std::tan(0.5 * lens.vertical_fov_deg * M_PI / 180.0) / lens.height_px;
  std::vector<test::VisibilitySample> samples;
  for (double east = -2900.0; east <= 2900.0; east += 5.0) {
    const glm::dvec3 centre = frame.point(east, 0.0, kTrackM);
    const glm::dvec3 towards_eye = glm::normalize(eye - centre);
    const double radius = 0.5 * kWidthPx * pixel_angle * glm::length(eye - centre);
    test::VisibilitySample s{0, 0, ridge_hides(eye, centre + towards_eye * radius), std::to_string(east) + " m east"};
    if (pixel_of(camera, centre, s.x, s.y)) samples.push_back(s);
  }
  ASSERT_GT(samples.size(), 500u) << "the track is not in the picture";
  const bool some_hidden = std::any_of(samples.begin(), samples.end(), [](const auto& s) { return s.hidden; });
  ASSERT_TRUE(some_hidden) << "the ridge hides nothing of the track: the scene is wrong";
  const test::VisibilityCount count = test::check_visibility(samples, images, kAlpha, 0.06, 4.0);
  EXPECT_EQ(count.wrong, 0);
  EXPECT_GT(count.opaque, 100) << "too little of the track in front of the ridge to judge";
  EXPECT_GT(count.ghost, 100) << "too little of the track behind the ridge to judge";
}

}  // namespace
}  // namespace trailray::render
