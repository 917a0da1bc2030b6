// The renderer keeps the scene's tracks on the GPU by (track id, revision): a track is uploaded
// the first frame that draws it and reused after, uploaded again when its revision changes, kept
// while hidden, and freed once it has left the scene. Only visible tracks are drawn.
#include <gtest/gtest.h>

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

TEST_F(RendererTracksTest, ATrackIsUploadedOncePerRevisionAndFreedWhenItLeavesTheScene) {
  test::SceneDrawer drawer(nullptr, nullptr);
  scene::TrackSet tracks = test::track_set({test::track_of(line(-20)), test::track_of(line(20))});
  scene::Scene scene = test::plain_scene(kPlace, 0.0);
  scene.tracks = &tracks;

  const FrameReport first = drawer.draw(camera_, scene).report;
  EXPECT_EQ(first.tracks_drawn, 2u);
  EXPECT_EQ(first.gpu_tracks.uploads, 2u);
  EXPECT_EQ(first.gpu_tracks.entries, 2u);
  EXPECT_GT(first.gpu_tracks.bytes, 0u);

  const FrameReport again = drawer.draw(camera_, scene).report;
  EXPECT_EQ(again.gpu_tracks.uploads, 0u);
  EXPECT_EQ(again.gpu_tracks.entries, 2u);

  // A new revision replaces the old buffer; a hidden track keeps its own but is not drawn.
  tracks[0].geometry = line(-30);
  tracks[0].bump_revision();
  tracks[1].visible = false;
  const FrameReport changed = drawer.draw(camera_, scene).report;
  EXPECT_EQ(changed.tracks_drawn, 1u);
  EXPECT_EQ(changed.gpu_tracks.uploads, 1u);
  EXPECT_EQ(changed.gpu_tracks.entries, 2u);
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

}  // namespace
}  // namespace trailray::render
