// The overlay traces only the capsules the terrain may hide (TrackSceneSettings::terrain_top_m):
// the others add only their fringe, on top of the visible tracks' depth. A scene with all of it
// (a track through a ridge, so a ghost behind it; then climbing high above the crest and back
// across the picture in front of the ghost; then lying on the ground) is drawn both ways: the
// ghosts are the same pixels with the same colours, and so is everything else but where fringes
// of the high capsules overlap each other, whose order now comes from their quads' depth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "gl_test_support.hpp"
#include "render/renderer.hpp"
#include "scene_test_support.hpp"
#include "track_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;
using test::keep_image;
using test::LocalFrame;
using test::polyline;
using test::track_alpha;

constexpr scene::GeoPosition kPlace{46.5, 10.0, 0.0};

// A north-south ridge: valleys at 1000 m, the crest at 1800 m, slopes 2 km wide.
double ridge_height_m(double east_m) { return 1000.0 + 800.0 * std::max(0.0, 1.0 - std::abs(east_m) / 2000.0); }

int largest_channel_difference(const scene::RgbaImage& a, const scene::RgbaImage& b, std::uint32_t x, std::uint32_t y) {
  const auto p = a.pixel(x, y), q = b.pixel(x, y);
  int most = 0;
  for (int c = 0; c < 4; ++c) most = std::max(most, std::abs(static_cast<int>(p[c]) - static_cast<int>(q[c])));
  return most;
}

// Both ways of dropping what lies behind a visible track (OverlayDepth): the depth prefilled from
// the G-buffer, or a test in the overlay's shaders.
class TrackOverlaySplitTest : public GlTest, public ::testing::WithParamInterface<OverlayDepth> {};

TEST_P(TrackOverlaySplitTest, GhostsAreTheSamePixelsWhetherOrNotTheHighCapsulesAreTraced) {
  test::EastProfileSource ridge("ridge", kPlace.lat_deg, kPlace.lon_deg, ridge_height_m);
  RendererOptions full_options;
  full_options.split_track_overlay = false;
  test::SceneDrawer full(&ridge, nullptr, full_options);
  RendererOptions split_options;
  split_options.track_overlay_depth = GetParam();
  test::SceneDrawer split(&ridge, nullptr, split_options);
  const LocalFrame frame(kPlace);
  const scene::Lens lens{40.0, 400, 240};
  const glm::dvec3 eye = frame.point(-3500, -3000, 1900);
  const glm::dvec3 to_target = glm::dvec3(0, 0, 1400) - glm::dvec3(-3500, -3000, 1900);
  const double heading = std::atan2(to_target.x, to_target.y) * 180.0 / M_PI;
  const double pitch = std::atan2(to_target.z, std::hypot(to_target.x, to_target.y)) * 180.0 / M_PI;
  const scene::Camera camera(eye, heading, pitch, lens, scene::DepthRange{50.0, 1.0e5});

  // Through the ridge at 1300 m (its east part hidden), up to 2100 m beyond it and back west high
  // over the crest, then across the view 500 m from the camera at 1852 m, above the crest and in
  // front of the ghost, then down to the valley floor and along it (lying on it).
  std::vector<glm::dvec3> line;
  for (double east = -3000.0; east <= 3000.0; east += 250.0) line.push_back({east, 0.0, 1300.0});
  for (double east = 3000.0; east >= -3000.0; east -= 250.0) line.push_back({east, -600.0, 2100.0});
  for (double east = -2800.0; east >= -3300.0; east -= 20.0) line.push_back({east, -2760.0, 1852.0});
  for (double north = -2000.0; north <= -1000.0; north += 100.0) line.push_back({-3300.0, north, 1000.0});
  const scene::TrackSet tracks = test::track_set({test::track_of(test::geometry_of({polyline(frame, line)}))});
  scene::Scene options = test::plain_scene(kPlace, 1000.0);
  options.style.tracks.width = {5.0, scene::TrackWidth::Unit::pixels};
  options.style.tracks.occlusion.alpha = 0.45f;
  options.style.tracks.occlusion.fade_near_m = 1.0e5f;
  options.style.tracks.occlusion.fade_far_m = 2.0e5f;

  const auto reference = test::render_both(full, camera, options, tracks);
  options.tracks = &tracks;
  const scene::RgbaImage image = split.draw(camera, options).image;
  keep_image(reference.with, "overlay_split_reference.png");
  keep_image(image, "overlay_split.png");

  // Classed by the reference's track alpha at each pixel: a ghost (the occluded alpha, 0.45,
  // blended once), the opaque tube, nothing, or else a fringe. Ghosts and the background must be
  // the same but for rounding on two paths (one step of 8 bits). The high capsules' fringes now
  // take their order from their quads' depth, not from the silhouette's: where one lies over a
  // neighbouring tube or fringe (joints, crossings) it may show or not, a few levels in a few
  // pixels; a ghost over a visible tube (what a missing visible depth would leave) is many more.
  int ghosts = 0, opaque = 0, fringes = 0, changed = 0, tubes_changed = 0, fringes_changed = 0;
  for (std::uint32_t y = 0; y < lens.height_px; ++y)
    for (std::uint32_t x = 0; x < lens.width_px; ++x) {
      const double alpha = track_alpha(reference.with, reference.without, x, y);
      const bool differs = largest_channel_difference(reference.with, image, x, y) > 1;
      const bool ghost = std::abs(alpha - 0.45)<0.05, tube = alpha> 0.9, none = alpha < 0.02;
      if (tube) {
        ++opaque;
        tubes_changed += differs ? 1 : 0;
      } else if (!ghost && !none) {
        ++fringes;
        fringes_changed += differs ? 1 : 0;
      } else {
        ghosts += ghost ? 1 : 0;
        if (differs && ++changed <= 8)
          ADD_FAILURE() << (ghost ? "ghost" : "background") << " pixel (" << x << ", " << y << ") differs by "
                        << largest_channel_difference(reference.with, image, x, y);
      }
    }
  EXPECT_GT(ghosts, 200) << "too little of the track behind the ridge to judge";
  EXPECT_GT(opaque, 2000) << "too little of the track in front of the ridge to judge";
  EXPECT_EQ(changed, 0);
  EXPECT_LE(tubes_changed, opaque / 500) << tubes_changed << " of " << opaque << " tube pixels differ";
  EXPECT_LE(fringes_changed, fringes / 50) << fringes_changed << " of " << fringes << " fringe pixels differ";
}

INSTANTIATE_TEST_SUITE_P(OverlayDepth, TrackOverlaySplitTest,
                         ::testing::Values(OverlayDepth::prefilled, OverlayDepth::tested_in_shaders),
                         [](const ::testing::TestParamInfo<OverlayDepth>& param) {
                           return param.param == OverlayDepth::prefilled ? "Prefilled" : "TestedInShaders";
                         });

}  // namespace
}  // namespace trailray::render
