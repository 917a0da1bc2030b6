// Photos' pins in the picture: a photo's thumbnail is drawn framed just above its pin, in the
// photo's colours and nowhere else; a waypoint's name never sits on it; a photo whose point lies
// behind a ridge is ghosted, or not drawn at all with hide_occluded.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gl_test_support.hpp"
#include "render/renderer.hpp"
#include "scene/text/label_raster.hpp"
#include "scene/pins/photo_pins.hpp"
#include "scene_test_support.hpp"
#include "track_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;
using test::LocalFrame;

constexpr scene::GeoPosition kPlace{46.5, 10.0, 0.0};

// A photo of one colour, 4:3.
std::shared_ptr<const scene::PhotoImage> flat_photo(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  scene::RgbaImage image{128, 96, {}};
  for (std::size_t i = 0; i < std::size_t{128} * 96; ++i)
    for (std::uint8_t c : {r, g, b, std::uint8_t{255}}) image.rgba.push_back(c);
  return scene::make_photo_image(std::move(image));
}

scene::Waypoint photo_pin(const glm::dvec3& marker, std::shared_ptr<const scene::PhotoImage> thumbnail) {
  scene::Waypoint w;
  w.name = "DSCN0001.jpg";
  w.kind = scene::WaypointKind::Photo;
  w.priority = scene::kPhotoPriority;
  w.marker_ecef = marker;
  w.ground_ecef = marker;
  w.thumbnail = std::move(thumbnail);
  return w;
}

bool reddish(const std::array<std::uint8_t, 4>& p) { return p[0] > 200 && p[1] < 60 && p[2] < 60; }

int count_in(const scene::RgbaImage& image, const scene::PixelRect& r, bool (*test)(const std::array<std::uint8_t, 4>&)) {
  int n = 0;
  for (int y = std::max(r.y, 0); y < std::min(r.bottom(), static_cast<int>(image.height)); ++y)
    for (int x = std::max(r.x, 0); x < std::min(r.right(), static_cast<int>(image.width)); ++x)
      n += test(image.pixel(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)));
  return n;
}

class PhotoPinsTest : public GlTest {
 protected:
  LocalFrame frame_{kPlace};
  const scene::Lens lens_{45.0, 400, 300};
  scene::Camera camera_ = test::looking_down({kPlace.lat_deg, kPlace.lon_deg, 1000.0}, lens_, 10.0);

  scene::Scene scene_with(const scene::WaypointSet& points) const {
    scene::Scene s = test::plain_scene(kPlace, 0.0);
    s.waypoints = &points;
    return s;
  }
};

TEST_F(PhotoPinsTest, APhotosThumbnailIsDrawnFramedAboveItsPinInItsColours) {
  test::SceneDrawer drawer(nullptr, nullptr);
  scene::WaypointSet points;
  points.points = {photo_pin(frame_.point(30, -20, 0), flat_photo(255, 0, 0))};
  scene::Scene scene = scene_with(points);
  scene.style.labels.enabled = false;  // --no-labels takes names away, not photos
  const std::vector<scene::PlacedLabel> layout = drawer.renderer().layout_labels(scene, camera_, 1.0);
  ASSERT_EQ(layout.size(), 1u);
  const scene::PixelRect box = layout[0].box;
  const test::Drawn drawn = drawer.draw(camera_, scene);
  test::keep_image(drawn.image, "photo_pin.png");
  scene::WaypointSet none;
  const test::Drawn plain = drawer.draw(camera_, scene_with(none));

  // The 72 px thumbnail (4:3) in a frame of 2 px, centred over the point, above the pin's ball.
  const auto anchor = camera_.project(frame_.point(30, -20, 0));
  ASSERT_TRUE(anchor);
  EXPECT_EQ(box.width, 72 + 2 * 2);
  EXPECT_EQ(box.height, 54 + 2 * 2);
  EXPECT_NEAR(box.x + box.width / 2.0, anchor->x_px, 2.0);
  EXPECT_LE(box.bottom(), anchor->y_px - scene::pin_clearance(scene::WaypointKind::Photo, scene::PinStyle{}).px);
  // Inside the frame: the photo's red, every pixel; the frame itself pale; nothing red elsewhere.
  const scene::PixelRect inner{box.x + 2, box.y + 2, box.width - 4, box.height - 4};
  EXPECT_EQ(count_in(drawn.image, inner, reddish), inner.width * inner.height);
  const auto frame_pixel = drawn.image.pixel(static_cast<std::uint32_t>(box.x), static_cast<std::uint32_t>(box.y + box.height / 2));
  EXPECT_GT(frame_pixel[1], 230);
  EXPECT_EQ(count_in(drawn.image, {0, 0, 400, 300}, reddish), inner.width * inner.height);
  EXPECT_EQ(count_in(plain.image, inner, reddish), 0);
  EXPECT_EQ(drawn.report.labels_drawn, 1u);
}

