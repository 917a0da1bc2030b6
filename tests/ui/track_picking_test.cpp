// Picking a track point under the cursor: the nearest projected point within the radius, points
// of hidden tracks never, and a point in front of the terrain before one hidden behind it.
#include <gtest/gtest.h>

#include <vector>

#include "scene/camera/camera.hpp"
#include "ui/track_picking.hpp"

namespace trailray::ui {
namespace {

// A camera 2 km above Interlaken looking north and down 20 degrees, 640x360.
scene::Camera test_camera() {
  scene::Lens lens;
  lens.width_px = 640;
  lens.height_px = 360;
  const glm::dvec3 eye = scene::ecef_from({46.68, 7.86, 2600.0});
  return scene::Camera(eye, 0.0, -20.0, lens, scene::DepthRange{1.0, 1.0e6});
}

// The point `distance_m` from the eye along the ray through pixel (x, y).
glm::dvec3 along(const scene::Camera& camera, double x, double y, double distance_m) {
  const scene::Ray ray = camera.ray_through_pixel(x, y);
  return ray.origin + distance_m * ray.direction;
}

// A track of one segment through the points (picking reads only the drawn geometry).
scene::Track track_at(std::vector<glm::dvec3> points) {
  scene::Track t;
  t.segment_first = {0};
  t.geometry.segments.push_back({std::move(points), {}, {}});
  return t;
}

scene::TrackSet set_of(std::vector<scene::Track> tracks) {
  scene::TrackSet set;
  for (scene::Track& t : tracks) set.add(std::move(t));
  return set;
}

TEST(TrackPicking, TheNearestPointWithinTheRadius) {
  const scene::Camera camera = test_camera();
  const scene::TrackSet tracks = set_of(
      {track_at({along(camera, 300, 200, 3000.0), along(camera, 306, 200, 3000.0), along(camera, 100, 50, 3000.0)})});
  HoverState h = pick_track_point(tracks, camera, 304.0, 200.0);
  EXPECT_EQ(h.track, 0);
  EXPECT_EQ(h.point, 1u);  // 2 px away, the other 4 px
  h = pick_track_point(tracks, camera, 200.0, 120.0);
  EXPECT_EQ(h.track, -1) << "nothing within " << kPickRadiusPx << " px";
}

TEST(TrackPicking, HiddenTracksAreNotPicked) {
  const scene::Camera camera = test_camera();
  scene::TrackSet tracks =
      set_of({track_at({along(camera, 300, 200, 3000.0)}), track_at({along(camera, 303, 200, 2000.0)})});
  EXPECT_EQ(pick_track_point(tracks, camera, 303.0, 200.0).track, 1);
  tracks[1].visible = false;
  EXPECT_EQ(pick_track_point(tracks, camera, 303.0, 200.0).track, 0);
}

// Far away, where the renderer merges hundreds of a track's capsules into one (its level of
// detail), picking still reads the recorded points: the cursor on a point's exact projection
// picks that point, though its neighbours lie within a fraction of a pixel.
TEST(TrackPicking, FarAwayTheCursorStillPicksTheExactRecordedPoint) {
  const scene::Camera camera = test_camera();
  std::vector<glm::dvec3> points;
  const glm::dvec3 start = along(camera, 320, 180, 40000.0), towards = along(camera, 330, 182, 40000.0);
  for (int i = 0; i < 1000; ++i) {
    const double s = i / 999.0;
    // A zig-zag of 1000 points over 10 pixels: about 0.01 px apart along it, 5 m across.
    points.push_back(start + s * (towards - start) + ((i % 2) ? 5.0 : -5.0) * glm::dvec3(0.0, 0.0, 1.0));
  }
  const scene::TrackSet tracks = set_of({track_at(points)});
  for (const std::size_t k : {0u, 1u, 537u, 998u}) {
    const auto at = screen_position(camera, points[k]);
    ASSERT_TRUE(at.has_value());
    const HoverState h = pick_track_point(tracks, camera, at->x, at->y);
    EXPECT_EQ(h.track, 0);
    EXPECT_EQ(h.point, k);
  }
}

// A track passes in front of a ridge (1500 m away) and again behind it (4000 m): with the cursor
// exactly on the far pass and the near pass 5 px off, the near pass is what the user sees there.
TEST(TrackPicking, APointInFrontOfTheTerrainBeatsAHiddenOne) {
  const scene::Camera camera = test_camera();
  const scene::TrackSet tracks = set_of({track_at({along(camera, 320, 180, 4000.0), along(camera, 325, 180, 1500.0)})});
  const auto depth = [&](const glm::dvec3& p) { return camera.project(p)->depth_m; };
  const double ridge_depth = depth(along(camera, 320, 180, 2500.0));

  // Without terrain the nearest in pixels wins: the far pass.
  EXPECT_EQ(pick_track_point(tracks, camera, 320.0, 180.0).point, 0u);
  // The ridge hides the far pass: the near one wins although it is farther from the cursor.
  EXPECT_EQ(pick_track_point(tracks, camera, 320.0, 180.0, kPickRadiusPx, ridge_depth).point, 1u);
  // Terrain beyond both: nothing hidden, the nearest in pixels again.
  EXPECT_EQ(pick_track_point(tracks, camera, 320.0, 180.0, kPickRadiusPx,
                             depth(tracks[0].geometry.segments[0].points_ecef[0]) + 500.0)
                .point,
            0u);
  // A hidden point is still picked when it is the only one (the pass draws it as a ghost).
  const scene::TrackSet far_only = set_of({track_at({tracks[0].geometry.segments[0].points_ecef[0]})});
  const HoverState ghost = pick_track_point(far_only, camera, 320.0, 180.0, kPickRadiusPx, ridge_depth);
  EXPECT_EQ(ghost.track, 0);
  EXPECT_EQ(ghost.point, 0u);
}

// A point lying on the ground is not hidden by the ground it lies on.
TEST(TrackPicking, APointOnTheGroundIsNotHiddenByIt) {
  const scene::Camera camera = test_camera();
  const scene::TrackSet tracks = set_of({track_at({along(camera, 320, 180, 5000.0), along(camera, 324, 180, 5002.0)})});
  const double ground = camera.project(tracks[0].geometry.segments[0].points_ecef[0])->depth_m;
  // Both count as visible: the nearer one in pixels wins (the one 2 m behind the ground is not
  // demoted).
  EXPECT_EQ(pick_track_point(tracks, camera, 323.0, 180.0, kPickRadiusPx, ground).point, 1u);
}

}  // namespace
}  // namespace trailray::ui
