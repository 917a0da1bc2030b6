// The renderer keeps the scene's recorded tracks on the GPU in one buffer (track_gpu.hpp): uploaded
// the first frame that draws them and reused after, rebuilt when a track's revision changes or a
// track arrives or leaves, kept while a track is hidden (hiding uploads nothing), and freed once
// the tracks have left the scene. Only visible tracks are drawn, each in its own colour.
#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

#include "gl_test_support.hpp"
#include "render/renderer.hpp"
#include "scene_test_support.hpp"
#include "track_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;
using test::LocalFrame;
using test::polyline;

constexpr scene::GeoPosition kPlace{46.5, 10.0, 0.0};
const scene::Lens kLens{30.0, 64, 48};

class RendererTracksTest : public GlTest {
 protected:
  scene::TrackGeometry line(double north_m) const {
    return test::geometry_of({polyline(frame_, {{-50, north_m, 800}, {50, north_m, 800}})});
  }
  LocalFrame frame_{kPlace};
  scene::Camera camera_ = test::looking_down({kPlace.lat_deg, kPlace.lon_deg, 1000.0}, kLens, 10.0);
};

TEST_F(RendererTracksTest, TheTracksAreUploadedOncePerRevisionAndFreedWhenTheyLeaveTheScene) {
  test::SceneDrawer drawer(nullptr, nullptr);
  scene::TrackSet tracks = test::track_set({test::track_of(line(-20)), test::track_of(line(20))});
  scene::Scene scene = test::plain_scene(kPlace, 0.0);
  scene.tracks = &tracks;

  const FrameReport first = drawer.draw(camera_, scene).report;
  EXPECT_EQ(first.tracks_drawn, 2u);
  EXPECT_EQ(first.gpu_tracks.uploads, 1u);  // both in one buffer
  EXPECT_EQ(first.gpu_tracks.entries, 1u);
  EXPECT_GT(first.gpu_tracks.bytes, 0u);

  const FrameReport again = drawer.draw(camera_, scene).report;
  EXPECT_EQ(again.gpu_tracks.uploads, 0u);
  EXPECT_EQ(again.gpu_tracks.entries, 1u);

  // Hiding a track uploads nothing; it is not drawn.
  tracks[1].visible = false;
  const FrameReport hidden = drawer.draw(camera_, scene).report;
  EXPECT_EQ(hidden.tracks_drawn, 1u);
  EXPECT_EQ(hidden.gpu_tracks.uploads, 0u);

  // A new revision rebuilds the buffer and frees the old one.
  tracks[0].geometry = line(-30);
  tracks[0].bump_revision();
  const FrameReport changed = drawer.draw(camera_, scene).report;
  EXPECT_EQ(changed.tracks_drawn, 1u);
  EXPECT_EQ(changed.gpu_tracks.uploads, 1u);
  EXPECT_EQ(changed.gpu_tracks.entries, 1u);
  EXPECT_EQ(changed.gpu_tracks.evictions, 1u);

  // Without tracks every buffer goes.
  scene.tracks = nullptr;
  const FrameReport none = drawer.draw(camera_, scene).report;
  EXPECT_EQ(none.tracks_drawn, 0u);
  EXPECT_EQ(none.gpu_tracks.entries, 0u);
  EXPECT_EQ(none.gpu_tracks.bytes, 0u);
}

TEST_F(RendererTracksTest, AHiddenTrackIsNotDrawn) {
  test::SceneDrawer drawer(nullptr, nullptr);
  scene::TrackSet tracks = test::track_set({test::track_of(line(0))});
  scene::Scene scene = test::plain_scene(kPlace, 0.0);
  const scene::RgbaImage ground = drawer.draw(camera_, scene).image;
  scene.tracks = &tracks;
  const scene::RgbaImage shown = drawer.draw(camera_, scene).image;
  tracks[0].visible = false;
  const scene::RgbaImage hidden = drawer.draw(camera_, scene).image;
  EXPECT_NE(shown.rgba, ground.rgba);
  EXPECT_EQ(hidden.rgba, ground.rgba);
}

