// Tracks are data, not landscape: the aerial perspective that greys distant terrain only tints
// them (compose.frag's kTrackHaze), so their colours still match the legend far away.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
using test::LocalFrame;

class TrackHazeTest : public GlTest {};

// Chroma of an sRGB pixel: how far its brightest channel stands above its dimmest.
int chroma(const std::array<std::uint8_t, 4>& p) {
  return std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]});
}

// A red track 25 km away across flat ground, seen from 300 m up: with the atmosphere the ground
// there is mostly haze, the track keeps most of its colour.
TEST_F(TrackHazeTest, AFarTrackKeepsItsColourWhereTheGroundFadesIntoHaze) {
  const scene::GeoPosition place{46.5, 10.0, 0.0};
  const LocalFrame frame(place);
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Lens lens{20.0, 320, 180};
  const glm::dvec3 eye = frame.point(0.0, -25000.0, 1300.0);
  const double pitch = std::atan2(1005.0 - 1300.0, 25000.0) * 180.0 / M_PI;
  const scene::Camera camera(eye, 0.0, pitch, lens, scene::DepthRange{100.0, 1.0e5});
  const scene::TrackSet buffer = test::track_set(
      {test::track_of(test::geometry_of({test::polyline(frame, {{-3000.0, 0.0, 1005.0}, {3000.0, 0.0, 1005.0}})}))});
  scene::Scene options = test::plain_scene(place, 1000.0);
  options.style.tracks.width = {8.0, scene::TrackWidth::Unit::pixels};
  options.tracks = &buffer;
  options.style.shading.atmosphere = false;
  const scene::RgbaImage clear = renderer.draw(camera, options).image;
  options.style.shading.atmosphere = true;
  const scene::RgbaImage hazy = renderer.draw(camera, options).image;
  keep_image(hazy, "track_haze.png");

  // The track's centre row: the reddest row of the clear picture's middle column.
  const std::uint32_t x = lens.width_px / 2;
  std::uint32_t row = 0;
  for (std::uint32_t y = 0; y < lens.height_px; ++y)
    if (chroma(clear.pixel(x, y)) > chroma(clear.pixel(x, row))) row = y;
  ASSERT_GT(chroma(clear.pixel(x, row)), 100) << "no red track in the middle column";
  const std::uint32_t ground_row = std::min(row + 12, lens.height_px - 1);
  // The ground beside the track is grey either way; what matters is how much colour survives.
  const double track_kept = static_cast<double>(chroma(hazy.pixel(x, row))) / chroma(clear.pixel(x, row));
  // Measured: 0.75 with the track's share of haze, 0.55 with the terrain's full haze.
  EXPECT_GT(track_kept, 0.66) << "the haze washes the track out like the terrain";
  // And the haze is really there: the ground just in front of the track changed.
  const auto ground_clear = clear.pixel(x, ground_row), ground_hazy = hazy.pixel(x, ground_row);
  // The grey ground turns blue-grey with distance (measured: blue +18 at 25 km).
  const int ground_change = ground_hazy[2] - ground_clear[2];
  EXPECT_GT(ground_change, 10) << "no haze at 25 km: the test proves nothing (" << int(ground_clear[0]) << ","
                                << int(ground_clear[1]) << "," << int(ground_clear[2]) << " vs " << int(ground_hazy[0])
                                << "," << int(ground_hazy[1]) << "," << int(ground_hazy[2]) << "); track kept "
                                << track_kept;
}

}  // namespace
}  // namespace trailray::render
