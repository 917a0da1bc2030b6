// The bench's reference techniques (render/reference/) draw what they claim, so the track
// benchmark compares the capsules with honest opponents: the ribbon is as wide on screen as
// asked, the tube as wide as its radius says (2 r f / d) and as radius_for_pixel_width promises,
// neither leaves a hole at a turn, and their GPU memory follows their documented layouts.
// Headless (llvmpipe in CI): a camera looking straight down on level polylines, the G-buffer's
// albedo read back (alpha 255 where a track was drawn, 0 where it was cleared).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "gl_test_support.hpp"
#include "scene/camera/camera.hpp"
#include "render/gl/framebuffer_readback.hpp"
#include "render/passes/gbuffer.hpp"
#include "render/passes/reference/reference_track.hpp"
#include "render/passes/reference/ribbon_pass.hpp"
#include "render/passes/reference/tube_pass.hpp"

namespace trailray::render {
namespace {

using reference::RibbonBuffer;
using reference::RibbonPass;
using reference::TubeBuffer;
using reference::TubePass;
using test::GlTest;

constexpr scene::GeoPosition kPlace{46.5, 10.0, 0.0};
constexpr double kCameraHeightM = 500.0;
const scene::Lens kLens{30.0, 320, 240};
const glm::vec3 kRed{1.0f, 0.0f, 0.0f};

double focal_length_px() { return 0.5 * kLens.height_px / std::tan(kLens.vertical_fov_deg * std::numbers::pi / 360.0); }

// Level points (metres east and north of kPlace, on the ellipsoid) as one segment.
scene::TrackGeometry level_path(const std::vector<glm::dvec2>& east_north) {
  const scene::EnuAxes axes = scene::enu_axes_at(kPlace.lat_deg, kPlace.lon_deg);
  const glm::dvec3 origin = scene::ecef_from(kPlace);
  scene::TrackPolyline line;
  for (const glm::dvec2& p : east_north) line.points_ecef.push_back(origin + p.x * axes.east + p.y * axes.north);
  scene::TrackGeometry g;
  g.segments.push_back(std::move(line));
  return g;
}

// A straight line from 150 m west to 150 m east, a point every 50 m: across most of the picture
// (which is 357 m wide at the ground), ending about 26 pixels from either side.
scene::TrackGeometry west_to_east() {
  std::vector<glm::dvec2> points;
  for (int e = -150; e <= 150; e += 50) points.push_back({e, 0.0});
  return level_path(points);
}

class ReferencePassesTest : public GlTest {
 protected:
  ReferencePassesTest()
      : camera(scene::ecef_from({kPlace.lat_deg, kPlace.lon_deg, kCameraHeightM}), 0.0, -90.0, kLens, scene::DepthRange{1.0, 1.0e4}),
        gbuffer(static_cast<int>(kLens.width_px), static_cast<int>(kLens.height_px), DistanceEncoding::packed_rgba8) {}

  // The albedo after `draw` into a cleared G-buffer, rows top-down.
  template <class Draw>
  scene::RgbaImage albedo_after(Draw draw) {
    gbuffer.bind_and_clear();
    draw();
    return read_rgba8(0, 0, gbuffer.width(), gbuffer.height());
  }

  static bool drawn(const scene::RgbaImage& image, std::uint32_t x, std::uint32_t y) { return image.pixel(x, y)[3] > 127; }
  static int column_count(const scene::RgbaImage& image, std::uint32_t x) {
    int n = 0;
    for (std::uint32_t y = 0; y < image.height; ++y) n += drawn(image, x, y) ? 1 : 0;
    return n;
  }
  // Every pixel on the projected centre line of `east_north` (every 1/100 of an edge) is drawn;
  // the two open ends of the path are left out (neither technique caps them).
  void expect_no_holes(const scene::RgbaImage& image, const std::vector<glm::dvec2>& east_north, const char* what) {
    const scene::EnuAxes axes = scene::enu_axes_at(kPlace.lat_deg, kPlace.lon_deg);
    const glm::dvec3 origin = scene::ecef_from(kPlace);
    int holes = 0;
    std::string first_hole;
    for (std::size_t i = 0; i + 1 < east_north.size(); ++i)
      for (int k = 0; k <= 100; ++k) {
        if ((i == 0 && k == 0) || (i + 2 == east_north.size() && k == 100)) continue;
        const glm::dvec2 p = glm::mix(east_north[i], east_north[i + 1], k / 100.0);
        const auto pixel = camera.project(origin + p.x * axes.east + p.y * axes.north);
        ASSERT_TRUE(pixel && pixel->x_px >= 0.0 && pixel->y_px >= 0.0 && pixel->x_px < kLens.width_px &&
                    pixel->y_px < kLens.height_px)
            << what << ": the path leaves the picture";
        if (drawn(image, static_cast<std::uint32_t>(pixel->x_px), static_cast<std::uint32_t>(pixel->y_px))) continue;
        if (holes++ == 0) first_hole = "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ") m";
      }
    EXPECT_EQ(holes, 0) << what << ": the first at " << first_hole;
  }