// A width in pixels is in the viewer's pixels: a target of two device pixels per pixel (a high-DPI
// window, the page on a phone) draws the track twice as many pixels wide; a width in metres does
// not change with it.
TEST_F(RendererTracksTest, AWidthInPixelsFollowsThePixelRatioAndOneInMetresDoesNot) {
  test::SceneDrawer drawer(nullptr, nullptr);
  scene::TrackSet tracks = test::track_set({test::track_of(line(0))});
  scene::Scene scene = test::plain_scene(kPlace, 0.0);
  scene.style.shading.shadows = false;  // the track's own pixels, not its shadow's
  scene.terrain = &drawer.terrain();
  const auto covered = [&](double pixel_ratio) {
    ImageTarget ground, drawn;
    ground.pixel_ratio = drawn.pixel_ratio = pixel_ratio;
    scene.tracks = nullptr;
    drawer.renderer().draw(scene, camera_, ground);
    scene.tracks = &tracks;
    drawer.renderer().draw(scene, camera_, drawn);
    std::size_t n = 0;
    for (std::uint32_t y = 0; y < drawn.image.height; ++y)
      for (std::uint32_t x = 0; x < drawn.image.width; ++x) n += drawn.image.pixel(x, y) != ground.image.pixel(x, y);
    return static_cast<double>(n);
  };
  scene.style.tracks.width = {3.0, scene::TrackWidth::Unit::pixels};
  const double one = covered(1.0), two = covered(2.0);
  ASSERT_GT(one, 64.0);  // a line across the picture
  EXPECT_NEAR(two / one, 2.0, 0.4) << one << " pixels at ratio 1, " << two << " at ratio 2";
  scene.style.tracks.width = {12.0, scene::TrackWidth::Unit::metres};  // ~7 px: above the minimum width
  const double metres_one = covered(1.0), metres_two = covered(2.0);
  EXPECT_NEAR(metres_two / metres_one, 1.0, 0.1) << metres_one << " vs " << metres_two;
}

// Every pixel that `one` (of `all`) changes when drawn alone is the same, within 2/255, in the
// picture of all of them; at least `min_pixels` such pixels.
void expect_drawn_as_alone(test::SceneDrawer& drawer, const scene::Camera& camera, scene::Scene scene,
                           const std::vector<scene::Track>& all, std::size_t min_pixels) {
  scene.tracks = nullptr;
  const scene::RgbaImage ground = drawer.draw(camera, scene).image;
  scene::TrackSet together_set;
  for (const scene::Track& t : all) together_set.add(t);
  scene.tracks = &together_set;
  const test::Drawn together = drawer.draw(camera, scene);
  EXPECT_EQ(together.report.tracks_drawn, all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    scene::TrackSet alone_set = test::track_set({all[i]});
    scene.tracks = &alone_set;
    const scene::RgbaImage alone = drawer.draw(camera, scene).image;
    std::size_t covered = 0, same = 0;
    for (std::uint32_t y = 0; y < alone.height; ++y)
      for (std::uint32_t x = 0; x < alone.width; ++x) {
        if (alone.pixel(x, y) == ground.pixel(x, y)) continue;
        ++covered;
        const auto a = alone.pixel(x, y), b = together.image.pixel(x, y);
        bool close = true;
        for (int c = 0; c < 3; ++c) close = close && std::abs(int{a[c]} - int{b[c]}) <= 2;
        same += close ? 1 : 0;
      }
    EXPECT_GT(covered, min_pixels) << "track " << i;
    EXPECT_EQ(same, covered) << "track " << i;
  }
}

// Tracks that share one buffer are each drawn where, and in the colour, their own render puts them.
TEST_F(RendererTracksTest, TracksSharingABufferAreEachDrawnAsTheirOwnRenderDrawsThem) {
  test::SceneDrawer drawer(nullptr, nullptr);
  const scene::Lens lens{30.0, 160, 120};
  const scene::Camera camera = test::looking_down({kPlace.lat_deg, kPlace.lon_deg, 2000.0}, lens, 10.0);
  const auto across = [&](double north_m) {
    return test::geometry_of(
        {polyline(frame_, {{-300, north_m, 800}, {-100, north_m + 30, 800}, {300, north_m, 800}})});
  };
  expect_drawn_as_alone(
      drawer, camera, test::plain_scene(kPlace, 0.0),
      {test::track_of(across(-200), {0.9f, 0.1f, 0.1f}), test::track_of(across(0), {0.1f, 0.4f, 0.9f}),
       test::track_of(across(200), {0.1f, 0.8f, 0.2f})},
      400);
}

// The same with shadows, seen obliquely: tracks near and far fall into different shadow cascades,
// and each cascade draws only the tracks that reach it (TrackPass::draw_shadow_casters): every
// track's shadow is where its own render casts it.
TEST_F(RendererTracksTest, TracksSharingABufferCastTheShadowsOfTheirOwnRenders) {
  test::SceneDrawer drawer(nullptr, nullptr);
  const scene::Lens lens{40.0, 200, 120};
  const scene::Camera camera(frame_.point(0.0, -1500.0, 700.0), 0.0, -20.0, lens, scene::DepthRange{5.0, 1.0e5});
  const auto across = [&](double north_m, double up_m) {
    return test::geometry_of(
        {polyline(frame_, {{-200, north_m, up_m}, {-50, north_m + 40, up_m}, {200, north_m, up_m}})});
  };
  scene::Scene scene = test::plain_scene(kPlace, 0.0);
  scene.style.shading.shadows = true;
  expect_drawn_as_alone(
      drawer, camera, scene,
      {test::track_of(across(-400, 60), {0.9f, 0.1f, 0.1f}), test::track_of(across(2500, 120), {0.1f, 0.4f, 0.9f}),
       test::track_of(across(12000, 600), {0.1f, 0.8f, 0.2f})},
      20);
}

}  // namespace
}  // namespace trailray::render
