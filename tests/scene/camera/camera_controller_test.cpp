// The viewer's camera gestures without a window: drag, pan and zoom against a known ground, and
// the camera kept above it.
#include "scene/camera/camera_controller.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace trailray::scene {
namespace {

constexpr double kLat = 46.6, kLon = 8.0;
const scene::Lens kLens{45.0, 480, 270};

scene::LookAt start_view() {
  scene::LookAt v;
  v.target = {kLat, kLon, 1000.0};
  v.distance_m = 3000.0;
  v.heading_deg = 30.0;
  v.pitch_deg = -35.0;
  return v;
}

double flat_ground(double, double) { return 1000.0; }

// The pixel where `p` appears now.
glm::dvec2 pixel_of(const CameraController& c, const scene::GeoPosition& p) {
  const auto s = c.camera().project(scene::ecef_from(p));
  EXPECT_TRUE(s.has_value());
  return s ? glm::dvec2(s->x_px, s->y_px) : glm::dvec2(NAN);
}

TEST(CameraController, ADragToTheRightTurnsTheHeadingAndADragDownSteepensThePitch) {
  CameraController c(start_view(), kLens, flat_ground);
  c.orbit(40.0, 0.0);
  EXPECT_NEAR(c.view().heading_deg, 30.0 - 40.0 * 0.25, 1e-9);
  EXPECT_NEAR(c.view().pitch_deg, -35.0, 1e-9);
  c.orbit(0.0, 20.0);
  EXPECT_NEAR(c.view().pitch_deg, -40.0, 1e-9);
  c.orbit(-200.0, 0.0);  // across north
  EXPECT_NEAR(c.view().heading_deg, 70.0, 1e-9);
  // The pivot stays where it was: orbiting turns around it.
  EXPECT_DOUBLE_EQ(c.view().target.lat_deg, kLat);
  EXPECT_DOUBLE_EQ(c.view().target.lon_deg, kLon);
}

TEST(CameraController, ZoomingKeepsTheGroundPointUnderTheCursor) {
  for (const double steps : {3.0, -2.0}) {
    CameraController c(start_view(), kLens, flat_ground);
    const double x = 350.0, y = 190.0;  // off the centre: the pivot moves
    const auto grabbed = c.ground_point_at(x, y);
    ASSERT_TRUE(grabbed.has_value());
    EXPECT_NEAR(grabbed->height_m, 1000.0, 0.01);
    const double before = c.view().distance_m;
    c.zoom(steps, x, y);
    EXPECT_NEAR(c.view().distance_m, before * std::pow(0.8, steps), 1e-6);
    const glm::dvec2 now = pixel_of(c, *grabbed);
    EXPECT_NEAR(now.x, x, 0.5) << steps;
    EXPECT_NEAR(now.y, y, 0.5) << steps;
    EXPECT_NE(c.view().target.lat_deg, kLat);
  }
}

TEST(CameraController, PanningMovesTheGrabbedGroundPointWithTheCursor) {
  CameraController c(start_view(), kLens, flat_ground);
  const auto grabbed = c.ground_point_at(150.0, 160.0);
  ASSERT_TRUE(grabbed.has_value());
  c.pan(150.0, 160.0, 260.0, 120.0);
  const glm::dvec2 now = pixel_of(c, *grabbed);
  EXPECT_NEAR(now.x, 260.0, 0.5);
  EXPECT_NEAR(now.y, 120.0, 0.5);
  EXPECT_NEAR(c.view().heading_deg, 30.0, 1e-9);  // panning does not turn
}

TEST(CameraController, TheCameraStaysAboveRisingGround) {
  // A wall 2500 m high west of the pivot's meridian, behind a camera looking east.
  const auto wall = [](double, double lon) { return lon < kLon - 0.01 ? 3500.0 : 1000.0; };
  scene::LookAt v = start_view();
  v.heading_deg = 90.0;
  v.pitch_deg = -5.0;
  v.distance_m = 4000.0;  // 4 km west of the pivot: inside the wall
  CameraController c(v, kLens, wall);
  const scene::GeoPosition at = c.camera().geodetic();
  EXPECT_GE(at.height_m, wall(at.lat_deg, at.lon_deg) + 5.0 - 0.01);
  // Gestures that would push it into the ground are undone the same way.
  c.tilt(+30.0);
  c.orbit(0.0, -400.0);
  const scene::GeoPosition after = c.camera().geodetic();
  EXPECT_GE(after.height_m, wall(after.lat_deg, after.lon_deg) + 5.0 - 0.01);
  // And without anything in the way the camera keeps what it is given.
  CameraController free(v, kLens, flat_ground);
  EXPECT_NEAR(free.view().pitch_deg, -5.0, 1e-9);
}

TEST(CameraController, AFlightEndsExactlyAtItsTargetAndPassesInBetween) {
  CameraController c(start_view(), kLens, flat_ground);
  scene::LookAt to = start_view();
  to.target = {kLat + 0.05, kLon + 0.05, 1000.0};
  to.distance_m = 800.0;
  to.heading_deg = 350.0;  // the short way round: through north, not back through 180
  c.fly_to(to);
  EXPECT_TRUE(c.animating());
  c.update(0.6);  // halfway through the default 1.2 s
  EXPECT_GT(c.view().target.lat_deg, kLat);
  EXPECT_LT(c.view().target.lat_deg, kLat + 0.05);
  EXPECT_TRUE(c.view().heading_deg < 30.0 || c.view().heading_deg > 350.0) << c.view().heading_deg;
  c.update(0.7);
  EXPECT_FALSE(c.animating());
  EXPECT_DOUBLE_EQ(c.view().target.lat_deg, kLat + 0.05);
  EXPECT_NEAR(c.view().distance_m, 800.0, 1e-9);
  EXPECT_NEAR(c.view().heading_deg, 350.0, 1e-9);
}

TEST(CameraController, ResetNorthTurnsTheHeadingToZero) {
  CameraController c(start_view(), kLens, flat_ground);
  c.reset_north();
  c.update(5.0);
  EXPECT_NEAR(std::fmod(c.view().heading_deg, 360.0), 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(c.view().target.lat_deg, kLat);
}

TEST(CameraController, ALookAtRecoveredFromItsCameraIsTheSame) {
  const scene::LookAt v = start_view();
  const auto camera = scene::camera_looking_at(v, kLens, 1000.0);
  ASSERT_TRUE(camera.ok());
  const scene::LookAt back = CameraController::look_at_from_camera(*camera.value, 1000.0);
  EXPECT_NEAR(back.target.lat_deg, v.target.lat_deg, 1e-7);
  EXPECT_NEAR(back.target.lon_deg, v.target.lon_deg, 1e-7);
  EXPECT_NEAR(back.distance_m, v.distance_m, 0.01);
  EXPECT_NEAR(back.heading_deg, v.heading_deg, 1e-6);
  EXPECT_NEAR(back.pitch_deg, v.pitch_deg, 1e-6);
}

TEST(CameraController, KeysMoveThePivotAlongTheHeading) {
  scene::LookAt v = start_view();
  v.heading_deg = 0.0;
  CameraController c(v, kLens, flat_ground);
  c.move(0.0, 0.1);  // forward: north, by a tenth of the distance
  EXPECT_GT(c.view().target.lat_deg, kLat);
  EXPECT_NEAR(c.view().target.lon_deg, kLon, 1e-9);
  EXPECT_NEAR((c.view().target.lat_deg - kLat) * 111200.0, 300.0, 3.0);
}

}  // namespace
}  // namespace trailray::scene

namespace trailray::scene {
namespace {

TEST(CameraController, FollowingMovesThePivotAndChaseTurnsTheHeading) {
  CameraController c(start_view(), kLens, flat_ground);
  const scene::GeoPosition marker{kLat + 0.01, kLon, 1500.0};
  c.follow(marker);
  EXPECT_DOUBLE_EQ(c.view().target.lat_deg, kLat + 0.01);
  EXPECT_DOUBLE_EQ(c.view().target.height_m, 1500.0);
  EXPECT_NEAR(c.view().heading_deg, 30.0, 1e-9);  // orbit: the heading stays
  c.follow(marker, -90.0);                        // chase: look west, along the track
  EXPECT_NEAR(c.view().heading_deg, 270.0, 1e-9);
  const glm::dvec2 centre = pixel_of(c, marker);
  EXPECT_NEAR(centre.x, kLens.width_px / 2.0, 0.5);  // the marker in the middle of the view
  EXPECT_NEAR(centre.y, kLens.height_px / 2.0, 0.5);
}

}  // namespace
}  // namespace trailray::scene