  scene::Camera camera;
  GBuffer gbuffer;
};

TEST_F(ReferencePassesTest, TheRibbonIsAsWideOnScreenAsAsked) {
  const RibbonPass pass;
  const RibbonBuffer ribbon(west_to_east());
  for (const double width_px : {3.0, 6.0, 11.0}) {
    const scene::RgbaImage image = albedo_after([&] { pass.draw(gbuffer, camera, ribbon, kRed, width_px); });
    for (const std::uint32_t x : {60u, 160u, 260u}) EXPECT_NEAR(column_count(image, x), width_px, 1.0) << "column " << x;
    EXPECT_EQ(column_count(image, 2), 0) << "the line ends inside the picture";
  }
}

TEST_F(ReferencePassesTest, TheTubeIsTwoRadiiWideAtItsDistance) {
  const TubePass pass;
  const double radius_m = 5.0;
  const TubeBuffer tube(west_to_east(), radius_m);
  const scene::RgbaImage image = albedo_after([&] { pass.draw(gbuffer, camera, tube, kRed); });
  // An octagon's width across varies between its inner and outer diameters (cos 22.5 deg).
  const double expected_px = 2.0 * radius_m * focal_length_px() / kCameraHeightM;
  for (const std::uint32_t x : {60u, 160u, 260u})
    EXPECT_NEAR(column_count(image, x), expected_px, 1.5) << "column " << x << ", expected " << expected_px;
}

TEST_F(ReferencePassesTest, RadiusForPixelWidthMatchesTheRibbon) {
  const double width_px = 9.0;
  const double radius_m = reference::radius_for_pixel_width(camera, kCameraHeightM, width_px);
  EXPECT_NEAR(2.0 * radius_m * focal_length_px() / kCameraHeightM, width_px, 1e-9);
  const TubePass tube_pass;
  const RibbonPass ribbon_pass;
  const TubeBuffer tube(west_to_east(), radius_m);
  const RibbonBuffer ribbon(west_to_east());
  const scene::RgbaImage tube_image = albedo_after([&] { tube_pass.draw(gbuffer, camera, tube, kRed); });
  const scene::RgbaImage ribbon_image = albedo_after([&] { ribbon_pass.draw(gbuffer, camera, ribbon, kRed, width_px); });
  EXPECT_NEAR(column_count(tube_image, 160), column_count(ribbon_image, 160), 1.5);
}

TEST_F(ReferencePassesTest, NeitherLeavesAHoleAtTurns) {
  // East, a right angle to the north, then a 150 degree turn to the right (heading 150).
  const std::vector<glm::dvec2> path{{-150, -80}, {0, -80}, {0, 80}, {60, 80 - 120 * std::sqrt(0.75)}};
  const TubePass tube_pass;
  const TubeBuffer tube(level_path(path), 4.0);
  expect_no_holes(albedo_after([&] { tube_pass.draw(gbuffer, camera, tube, kRed); }), path, "tube");
  // The ribbon's rough miter pinches sharp turns (by cos of half the turn): the right angle only.
  const std::vector<glm::dvec2> right_angle(path.begin(), path.begin() + 3);
  const RibbonPass ribbon_pass;
  const RibbonBuffer ribbon(level_path(right_angle));
  expect_no_holes(albedo_after([&] { ribbon_pass.draw(gbuffer, camera, ribbon, kRed, 6.0); }), right_angle, "ribbon");
}

TEST_F(ReferencePassesTest, GpuMemoryFollowsTheLayouts) {
  scene::TrackGeometry geometry = west_to_east();                        // 7 points
  geometry.segments.push_back(level_path({{0, 50}}).segments[0]);  // a lone point
  const RibbonBuffer ribbon(geometry);
  EXPECT_EQ(ribbon.point_count(), 8u);
  EXPECT_EQ(ribbon.gpu_bytes(), 7u * 2u * 28u) << "2 vertices of 28 bytes per point; a lone point has no strip";
  ASSERT_EQ(ribbon.strips().size(), 1u);
  EXPECT_EQ(ribbon.strips()[0].count, 14);
  const TubeBuffer tube(geometry, 2.0);
  EXPECT_EQ(tube.point_count(), 8u);
  EXPECT_EQ(tube.gpu_bytes(), 8u * 8u * 24u + 6u * 48u * 4u) << "a ring per point, 16 triangles per segment";
  EXPECT_EQ(tube.index_count(), 6 * 48);
}

TEST_F(ReferencePassesTest, TheTubeRefusesARadiusThatIsNotPositive) {
  EXPECT_THROW(TubeBuffer(west_to_east(), 0.0), std::invalid_argument);
  EXPECT_THROW(TubeBuffer(west_to_east(), std::nan("")), std::invalid_argument);
}

TEST_F(ReferencePassesTest, EmptyGeometryDrawsNothing) {
  const scene::TrackGeometry empty;
  const RibbonBuffer ribbon(empty);
  const TubeBuffer tube(empty, 1.0);
  EXPECT_EQ(ribbon.gpu_bytes(), 0u);
  EXPECT_EQ(tube.gpu_bytes(), 0u);
  const RibbonPass ribbon_pass;
  const TubePass tube_pass;
  const scene::RgbaImage image = albedo_after([&] {
    ribbon_pass.draw(gbuffer, camera, ribbon, kRed, 5.0);
    tube_pass.draw(gbuffer, camera, tube, kRed);
  });
  int drawn_pixels = 0;
  for (std::uint32_t y = 0; y < image.height; ++y)
    for (std::uint32_t x = 0; x < image.width; ++x) drawn_pixels += drawn(image, x, y) ? 1 : 0;
  EXPECT_EQ(drawn_pixels, 0);
}

}  // namespace
}  // namespace trailray::render
