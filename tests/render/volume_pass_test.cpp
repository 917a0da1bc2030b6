// The volumes pass: an airspace in front of the camera tints the pixels inside its projection
// and nowhere else, its ceiling's outline is stronger than its wall, the terrain in front of it
// (a ridge) hides it completely, and its buffers are made once per revision of the set.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "gl_test_support.hpp"
#include "render/renderer.hpp"
#include "render/volume_gpu.hpp"
#include "scene_test_support.hpp"
#include "track_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;

constexpr scene::GeoPosition kPlace{46.5, 10.0, 0.0};
const scene::Lens kLens{40.0, 160, 120};
const double kDegPerMetreLon = 1.0 / (111320.0 * std::cos(kPlace.lat_deg * M_PI / 180.0));
constexpr double kDegPerMetreLat = 1.0 / 111320.0;

geo::LatLon at(double east_m, double north_m) {
  return {kPlace.lat_deg + north_m * kDegPerMetreLat, kPlace.lon_deg + east_m * kDegPerMetreLon};
}
glm::dvec3 point(double east_m, double north_m, double height_m) {
  const geo::LatLon p = at(east_m, north_m);
  return scene::ecef_from({p.lat, p.lon, height_m});
}

// A pure blue box from (west, south) `side_m` wide, between two heights above MSL.
scene::Volume box(double west_m, double south_m, double side_m, double floor_m, double ceiling_m) {
  scene::Volume v;
  v.name = "box";
  v.boundary = {at(west_m, south_m), at(west_m + side_m, south_m), at(west_m + side_m, south_m + side_m),
                at(west_m, south_m + side_m)};
  v.floor = {scene::VolumeHeightReference::Msl, floor_m, false};
  v.ceiling = {scene::VolumeHeightReference::Msl, ceiling_m, false};
  v.color_srgb = {0.0f, 0.0f, 1.0f};
  v.opacity = 0.15f;  // faint, so the outlines stand out
  return v;
}

// How much bluer a pixel is with the volumes than without.
int blue_gain(const scene::RgbaImage& with, const scene::RgbaImage& without, double x, double y) {
  const auto ix = static_cast<std::uint32_t>(std::lround(x)), iy = static_cast<std::uint32_t>(std::lround(y));
  const auto a = with.pixel(ix, iy), b = without.pixel(ix, iy);
  return (int(a[2]) - int(a[0])) - (int(b[2]) - int(b[0]));
}

int changed_pixels(const scene::RgbaImage& a, const scene::RgbaImage& b) {
  int n = 0;
  for (std::uint32_t y = 0; y < a.height; ++y)
    for (std::uint32_t x = 0; x < a.width; ++x) n += a.pixel(x, y) != b.pixel(x, y);
  return n;
}

class VolumePassTest : public GlTest {};

TEST_F(VolumePassTest, AVolumeInFrontTintsItsProjectionAndNothingElse) {
  test::SceneDrawer drawer(nullptr, nullptr);
  // Looking east from 400 m at a box 2 km away, 1 km wide, from 200 m to 700 m.
  const auto camera = scene::camera_at({{at(0, 0).lat, at(0, 0).lon, 400.0}, 90.0, 0.0}, kLens, 0.0);
  ASSERT_TRUE(camera.ok()) << camera.error;
  scene::VolumeSet set;
  set.volumes = {box(2000.0, -500.0, 1000.0, 200.0, 700.0)};
  for (const DistanceEncoding encoding : {DistanceEncoding::float32, DistanceEncoding::packed_rgba8}) {
    SCOPED_TRACE(encoding == DistanceEncoding::float32 ? "float distances" : "packed distances");
    drawer.renderer().set_distance_encoding(encoding);
    scene::Scene scene = test::plain_scene(kPlace, 0.0);
    scene.style.labels.enabled = false;  // the box's name is the labels' business
    const scene::RgbaImage without = drawer.draw(*camera.value, scene).image;
    scene.volumes = &set;
    const test::Drawn with = drawer.draw(*camera.value, scene);
    test::keep_image(with.image, "volume_in_front.png");
    EXPECT_EQ(with.report.volumes_drawn, 1u);

    const auto project = [&](double e, double n, double h) { return camera.value->project(point(e, n, h)); };
    const auto inside = project(2000.0, 0.0, 450.0);
    const auto above = project(2000.0, 0.0, 1000.0);
    const auto beside = project(2000.0, 900.0, 450.0);
    const auto ceiling = project(2000.0, 250.0, 700.0);
    ASSERT_TRUE(inside && above && beside && ceiling);
    EXPECT_GT(blue_gain(with.image, without, inside->x_px, inside->y_px), 10) << "inside the wall";
    EXPECT_EQ(blue_gain(with.image, without, above->x_px, above->y_px), 0) << "above the ceiling";
    EXPECT_EQ(blue_gain(with.image, without, beside->x_px, beside->y_px), 0) << "beside it";
    // The ceiling's outline is drawn stronger than the wall under it.
    EXPECT_GT(blue_gain(with.image, without, ceiling->x_px, ceiling->y_px),
              blue_gain(with.image, without, inside->x_px, inside->y_px) + 20);
    // Everything that changed lies within the box's projection (a pixel of margin for the outline).
    double left = 1e9, right = -1e9, top = 1e9, bottom = -1e9;
    for (double e : {2000.0, 3000.0})
      for (double n : {-500.0, 500.0})
        for (double h : {200.0, 700.0}) {
          const auto p = project(e, n, h);
          ASSERT_TRUE(p);
          left = std::min(left, p->x_px), right = std::max(right, p->x_px);
          top = std::min(top, p->y_px), bottom = std::max(bottom, p->y_px);
        }
    for (std::uint32_t y = 0; y < without.height; ++y)
      for (std::uint32_t x = 0; x < without.width; ++x)
        if (with.image.pixel(x, y) != without.pixel(x, y)) {
          EXPECT_GE(x + 2.5, left);
          EXPECT_LE(x - 2.5, right);
          EXPECT_GE(y + 2.5, top);
          EXPECT_LE(y - 2.5, bottom);
        }
  }
}

