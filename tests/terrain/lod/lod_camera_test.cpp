#include "terrain/lod/lod_camera.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "geo/wgs84.hpp"

namespace trailray::terrain {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Above Interlaken at 3000 m, looking at the summit of the Eiger.
LodCamera interlaken_to_eiger() { return look_at(46.68, 7.86, 3000.0, 46.577, 8.005, 3967.0, 60.0 * kDeg, 1920, 1080); }

// The geodetic up is the direction in which height grows.
TEST(LodCamera, GeodeticUpIsWhereHeightGrows) {
  const glm::dvec3 p = geo::ecef_from_geodetic(46.68, 7.86, 3000.0);
  const glm::dvec3 up = geodetic_up(46.68, 7.86);
  const glm::dvec3 higher = geo::ecef_from_geodetic(46.68, 7.86, 4000.0) - p;
  EXPECT_NEAR(higher.x, 1000.0 * up.x, 1e-6);
  EXPECT_NEAR(higher.y, 1000.0 * up.y, 1e-6);
  EXPECT_NEAR(higher.z, 1000.0 * up.z, 1e-6);
}

TEST(LodCamera, LookAtPutsTheTargetInTheCentreWithTheSkyUp) {
  const LodCamera camera = interlaken_to_eiger();
  EXPECT_NEAR(glm::length(camera.forward), 1.0, 1e-12);
  EXPECT_NEAR(glm::length(camera.up), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(camera.forward, camera.up), 0.0, 1e-12);
  EXPECT_EQ(camera.viewport_width_px, 1920u);
  EXPECT_EQ(camera.viewport_height_px, 1080u);

  const auto target = project_to_pixels(camera, geo::ecef_from_geodetic(46.577, 8.005, 3967.0));
  ASSERT_TRUE(target);
  EXPECT_NEAR(target->x_px, 960.0, 1e-6);
  EXPECT_NEAR(target->y_px, 540.0, 1e-6);
  EXPECT_NEAR(target->depth_m, glm::length(geo::ecef_from_geodetic(46.577, 8.005, 3967.0) - camera.position), 1e-6);

  // A point 1000 m above the summit is above it on screen (smaller y), not beside it.
  const auto above = project_to_pixels(camera, geo::ecef_from_geodetic(46.577, 8.005, 4967.0));
  ASSERT_TRUE(above);
  EXPECT_LT(above->y_px, 540.0 - 10.0);
  EXPECT_NEAR(above->x_px, 960.0, 5.0);
  // The Eiger lies south-east of Interlaken: a point east of it is to the left of the view's
  // centre line (looking south-east, east is on the left).
  const auto east = project_to_pixels(camera, geo::ecef_from_geodetic(46.577, 8.10, 3967.0));
  ASSERT_TRUE(east);
  EXPECT_LT(east->x_px, 960.0);

  // The far plane reaches past the horizon of a 9000 m peak seen from 3000 m (195 + 339 km).
  EXPECT_GT(camera.far_m, 530e3);
  EXPECT_EQ(camera_problem(camera), std::nullopt);
}

TEST(LodCamera, PointsBehindHaveNoImage) {
  const LodCamera camera = interlaken_to_eiger();
  // Interlaken lies north-west of the camera's target; a point 20 km further north-west is behind.
  EXPECT_FALSE(project_to_pixels(camera, geo::ecef_from_geodetic(46.85, 7.60, 600.0)));
  EXPECT_FALSE(project_to_pixels(camera, camera.position));
}

TEST(LodCamera, LookingStraightDownPutsNorthUp) {
  const LodCamera camera = look_at(46.68, 7.86, 5000.0, 46.68, 7.86, 0.0, 60.0 * kDeg, 800, 600);
  const auto north = project_to_pixels(camera, geo::ecef_from_geodetic(46.69, 7.86, 0.0));
  const auto east = project_to_pixels(camera, geo::ecef_from_geodetic(46.68, 7.87, 0.0));
  ASSERT_TRUE(north && east);
  EXPECT_NEAR(north->x_px, 400.0, 1.0);
  EXPECT_LT(north->y_px, 300.0 - 50.0);
  EXPECT_GT(east->x_px, 400.0 + 50.0);
  EXPECT_NEAR(east->y_px, 300.0, 1.0);

  // Also at the pole, where the local north depends on the longitude.
  const LodCamera pole = look_at(90.0, 30.0, 10000.0, 90.0, 30.0, 0.0, 60.0 * kDeg, 800, 600);
  EXPECT_EQ(camera_problem(pole), std::nullopt);
  EXPECT_NEAR(glm::dot(pole.forward, pole.up), 0.0, 1e-12);
}

TEST(LodCamera, PixelsPerMetreIsTheProjectedSizeOfAMetre) {
  const LodCamera camera = look_at(0.0, 0.0, 10000.0, 0.0, 0.0, 0.0, 50.0 * kDeg, 1000, 700);
  EXPECT_NEAR(camera.pixels_per_metre_at(10000.0), 700.0 / (2.0 * 10000.0 * std::tan(25.0 * kDeg)), 1e-15);
  // A 100 m stretch of ground across the view, 10 km below, spans 100 * pixels_per_metre_at(10 km)
  // pixels (the ground is flat enough over 100 m: the curvature changes that by under 1e-6).
  const glm::dvec3 centre = geo::ecef_from_geodetic(0.0, 0.0, 0.0);
  const glm::dvec3 right = camera.right();
  const auto a = project_to_pixels(camera, centre - right * 50.0);
  const auto b = project_to_pixels(camera, centre + right * 50.0);
  ASSERT_TRUE(a && b);
  EXPECT_NEAR(b->x_px - a->x_px, 100.0 * camera.pixels_per_metre_at(10000.0), 1e-6);
  // Twice as far, half as many pixels.
  EXPECT_DOUBLE_EQ(camera.pixels_per_metre_at(20000.0), 0.5 * camera.pixels_per_metre_at(10000.0));
}

TEST(LodCamera, RayThroughPixelInvertsTheProjection) {
  const LodCamera camera = interlaken_to_eiger();
  for (double x : {0.0, 100.5, 960.0, 1919.0, 1920.0}) {
    for (double y : {0.0, 333.3, 540.0, 1080.0}) {
      const glm::dvec3 ray = ray_through_pixel(camera, x, y);
      EXPECT_NEAR(glm::length(ray), 1.0, 1e-12);
      const auto s = project_to_pixels(camera, camera.position + ray * 5000.0);
      ASSERT_TRUE(s);
      EXPECT_NEAR(s->x_px, x, 1e-6);
      EXPECT_NEAR(s->y_px, y, 1e-6);
    }
  }
}

TEST(LodCamera, FrustumHoldsExactlyWhatIsOnScreenBetweenNearAndFar) {
  const LodCamera camera = interlaken_to_eiger();
  const Frustum frustum = frustum_planes(camera);
  for (const FrustumPlane& plane : frustum.planes) EXPECT_NEAR(glm::length(plane.normal), 1.0, 1e-12);
  // Points along rays through pixels: inside for pixels in the viewport at depths within
  // [near, far], outside otherwise.
  struct Case {
    double x, y, distance;
    bool inside;
  };
  const Case cases[] = {
      {960, 540, 1000, true},
      {1, 1, 1000, true},
      {1919, 1079, 50000, true},
      {-5, 540, 1000, false},
      {1925, 540, 1000, false},
      {960, -5, 1000, false},
      {960, 1085, 1000, false},
      {960, 540, 0.5, false},
      {960, 540, camera.far_m + 10.0, false},
      {960, 540, 2.0, true},
      {1910, 10, camera.far_m * 0.9, true},
  };
  for (const Case& c : cases) {
    const glm::dvec3 ray = ray_through_pixel(camera, c.x, c.y);
    // Distance along the view axis: scale the ray so its depth is c.distance.
    const glm::dvec3 p = camera.position + ray * (c.distance / glm::dot(ray, camera.forward));
    EXPECT_EQ(frustum.contains(p), c.inside) << c.x << ", " << c.y << " at " << c.distance;
  }
  // Behind the camera: outside whatever the direction.
  EXPECT_FALSE(frustum.contains(camera.position - camera.forward * 100.0));
  // Each side plane passes through the camera.
  for (int side : {kFrustumLeft, kFrustumRight, kFrustumBottom, kFrustumTop}) {
    EXPECT_NEAR(frustum.planes[side].signed_distance(camera.position), 0.0, 1e-6);
  }
}

TEST(LodCamera, BadInputIsRefusedWithAClearMessage) {
  EXPECT_THROW(look_at(kNaN, 7.86, 3000.0, 46.577, 8.005, 3967.0, 1.0, 100, 100), std::invalid_argument);
  EXPECT_THROW(look_at(46.68, 7.86, 3000.0, 46.68, 7.86, 3000.0, 1.0, 100, 100), std::invalid_argument);
  EXPECT_THROW(look_at(46.68, 7.86, 3000.0, 46.577, 8.005, 3967.0, 0.0, 100, 100), std::invalid_argument);
  EXPECT_THROW(look_at(46.68, 7.86, 3000.0, 46.577, 8.005, 3967.0, 4.0, 100, 100), std::invalid_argument);
  EXPECT_THROW(look_at(46.68, 7.86, 3000.0, 46.577, 8.005, 3967.0, 1.0, 0, 100), std::invalid_argument);
  EXPECT_THROW(look_at(95.0, 7.86, 3000.0, 46.577, 8.005, 3967.0, 1.0, 100, 100), std::invalid_argument);
  try {
    look_at(46.68, 7.86, 3000.0, 46.68, 7.86, 3000.0, 1.0, 100, 100);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("46.68"), std::string::npos) << e.what();
  }

  LodCamera camera = interlaken_to_eiger();
  EXPECT_EQ(camera_problem(camera), std::nullopt);
  camera.up = camera.forward;
  EXPECT_TRUE(camera_problem(camera));
  camera = interlaken_to_eiger();
  camera.position.x = kNaN;
  EXPECT_TRUE(camera_problem(camera));
  camera = interlaken_to_eiger();
  camera.near_m = camera.far_m;
  EXPECT_TRUE(camera_problem(camera));
  camera = interlaken_to_eiger();
  camera.viewport_height_px = 0;
  EXPECT_TRUE(camera_problem(camera));
}

}  // namespace
}  // namespace trailray::terrain
