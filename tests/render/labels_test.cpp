// The labels pass in the picture: a waypoint's name appears just above its projected point and
// nowhere else, two labels whose points nearly coincide never share a pixel, a label whose point
// lies behind a ridge is ghosted (or hidden), and the pixel ratio scales the text.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "gl_test_support.hpp"
#include "render/renderer.hpp"
#include "scene/text/label_raster.hpp"
#include "scene_test_support.hpp"
#include "track_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;
using test::LocalFrame;

constexpr scene::GeoPosition kPlace{46.5, 10.0, 0.0};

scene::Waypoint waypoint(std::string name, const glm::dvec3& marker) {
  scene::Waypoint w;
  w.name = std::move(name);
  w.marker_ecef = marker;
  w.ground_ecef = marker;
  return w;
}

// How much a pixel changed between two pictures (the largest channel difference).
int change(const scene::RgbaImage& a, const scene::RgbaImage& b, int x, int y) {
  const auto p = a.pixel(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
  const auto q = b.pixel(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
  int most = 0;
  for (int c = 0; c < 3; ++c) most = std::max(most, std::abs(p[c] - q[c]));
  return most;
}

// The bounding box of the pixels that changed by more than `threshold`; empty when none did.
scene::PixelRect changed_box(const scene::RgbaImage& a, const scene::RgbaImage& b, int threshold = 8) {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
  for (int y = 0; y < static_cast<int>(a.height); ++y)
    for (int x = 0; x < static_cast<int>(a.width); ++x)
      if (change(a, b, x, y) > threshold) {
        x0 = std::min(x0, x);
        y0 = std::min(y0, y);
        x1 = std::max(x1, x);
        y1 = std::max(y1, y);
      }
  if (x1 < 0) return {};
  return {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

// Near-white pixels (the waypoints' text colour) within a rectangle.
int white_pixels(const scene::RgbaImage& image, const scene::PixelRect& r) {
  int n = 0;
  for (int y = std::max(r.y, 0); y < std::min(r.bottom(), static_cast<int>(image.height)); ++y)
    for (int x = std::max(r.x, 0); x < std::min(r.right(), static_cast<int>(image.width)); ++x) {
      const auto p = image.pixel(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
      if (p[0] > 200 && p[1] > 200 && p[2] > 200) ++n;
    }
  return n;
}

// The summed change of the pixels in a rectangle.
long total_change(const scene::RgbaImage& a, const scene::RgbaImage& b, const scene::PixelRect& r) {
  long sum = 0;
  for (int y = r.y; y < r.bottom(); ++y)
    for (int x = r.x; x < r.right(); ++x) sum += change(a, b, x, y);
  return sum;
}

class LabelsTest : public GlTest {
 protected:
  LocalFrame frame_{kPlace};
  const scene::Lens lens_{45.0, 320, 240};
  scene::Camera camera_ = test::looking_down({kPlace.lat_deg, kPlace.lon_deg, 1000.0}, lens_, 10.0);

  scene::Scene scene_with(const scene::WaypointSet& points) const {
    scene::Scene s = test::plain_scene(kPlace, 0.0);
    s.waypoints = &points;
    return s;
  }
};

TEST_F(LabelsTest, AWaypointsNameAppearsJustAboveItsProjectedPoint) {
  test::SceneDrawer drawer(nullptr, nullptr);
  scene::WaypointSet points;
  points.points = {waypoint("Rifugio", frame_.point(60, 40, 0))};
  scene::Scene scene = scene_with(points);
  const test::Drawn labelled = drawer.draw(camera_, scene);
  scene.style.labels.enabled = false;
  const test::Drawn plain = drawer.draw(camera_, scene);
  test::keep_image(labelled.image, "label_waypoint.png");
  EXPECT_EQ(labelled.report.labels_drawn, 1u);
  EXPECT_EQ(plain.report.labels_drawn, 0u);

  const auto anchor = camera_.project(frame_.point(60, 40, 0));
  ASSERT_TRUE(anchor);
  const scene::PixelRect drawn = changed_box(labelled.image, plain.image);
  ASSERT_FALSE(drawn.empty()) << "no label drawn";
  // Centred over the point, its bottom just above the pin's ball there (at 1000 m the pin's
  // pixel clearance decides), about a line of text tall.
  const double pin_top = anchor->y_px - scene::pin_clearance(scene::WaypointKind::Waypoint, scene::PinStyle{}).px;
  EXPECT_NEAR(drawn.x + drawn.width / 2.0, anchor->x_px, 3.0);
  EXPECT_LE(drawn.bottom(), pin_top);
  EXPECT_GE(drawn.bottom(), pin_top - 2 * scene::label_lift_px(13) - 2);
  EXPECT_GT(drawn.width, 30);
  EXPECT_LT(drawn.width, 90);
  EXPECT_GT(drawn.height, 10);
  EXPECT_LT(drawn.height, 24);
  EXPECT_GT(white_pixels(labelled.image, drawn), 25);
  EXPECT_EQ(white_pixels(plain.image, drawn), 0);
}

TEST_F(LabelsTest, TwoLabelsWithNearlyTheSamePointNeverShareAPixel) {
  test::SceneDrawer drawer(nullptr, nullptr);
  scene::WaypointSet points;
  points.points = {waypoint("Alpha hut", frame_.point(0, 0, 0)), waypoint("Beta hut", frame_.point(4, 2, 0))};
  scene::Scene scene = scene_with(points);
  const std::vector<scene::PlacedLabel> layout = drawer.renderer().layout_labels(scene, camera_, 1.0);
  ASSERT_EQ(layout.size(), 2u);
  EXPECT_FALSE(layout[0].box.intersects(layout[1].box));
  const test::Drawn both = drawer.draw(camera_, scene);
  test::keep_image(both.image, "label_pair.png");
  scene.style.labels.enabled = false;
  const test::Drawn plain = drawer.draw(camera_, scene);
  // Every changed pixel lies in exactly one label's box, and each box has its text.
  int outside = 0;
  for (int y = 0; y < static_cast<int>(lens_.height_px); ++y)
    for (int x = 0; x < static_cast<int>(lens_.width_px); ++x)
      if (change(both.image, plain.image, x, y) > 8 && !layout[0].box.contains(x, y) && !layout[1].box.contains(x, y))
        ++outside;
  EXPECT_EQ(outside, 0);
  EXPECT_GT(white_pixels(both.image, layout[0].box), 25);
  EXPECT_GT(white_pixels(both.image, layout[1].box), 25);
}

// A north-south ridge (valleys at 1000 m, crest 1800 m at kPlace's meridian, 2 km slopes).
struct RidgeSource : test::EastProfileSource {
  RidgeSource()
      : EastProfileSource("ridge", kPlace.lat_deg, kPlace.lon_deg, [](double east_m) {
          return 1000.0 + 800.0 * std::max(0.0, 1.0 - std::abs(east_m) / 2000.0);
        }) {}
};

TEST_F(LabelsTest, ALabelWhosePointIsBehindARidgeIsGhostedOrHidden) {
  RidgeSource ridge;
  test::SceneDrawer drawer(&ridge, nullptr);
  const double deg_per_m = 1.0 / (111320.0 * std::cos(kPlace.lat_deg * M_PI / 180.0));
  const auto camera =
      scene::camera_at({{kPlace.lat_deg, kPlace.lon_deg - 6000.0 * deg_per_m, 1300.0}, 90.0, 0.0}, lens_, 1000.0);
  ASSERT_TRUE(camera.ok()) << camera.error;
  // One line of sight from the camera: a point above the near valley, and one on the far valley's
  // floor, which the ridge hides. Both labels take the same box.
  const glm::dvec3 from = camera.value->position();
  const glm::dvec3 behind = scene::ecef_from({kPlace.lat_deg, kPlace.lon_deg + 4000.0 * deg_per_m, 1000.0});
  const glm::dvec3 in_front = from + 0.15 * (behind - from);
  // Either distance encoding of the G-buffer.
  for (const DistanceEncoding encoding : {DistanceEncoding::float32, DistanceEncoding::packed_rgba8}) {
    SCOPED_TRACE(encoding == DistanceEncoding::float32 ? "float distances" : "packed distances");
    drawer.renderer().set_distance_encoding(encoding);
    scene::WaypointSet points;
    scene::Scene scene = scene_with(points);
    scene.neutral_ground_m = 1000.0;
    scene.style.labels.enabled = false;
    const scene::RgbaImage plain = drawer.draw(*camera.value, scene).image;
    scene.style.labels.enabled = true;

    points.points = {waypoint("Malga", in_front)};
    const std::vector<scene::PlacedLabel> layout = drawer.renderer().layout_labels(scene, *camera.value, 1.0);
    ASSERT_EQ(layout.size(), 1u);
    const scene::RgbaImage seen = drawer.draw(*camera.value, scene).image;
    points.points = {waypoint("Malga", behind)};
    ASSERT_EQ(drawer.renderer().layout_labels(scene, *camera.value, 1.0).at(0).box.x, layout[0].box.x);
    const scene::RgbaImage ghost = drawer.draw(*camera.value, scene).image;
    scene.style.labels.hide_occluded = true;
    const scene::RgbaImage hidden = drawer.draw(*camera.value, scene).image;
    test::keep_image(seen, "label_seen.png");
    test::keep_image(ghost, "label_ghost.png");

    const long seen_change = total_change(seen, plain, layout[0].box);
    const long ghost_change = total_change(ghost, plain, layout[0].box);
    EXPECT_GT(seen_change, 0);
    EXPECT_GT(ghost_change, 0) << "a ghost is still drawn";
    EXPECT_LT(ghost_change, seen_change / 2) << "the ghost is fainter";
    EXPECT_EQ(white_pixels(ghost, layout[0].box), 0);
    EXPECT_EQ(hidden.rgba, plain.rgba) << "--hidden-labels hide draws nothing";
  }
}

TEST_F(LabelsTest, EveryLabelOfACrowdIsDrawnAsItWasRasterized) {
  // Enough labels to fill more than one row of the atlas (texels past 1024, where a 16-bit float
  // could not address single texels any more).
  test::SceneDrawer drawer(nullptr, nullptr);
  const scene::Lens lens{45.0, 1024, 768};
  const scene::Camera camera = test::looking_down({kPlace.lat_deg, kPlace.lon_deg, 1000.0}, lens, 10.0);
  scene::WaypointSet points;
  for (int i = 0; i < 80; ++i)
    points.points.push_back(waypoint("Waypoint number " + std::to_string(i),
                                     frame_.point((i % 8) * 90.0 - 315.0, (i / 8) * 60.0 - 270.0, 0)));
  scene::Scene scene = scene_with(points);
  const std::vector<scene::PlacedLabel> layout = drawer.renderer().layout_labels(scene, camera, 1.0);
  int widths = 0;
  for (const scene::PlacedLabel& label : layout) widths += label.box.width;
  ASSERT_GT(widths, 2048) << "the atlas' first row is not full";
  const scene::RgbaImage picture = drawer.draw(camera, scene).image;
  test::keep_image(picture, "label_crowd.png");
  scene::LabelLayouter raster;
  for (const scene::PlacedLabel& label : layout) {
    const scene::LabelBitmap bitmap = scene::rasterize_label(raster.text(), label);
    int full = 0, full_white = 0;
    for (int y = 0; y < bitmap.height; ++y)
      for (int x = 0; x < bitmap.width; ++x) {
        const auto p =
            picture.pixel(static_cast<std::uint32_t>(label.box.x + x), static_cast<std::uint32_t>(label.box.y + y));
        const bool white = p[0] > 200 && p[1] > 200 && p[2] > 200;
        if (bitmap.text(x, y) == 255) {
          ++full;
          if (white) ++full_white;
        } else if (bitmap.text(x, y) == 0) {
          EXPECT_FALSE(white) << label.text << " has text where its raster has none, at " << x << "," << y;
        }
      }
    EXPECT_GT(full, 20) << label.text;
    EXPECT_EQ(full_white, full) << label.text;
  }
}

TEST_F(LabelsTest, ThePixelRatioDrawsLargerText) {
  test::SceneDrawer drawer(nullptr, nullptr);
  scene::WaypointSet points;
  points.points = {waypoint("Rifugio", frame_.point(0, 0, 0))};
  scene::Scene scene = scene_with(points);
  ImageTarget normal, doubled;
  doubled.pixel_ratio = 2.0;
  scene.terrain = &drawer.terrain();
  drawer.renderer().draw(scene, camera_, normal);
  drawer.renderer().draw(scene, camera_, doubled);
  // The same without the label, at each ratio (the pin is drawn larger too).
  scene.style.labels.enabled = false;
  ImageTarget plain, plain_doubled;
  plain_doubled.pixel_ratio = 2.0;
  drawer.renderer().draw(scene, camera_, plain);
  drawer.renderer().draw(scene, camera_, plain_doubled);
  const scene::PixelRect one = changed_box(normal.image, plain.image),
                         two = changed_box(doubled.image, plain_doubled.image);
  ASSERT_FALSE(one.empty());
  ASSERT_FALSE(two.empty());
  EXPECT_NEAR(two.height, 2.0 * one.height, 0.2 * one.height);
  EXPECT_NEAR(two.width, 2.0 * one.width, 0.2 * one.width);
}

}  // namespace
}  // namespace trailray::render