TEST_F(PhotoPinsTest, AWaypointsNameNeverSitsOnAThumbnail) {
  test::SceneDrawer drawer(nullptr, nullptr);
  scene::WaypointSet points;
  scene::Waypoint hut;
  hut.name = "Rifugio";
  hut.marker_ecef = hut.ground_ecef = frame_.point(2, 0, 0);
  // The hut first in the list: the photo still wins the place above the pair.
  points.points = {hut, photo_pin(frame_.point(0, 0, 0), flat_photo(255, 0, 0))};
  const std::vector<scene::PlacedLabel> layout = drawer.renderer().layout_labels(scene_with(points), camera_, 1.0);
  ASSERT_GE(layout.size(), 1u);
  EXPECT_NE(layout[0].image, nullptr) << "the photo is placed first";
  for (std::size_t i = 1; i < layout.size(); ++i) EXPECT_FALSE(layout[i].box.intersects(layout[0].box));
}

// A north-south ridge (valleys at 1000 m, crest 1800 m at kPlace's meridian, 2 km slopes).
struct RidgeSource : test::EastProfileSource {
  RidgeSource()
      : EastProfileSource("ridge", kPlace.lat_deg, kPlace.lon_deg, [](double east_m) {
          return 1000.0 + 800.0 * std::max(0.0, 1.0 - std::abs(east_m) / 2000.0);
        }) {}
};

TEST_F(PhotoPinsTest, APhotoBehindARidgeIsGhostedOrNotDrawn) {
  RidgeSource ridge;
  test::SceneDrawer drawer(&ridge, nullptr);
  const double deg_per_m = 1.0 / (111320.0 * std::cos(kPlace.lat_deg * M_PI / 180.0));
  const auto camera =
      scene::camera_at({{kPlace.lat_deg, kPlace.lon_deg - 6000.0 * deg_per_m, 1300.0}, 90.0, 0.0}, lens_, 1000.0);
  ASSERT_TRUE(camera.ok()) << camera.error;
  const glm::dvec3 from = camera.value->position();
  const glm::dvec3 behind = scene::ecef_from({kPlace.lat_deg, kPlace.lon_deg + 4000.0 * deg_per_m, 1000.0});
  const glm::dvec3 in_front = from + 0.15 * (behind - from);
  scene::WaypointSet points;
  scene::Scene scene = scene_with(points);
  scene.neutral_ground_m = 1000.0;
  const scene::RgbaImage plain = drawer.draw(*camera.value, scene).image;

  points.points = {photo_pin(in_front, flat_photo(255, 0, 0))};
  const std::vector<scene::PlacedLabel> layout = drawer.renderer().layout_labels(scene, *camera.value, 1.0);
  ASSERT_EQ(layout.size(), 1u);
  const scene::RgbaImage seen = drawer.draw(*camera.value, scene).image;
  points.points = {photo_pin(behind, flat_photo(255, 0, 0))};
  ++points.revision;
  const scene::RgbaImage ghost = drawer.draw(*camera.value, scene).image;
  scene.style.labels.hide_occluded = true;
  const scene::RgbaImage hidden = drawer.draw(*camera.value, scene).image;
  test::keep_image(seen, "photo_seen.png");
  test::keep_image(ghost, "photo_ghost.png");

  const int area = layout[0].box.width * layout[0].box.height;
  EXPECT_GT(count_in(seen, layout[0].box, reddish), area / 2);
  EXPECT_EQ(count_in(ghost, layout[0].box, reddish), 0) << "a ghost is faint";
  EXPECT_GT(count_in(ghost, {0, 0, 400, 300}, [](const std::array<std::uint8_t, 4>& p) { return p[0] > p[1] + 30; }),
            area / 4)
      << "a ghost is still drawn, tinted";
  EXPECT_EQ(hidden.rgba, plain.rgba) << "--hidden-labels hide draws nothing of it";
}

}  // namespace
}  // namespace trailray::render