// A north-south ridge (valleys at 1000 m, crest 1800 m at kPlace's meridian, 2 km slopes).
struct RidgeSource : test::EastProfileSource {
  RidgeSource()
      : EastProfileSource("ridge", kPlace.lat_deg, kPlace.lon_deg, [](double east_m) {
          return 1000.0 + 800.0 * std::max(0.0, 1.0 - std::abs(east_m) / 2000.0);
        }) {}
};

TEST_F(VolumePassTest, ARidgeInFrontHidesAVolumeCompletely) {
  RidgeSource ridge;
  test::SceneDrawer drawer(&ridge, nullptr);
  // From 6 km west of the crest at 1300 m, looking east: the line over the crest is at 2050 m
  // 3 km behind it, so a box up to 1500 m there is hidden; the same box in the near valley is not.
  const auto camera = scene::camera_at({{at(-6000, 0).lat, at(-6000, 0).lon, 1300.0}, 90.0, 0.0}, kLens, 1000.0);
  ASSERT_TRUE(camera.ok()) << camera.error;
  scene::Scene scene = test::plain_scene(kPlace, 1000.0);
  scene.style.labels.enabled = false;
  const scene::RgbaImage without = drawer.draw(*camera.value, scene).image;
  scene::VolumeSet behind;
  behind.volumes = {box(3000.0, -500.0, 1000.0, 1100.0, 1500.0)};
  scene.volumes = &behind;
  const scene::RgbaImage hidden = drawer.draw(*camera.value, scene).image;
  EXPECT_EQ(changed_pixels(hidden, without), 0) << "nothing of a volume behind the ridge shows";

  scene::VolumeSet in_front;
  in_front.volumes = {box(-3500.0, -500.0, 1000.0, 1100.0, 1500.0)};
  scene.volumes = &in_front;
  const scene::RgbaImage seen = drawer.draw(*camera.value, scene).image;
  test::keep_image(seen, "volume_before_ridge.png");
  const auto wall = camera.value->project(point(-3500.0, 0.0, 1300.0));
  ASSERT_TRUE(wall);
  EXPECT_GT(blue_gain(seen, without, wall->x_px, wall->y_px), 20);
  EXPECT_GT(changed_pixels(seen, without), 100);
}

TEST_F(VolumePassTest, BuffersAreMadeOncePerRevisionAndHiddenVolumesLeftOut) {
  scene::VolumeSet set;
  set.volumes = {box(0.0, 0.0, 1000.0, 100.0, 500.0), box(5000.0, 0.0, 1000.0, 100.0, 500.0)};
  set.volumes[1].floor = {scene::VolumeHeightReference::Ground, 0.0, false};  // no floor outline
  const VolumeMesh mesh = volume_mesh(scene::volume_shapes(set, 0.0));
  EXPECT_EQ(mesh.walls.size(), 2u * 4u * 6u);
  EXPECT_EQ(mesh.outlines.size(), (4u + 4u + 4u) * 6u);  // both ceilings, one floor
  VolumeGpu gpu;
  const VolumeDraw* first = gpu.draw(&set, 0.0);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->wall_vertices, 48);
  EXPECT_EQ(gpu.draw(&set, 0.0)->wall_buffer.id(), first->wall_buffer.id());
  set.volumes[0].visible = false;
  ++set.revision;
  EXPECT_EQ(gpu.draw(&set, 0.0)->wall_vertices, 24);
  set.volumes[1].visible = false;
  ++set.revision;
  EXPECT_EQ(gpu.draw(&set, 0.0), nullptr);
  EXPECT_EQ(gpu.draw(nullptr, 0.0), nullptr);
}

}  // namespace
}  // namespace trailray::render
