// Cascaded shadow maps, CPU half: splits, slice coverage, stability under camera motion and
// rotation, caster reach towards the sun, bias by texel size, input errors.

#include "render/passes/shadow_cascades.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace trailray::render {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

// Above Interlaken, 1500 m over the ellipsoid, a 16:9 image.
const scene::GeoPosition kCameraPosition{46.69, 7.86, 1500.0};
const scene::Lens kLens{45.0, 1280, 720};
const scene::DepthRange kDepth{100.0, 300'000.0};

scene::Camera camera(double heading, double pitch, const glm::dvec3& shift = glm::dvec3(0.0)) {
  return scene::Camera(scene::ecef_from(kCameraPosition) + shift, heading, pitch, kLens, kDepth);
}

// The sun 35 degrees high in the south-east of the camera.
glm::dvec3 sun_direction() {
  const scene::EnuAxes enu = scene::enu_axes_at(kCameraPosition.lat_deg, kCameraPosition.lon_deg);
  const double elevation = 35.0 * kRadPerDeg, azimuth = 135.0 * kRadPerDeg;
  return std::cos(elevation) * (std::sin(azimuth) * enu.east + std::cos(azimuth) * enu.north) +
         std::sin(elevation) * enu.up;
}

// The eight corners of the camera frustum's slice between view depths near and far.
std::vector<glm::dvec3> slice_corners(const scene::Camera& cam, double near_m, double far_m) {
  const double tan_v = std::tan(0.5 * cam.lens().vertical_fov_deg * kRadPerDeg);
  const double tan_h = tan_v * cam.lens().aspect();
  std::vector<glm::dvec3> corners;
  for (double depth : {near_m, far_m}) {
    for (double sx : {-1.0, 1.0}) {
      for (double sy : {-1.0, 1.0}) {
        corners.push_back(cam.position() + depth * cam.axes().forward + sx * depth * tan_h * cam.axes().right +
                          sy * depth * tan_v * cam.axes().up);
      }
    }
  }
  return corners;
}

glm::dvec3 clip_of(const ShadowCascade& cascade, const glm::dvec3& point) {
  const glm::dvec4 clip = cascade.view_projection_relative_to_d(point) * glm::dvec4(0.0, 0.0, 0.0, 1.0);
  return glm::dvec3(clip) / clip.w;
}

TEST(ShadowCascades, PracticalSplitsIncreaseAndCoverNearToFar) {
  const auto splits = practical_split_depths(100.0, 60'000.0, 0.7);
  EXPECT_DOUBLE_EQ(splits.front(), 100.0);
  EXPECT_DOUBLE_EQ(splits.back(), 60'000.0);
  for (std::size_t i = 1; i < splits.size(); ++i) EXPECT_GT(splits[i], splits[i - 1]) << "split " << i;
  // Between the logarithmic (lambda 1) and the uniform (lambda 0) scheme.
  const auto logarithmic = practical_split_depths(100.0, 60'000.0, 1.0);
  const auto uniform = practical_split_depths(100.0, 60'000.0, 0.0);
  EXPECT_NEAR(logarithmic[2], 100.0 * std::sqrt(600.0), 1e-6);
  EXPECT_NEAR(uniform[2], 30'050.0, 1e-6);
  for (std::size_t i = 1; i + 1 < splits.size(); ++i) {
    EXPECT_GT(splits[i], logarithmic[i]);
    EXPECT_LT(splits[i], uniform[i]);
  }
}

TEST(ShadowCascades, CascadesTileTheViewUpToTheShadowDistance) {
  const ShadowCascades cascades(camera(20.0, -20.0), sun_direction());
  EXPECT_DOUBLE_EQ(cascades[0].near_m, kDepth.near_m);
  EXPECT_DOUBLE_EQ(cascades[kShadowCascadeCount - 1].far_m, 60'000.0);  // capped, not the camera's 300 km
  for (std::size_t i = 1; i < kShadowCascadeCount; ++i) EXPECT_DOUBLE_EQ(cascades[i].near_m, cascades[i - 1].far_m);
  const auto far = cascades.split_far_m();
  for (std::size_t i = 0; i < kShadowCascadeCount; ++i) EXPECT_FLOAT_EQ(far[i], static_cast<float>(cascades[i].far_m));

  // A camera whose far plane is nearer than the cap ends its shadows there.
  const scene::Camera short_view(scene::ecef_from(kCameraPosition), 0.0, -10.0, kLens, scene::DepthRange{10.0, 5'000.0});
  EXPECT_DOUBLE_EQ(ShadowCascades(short_view, sun_direction())[kShadowCascadeCount - 1].far_m, 5'000.0);
}

TEST(ShadowCascades, EachCascadeContainsItsFrustumSlice) {
  for (double heading : {0.0, 77.0, 200.0}) {
    for (double pitch : {-80.0, -30.0, 0.0, 25.0}) {
      const scene::Camera cam = camera(heading, pitch);
      const ShadowCascades cascades(cam, sun_direction());
      for (std::size_t i = 0; i < kShadowCascadeCount; ++i) {
        const ShadowCascade& c = cascades[i];
        for (const glm::dvec3& corner : slice_corners(cam, c.near_m, c.far_m)) {
          const glm::dvec3 clip = clip_of(c, corner);
          const std::string where = "cascade " + std::to_string(i) + ", heading " + std::to_string(heading) +
                                    ", pitch " + std::to_string(pitch);
          EXPECT_LE(std::abs(clip.x), 1.0) << where;
          EXPECT_LE(std::abs(clip.y), 1.0) << where;
          EXPECT_LE(std::abs(clip.z), 1.0) << where;
        }
      }
    }
  }
}

TEST(ShadowCascades, CastersUpToTheHeightSpanTowardsTheSunAreInside) {
  ShadowCascadeSettings settings;
  settings.caster_height_span_m = 3'000.0;
  const scene::Camera cam = camera(135.0, -30.0);
  const ShadowCascades cascades(cam, sun_direction(), settings);
  const double sin_elevation = std::sin(35.0 * kRadPerDeg);
  for (std::size_t i = 0; i < kShadowCascadeCount; ++i) {
    const ShadowCascade& c = cascades[i];
    for (const glm::dvec3& receiver : slice_corners(cam, c.near_m, c.far_m)) {
      // A caster 3000 m above the receiver on its sun ray.
      const glm::dvec3 caster = receiver + sun_direction() * (0.999 * 3'000.0 / sin_elevation);
      const glm::dvec3 clip = clip_of(c, caster);
      EXPECT_GE(clip.z, -1.0) << "cascade " << i;
      EXPECT_LE(clip.z, 1.0) << "cascade " << i;
      // The caster is nearer the sun, so it has the smaller depth: it occludes.
      EXPECT_LT(clip.z, clip_of(c, receiver).z);
    }
  }
}

TEST(ShadowCascades, MovingTheCameraMovesEachMapByWholeTexelsOrNotAtAll) {
  const ShadowCascades reference(camera(30.0, -25.0), sun_direction());
  const int size = reference.settings().map_size_px;
  const glm::dvec3 world_point = scene::ecef_from(scene::GeoPosition{46.72, 7.90, 800.0});
  const double texel0 = reference[0].texel_size_m;
  int moves_seen = 0;
  for (const glm::dvec3& step : {glm::dvec3(0.3, 0.0, 0.0), glm::dvec3(0.0, 0.45, 0.1), glm::dvec3(-0.7, 0.2, 0.6),
                                 glm::dvec3(3.3, -2.1, 1.7), glm::dvec3(41.3, 17.9, -8.2)}) {
    const ShadowCascades moved(camera(30.0, -25.0, step * texel0), sun_direction());
    for (std::size_t i = 0; i < kShadowCascadeCount; ++i) {
      ASSERT_DOUBLE_EQ(moved[i].texel_size_m, reference[i].texel_size_m);
      const glm::dvec3 before = reference[i].texel_and_depth(world_point, size);
      const glm::dvec3 after = moved[i].texel_and_depth(world_point, size);
      for (int axis = 0; axis < 2; ++axis) {
        const double shift = after[axis] - before[axis];
        EXPECT_NEAR(shift, std::round(shift), 1e-4) << "cascade " << i << ", axis " << axis;
        if (std::abs(shift) > 0.5) ++moves_seen;
      }
    }
  }
  // The larger steps do move the maps (the test would pass vacuously if nothing ever moved).
  EXPECT_GT(moves_seen, 0);
  // Sub-texel steps are absorbed most of the time: the first cascade did not move for 0.3 texel
  // unless its centre sat right at a rounding boundary; either way it moved whole texels.
}

TEST(ShadowCascades, RotatingTheCameraKeepsEachCascadesSize) {
  const ShadowCascades reference(camera(0.0, 0.0), sun_direction());
  for (double heading : {13.0, 90.0, 181.0, 359.0}) {
    for (double pitch : {-89.0, -45.0, -5.0, 40.0}) {
      const ShadowCascades turned(camera(heading, pitch), sun_direction());
      for (std::size_t i = 0; i < kShadowCascadeCount; ++i) {
        EXPECT_NEAR(turned[i].radius_m, reference[i].radius_m, 1e-9 * reference[i].radius_m);
        EXPECT_NEAR(turned[i].texel_size_m, reference[i].texel_size_m, 1e-12 * reference[i].radius_m);
      }
    }
  }
}

TEST(ShadowCascades, SliceSphereIsTheSmallestThroughAllCorners) {
  const double tan_v = std::tan(22.5 * kRadPerDeg), tan_h = tan_v * kLens.aspect();
  const double k = tan_v * tan_v + tan_h * tan_h;
  // A deep slice: the centre lies between the planes, equidistant to near and far corners.
  const SliceSphere deep = frustum_slice_sphere(kLens, 10.0, 10'000.0);
  EXPECT_GT(deep.centre_depth_m, 10.0);
  EXPECT_LT(deep.centre_depth_m, 10'000.0);
  EXPECT_NEAR(std::hypot(deep.centre_depth_m - 10.0, 10.0 * std::sqrt(k)), deep.radius_m, 1e-6);
  EXPECT_NEAR(std::hypot(deep.centre_depth_m - 10'000.0, 10'000.0 * std::sqrt(k)), deep.radius_m, 1e-6);
  // A thin slice: the far corners' circle decides, centred on the far plane, and the near
  // corners are inside it.
  const SliceSphere thin = frustum_slice_sphere(kLens, 1'000.0, 1'200.0);
  EXPECT_DOUBLE_EQ(thin.centre_depth_m, 1'200.0);
  EXPECT_NEAR(thin.radius_m, 1'200.0 * std::sqrt(k), 1e-6);
  EXPECT_LT(std::hypot(200.0, 1'000.0 * std::sqrt(k)), thin.radius_m);
}

TEST(ShadowCascades, BiasGrowsWithTexelSize) {
  const ShadowCascades cascades(camera(45.0, -30.0), sun_direction());
  for (std::size_t i = 1; i < kShadowCascadeCount; ++i) {
    EXPECT_GT(cascades[i].texel_size_m, cascades[i - 1].texel_size_m);
    EXPECT_GT(cascades[i].constant_bias_m, cascades[i - 1].constant_bias_m);
    EXPECT_GT(cascades[i].slope_bias_m, cascades[i - 1].slope_bias_m);
    EXPECT_GT(cascades[i].normal_offset_m, cascades[i - 1].normal_offset_m);
  }
  // Half the map size: about twice the texel and the bias (the one-texel margin aside).
  ShadowCascadeSettings coarse;
  coarse.map_size_px = 1024;
  const ShadowCascades coarse_cascades(camera(45.0, -30.0), sun_direction(), coarse);
  for (std::size_t i = 0; i < kShadowCascadeCount; ++i) {
    const double ratio = (2048.0 - 2.0) / (1024.0 - 2.0);
    EXPECT_NEAR(coarse_cascades[i].texel_size_m, ratio * cascades[i].texel_size_m, 1e-9);
    EXPECT_NEAR(coarse_cascades[i].slope_bias_m, ratio * cascades[i].slope_bias_m, 1e-9);
    EXPECT_NEAR(coarse_cascades[i].texel_size_m, 2.0 * coarse_cascades[i].radius_m / 1024.0, 1e-9);
  }
}

TEST(ShadowCascades, CameraRelativeFloatMatrixAgreesWithTheDoubleProjection) {
  const scene::Camera cam = camera(300.0, -40.0);
  const ShadowCascades cascades(cam, sun_direction());
  const glm::dvec3 offset(1234.5, -2500.25, -800.0);  // a point near the camera, as a camera-relative offset
  for (std::size_t i = 0; i < kShadowCascadeCount; ++i) {
    const auto m = cascades.camera_relative_matrix(i);
    glm::mat4 matrix(1.0f);
    for (int column = 0; column < 4; ++column) {
      for (int row = 0; row < 4; ++row) matrix[column][row] = m[static_cast<std::size_t>(column * 4 + row)];
    }
    const glm::vec4 clip = matrix * glm::vec4(glm::vec3(offset), 1.0f);
    const glm::dvec3 expected = clip_of(cascades[i], cam.position() + offset);
    // Within a hundredth of a texel.
    const double texel_clip = 2.0 / cascades.settings().map_size_px;
    EXPECT_NEAR(clip.x, expected.x, 0.01 * texel_clip) << "cascade " << i;
    EXPECT_NEAR(clip.y, expected.y, 0.01 * texel_clip) << "cascade " << i;
    EXPECT_NEAR(clip.z, expected.z, 1e-5) << "cascade " << i;
  }
}

// may_hold agrees with the projection: a sphere whose centre projects inside the box is held,
// one entirely off to a side is not, one just touching an edge is.
TEST(ShadowCascades, MayHoldTheSpheresThatReachIntoTheLightBox) {
  const ShadowCascades cascades(camera(30.0, -20.0), sun_direction());
  const ShadowCascade& c = cascades[0];
  const glm::dvec3 sideways = glm::transpose(c.light_rotation) * glm::dvec3(1.0, 0.0, 0.0);  // light x in ECEF
  EXPECT_TRUE(c.may_hold(c.centre_ecef, 1.0));
  const glm::dvec3 outside = c.centre_ecef + sideways * (c.radius_m + 500.0);
  EXPECT_GT(std::abs(clip_of(c, outside).x), 1.0);
  EXPECT_FALSE(c.may_hold(outside, 400.0));
  EXPECT_TRUE(c.may_hold(outside, 600.0));
  // Beyond the far end of the light's depth range (away from the sun), and towards the sun
  // behind the light's eye: not held.
  const glm::dvec3 sun = glm::normalize(sun_direction());
  const glm::dvec3 below = c.eye_ecef - sun * (c.depth_extent_m + 300.0);
  EXPECT_GT(clip_of(c, below).z, 1.0);
  EXPECT_FALSE(c.may_hold(below, 200.0));
  EXPECT_TRUE(c.may_hold(below, 400.0));
  EXPECT_FALSE(c.may_hold(c.eye_ecef + sun * 300.0, 200.0));
  // The last cascade is larger: the first one's outside point is inside it.
  EXPECT_TRUE(cascades[3].may_hold(outside, 1.0));
}

TEST(ShadowCascades, BadInputIsRefusedByName) {
  const scene::Camera cam = camera(0.0, -30.0);
  auto message_of = [&](const glm::dvec3& sun, const ShadowCascadeSettings& settings) -> std::string {
    try {
      const ShadowCascades cascades(cam, sun, settings);
    } catch (const std::invalid_argument& error) {
      return error.what();
    }
    return "(accepted)";
  };
  EXPECT_EQ(message_of(glm::dvec3(0.0), {}), "shadow cascades: the sun direction (0, 0, 0) is not a direction");
  EXPECT_NE(message_of(glm::dvec3(NAN, 0.0, 1.0), {}).find("is not a direction"), std::string::npos);
  ShadowCascadeSettings bad;
  bad.map_size_px = 8;
  EXPECT_NE(message_of(sun_direction(), bad).find("map size 8 px is outside 16..16384"), std::string::npos);
  bad = {};
  bad.split_lambda = 1.5;
  EXPECT_NE(message_of(sun_direction(), bad).find("split lambda"), std::string::npos);
  bad = {};
  bad.caster_height_span_m = -1.0;
  EXPECT_NE(message_of(sun_direction(), bad).find("caster height span"), std::string::npos);
}

}  // namespace
}  // namespace trailray::render
