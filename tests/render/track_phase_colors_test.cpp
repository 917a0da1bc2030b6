// --color-by phase in the track pass: a circling stretch (values: its climb) in the warm map's
// colour for that climb, a gliding stretch (track::kCategoryValue) in the category colour, never
// blended into the scale, and a stretch without a value in the neutral grey; each as the same
// tube drawn in that solid colour.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "gl_test_support.hpp"
#include "render/renderer.hpp"
#include "scene/pictures/colormap.hpp"
#include "scene_test_support.hpp"
#include "track/color_values.hpp"
#include "track_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;
using test::keep_image;
using test::kTrackRed;
using test::LocalFrame;
using test::looking_down;
using test::pixel_of;
using test::plain_scene;
using test::polyline;

constexpr scene::GeoPosition kPlace{46.5, 10.0, 0.0};
const scene::Lens kLens{30.0, 320, 240};

class TrackPhaseColorsTest : public GlTest {};

TEST_F(TrackPhaseColorsTest, CirclingGlidingAndNoValueEachGetTheirColour) {
  const LocalFrame frame(kPlace);
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Camera camera = looking_down({kPlace.lat_deg, kPlace.lon_deg, 1000.0}, kLens, 10.0);
  const std::vector<glm::dvec3> points{{-110, 0, 800}, {-90, 0, 800}, {-70, 0, 800}, {-50, 0, 800},
                                       {-15, 0, 800},  {0, 0, 800},   {15, 0, 800},  {50, 0, 800},
                                       {70, 0, 800},   {90, 0, 800},  {110, 0, 800}};
  const float glide = track::kCategoryValue, none = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> values{1.5f, 1.5f, 1.5f, 1.5f, glide, glide, glide, none, none, none, none};
  const scene::TrackSet phased =
      test::track_set({test::track_of(test::geometry_of({polyline(frame, points, values)}), kTrackRed, true)});
  scene::Scene options = plain_scene(kPlace, 0.0);
  options.style.tracks.width = {8.0, scene::TrackWidth::Unit::metres};
  options.style.tracks.color_by = track::ColorMetric::phase;
  options.style.tracks.colormap = scene::Colormap::warm;
  options.color_range = track::ValueRange{0.0, 3.0};
  options.tracks = &phased;
  const scene::RgbaImage by_phase = renderer.draw(camera, options).image;
  keep_image(by_phase, "track_by_phase.png");

  const glm::vec3 climb = scene::colormap_color(scene::Colormap::warm, 0.5f);
  const std::vector<std::pair<double, glm::vec3>> expected{
      {-60.0, climb}, {0.0, scene::kCategoryColorSrgb}, {60.0, scene::kMissingValueColorSrgb}};
  for (const auto& [east, colour] : expected) {
    const scene::TrackSet plain =
        test::track_set({test::track_of(test::geometry_of({polyline(frame, points)}), colour)});
    options.tracks = &plain;
    const scene::RgbaImage solid = renderer.draw(camera, options).image;
    std::uint32_t x = 0, y = 0;
    ASSERT_TRUE(pixel_of(camera, frame.point(east, 0, 800), x, y));
    for (std::uint32_t row = y - 5; row <= y + 5; ++row) {
      const auto a = by_phase.pixel(x, row), b = solid.pixel(x, row);
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(a[ch], b[ch], 3) << east << " m east, row " << row << ", channel " << ch;
    }
  }
  // The three colours are told apart in the picture, not only in the tables.
  std::uint32_t xc = 0, xg = 0, xn = 0, y = 0;
  ASSERT_TRUE(pixel_of(camera, frame.point(-60, 0, 800), xc, y));
  ASSERT_TRUE(pixel_of(camera, frame.point(0, 0, 800), xg, y));
  ASSERT_TRUE(pixel_of(camera, frame.point(60, 0, 800), xn, y));
  const auto c = by_phase.pixel(xc, y), g = by_phase.pixel(xg, y), n = by_phase.pixel(xn, y);
  EXPECT_GT(static_cast<int>(c[0]) - static_cast<int>(c[2]), 80) << "circling is warm";
  EXPECT_GT(static_cast<int>(g[2]) - static_cast<int>(g[0]), 80) << "gliding is cool";
  EXPECT_LT(std::abs(static_cast<int>(n[0]) - static_cast<int>(n[2])), 20) << "no value is grey";
}

}  // namespace
}  // namespace trailray::render
