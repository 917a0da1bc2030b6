// Waypoints drawn as pins (a stem and a ball, by the track pass) and routes as a thinner, dashed
// line in their own colour: a pin shows where its waypoint projects and nowhere else, a hidden
// one not at all, a place's ball is smaller than a waypoint's, and a route is thinner than a
// track of the same points, with gaps, and drawn in the route's colour.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "gl_test_support.hpp"
#include "render/pin_gpu.hpp"
#include "render/renderer.hpp"
#include "scene_test_support.hpp"
#include "track_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;
using test::LocalFrame;
using test::polyline;

constexpr scene::GeoPosition kPlace{46.5, 10.0, 0.0};
const scene::Lens kLens{30.0, 160, 120};

scene::Waypoint waypoint_at(const LocalFrame& frame, double east_m, double north_m, double up_m,
                            scene::WaypointKind kind = scene::WaypointKind::Waypoint) {
  scene::Waypoint w;
  w.kind = kind;
  w.ground_ecef = frame.point(east_m, north_m, 0.0);
  w.marker_ecef = frame.point(east_m, north_m, up_m);
  return w;
}

// Pixels of a row where the red classifier sees more than half coverage.
int covered_in_row(const test::WithAndWithout& images, std::uint32_t y) {
  int n = 0;
  for (std::uint32_t x = 0; x < images.with.width; ++x) n += test::track_alpha(images.with, images.without, x, y) > 0.5;
  return n;
}

int covered_pixels(const scene::RgbaImage& with, const scene::RgbaImage& without) {
  int n = 0;
  for (std::uint32_t y = 0; y < with.height; ++y)
    for (std::uint32_t x = 0; x < with.width; ++x) n += test::track_alpha(with, without, x, y) > 0.5;
  return n;
}

class PinsAndRoutesTest : public GlTest {
 protected:
  // Red balls and stems, so the classifier reads them.
  scene::Scene red_pin_scene() const {
    scene::Scene s = test::plain_scene(kPlace, 0.0);
    s.style.pins.waypoint_color = test::kTrackRed;
    s.style.pins.place_color = test::kTrackRed;
    s.style.pins.stem_color = test::kTrackRed;
    return s;
  }
  test::WithAndWithout draw_pins(const scene::Scene& scene, const scene::WaypointSet& set) {
    test::WithAndWithout out;
    scene::Scene s = scene;
    s.waypoints = nullptr;
    out.without = drawer_.draw(camera_, s).image;
    s.waypoints = &set;
    out.with = drawer_.draw(camera_, s).image;
    return out;
  }
  LocalFrame frame_{kPlace};
  scene::Camera camera_ = test::looking_down({kPlace.lat_deg, kPlace.lon_deg, 1000.0}, kLens, 10.0);
  test::SceneDrawer drawer_{nullptr, nullptr};
};

TEST_F(PinsAndRoutesTest, APinIsDrawnWhereItsWaypointProjectsAndNowhereElse) {
  scene::WaypointSet set;
  set.points = {waypoint_at(frame_, 80.0, 40.0, 30.0)};
  const test::WithAndWithout images = draw_pins(red_pin_scene(), set);

  std::uint32_t x = 0, y = 0;
  ASSERT_TRUE(test::pixel_of(camera_, set.points[0].marker_ecef, x, y));
  EXPECT_GT(test::track_alpha(images.with, images.without, x, y), 0.9) << "at the pin (" << x << ", " << y << ")";
  // Where there is no waypoint (the mirror image of its place) nothing is drawn.
  std::uint32_t mx = 0, my = 0;
  ASSERT_TRUE(test::pixel_of(camera_, frame_.point(-80.0, -40.0, 30.0), mx, my));
  EXPECT_LT(test::track_alpha(images.with, images.without, mx, my), 0.05);
  // Everything drawn lies near the pin: a ball about marker_px across, bounded in pixels.
  const int all = covered_pixels(images.with, images.without);
  EXPECT_GT(all, 50);
  EXPECT_LT(all, 400);
  const int across = covered_in_row(images, y);
  EXPECT_GE(across, 9);
  EXPECT_LE(across, 18);
}

TEST_F(PinsAndRoutesTest, ManyPinsOfAKindAreEachDrawnAtTheirPlace) {
  // One buffer and one draw per kind and part: every pin still stands on its own.
  scene::WaypointSet set;
  for (int i = 0; i < 5; ++i) set.points.push_back(waypoint_at(frame_, -120.0 + 60.0 * i, 30.0 * (i % 2), 5.0 * i));
  const test::WithAndWithout images = draw_pins(red_pin_scene(), set);
  for (const scene::Waypoint& w : set.points) {
    std::uint32_t x = 0, y = 0;
    ASSERT_TRUE(test::pixel_of(camera_, w.marker_ecef, x, y));
    EXPECT_GT(test::track_alpha(images.with, images.without, x, y), 0.9) << "at (" << x << ", " << y << ")";
  }
  // Between two neighbours nothing: the pins are not joined into a line.
  std::uint32_t x = 0, y = 0;
  ASSERT_TRUE(test::pixel_of(camera_, frame_.point(-90.0, 15.0, 2.5), x, y));
  EXPECT_LT(test::track_alpha(images.with, images.without, x, y), 0.05);
}

TEST_F(PinsAndRoutesTest, AHiddenWaypointHasNoPinAndAPlaceIsSmaller) {
  scene::WaypointSet set;
  set.points = {waypoint_at(frame_, -60.0, 0.0, 10.0),
                waypoint_at(frame_, 60.0, 0.0, 10.0, scene::WaypointKind::Place)};
  const test::WithAndWithout both = draw_pins(red_pin_scene(), set);
  std::uint32_t wx = 0, wy = 0, px = 0, py = 0;
  ASSERT_TRUE(test::pixel_of(camera_, set.points[0].marker_ecef, wx, wy));
  ASSERT_TRUE(test::pixel_of(camera_, set.points[1].marker_ecef, px, py));
  EXPECT_GT(test::track_alpha(both.with, both.without, wx, wy), 0.9);
  EXPECT_GT(test::track_alpha(both.with, both.without, px, py), 0.9);
  // Both lie on one row: the waypoint's ball in the left half, the place's in the right.
  int waypoint_px = 0, place_px = 0;
  for (std::uint32_t x = 0; x < both.with.width; ++x)
    (x < both.with.width / 2 ? waypoint_px : place_px) += test::track_alpha(both.with, both.without, x, wy) > 0.5;
  EXPECT_GT(waypoint_px, place_px + 2);

  set.points[0].visible = false;
  ++set.revision;
  const test::WithAndWithout one = draw_pins(red_pin_scene(), set);
  EXPECT_LT(test::track_alpha(one.with, one.without, wx, wy), 0.05);
  EXPECT_GT(test::track_alpha(one.with, one.without, px, py), 0.9);
}

TEST_F(PinsAndRoutesTest, PinBuffersAreMadeOncePerRevision) {
  scene::WaypointSet set;
  set.points = {waypoint_at(frame_, 0.0, 0.0, 10.0), waypoint_at(frame_, 10.0, 0.0, 10.0, scene::WaypointKind::Place)};
  PinGpu gpu;
  const scene::PinStyle style;
  const auto first = gpu.draws(&set, style);
  ASSERT_EQ(first.size(), 4u);  // stems and balls of both kinds
  for (const TrackDraw& d : first) EXPECT_TRUE(d.is_pin);
  const auto again = gpu.draws(&set, style);
  EXPECT_EQ(again[0].buffer, first[0].buffer);
  set.points.pop_back();
  ++set.revision;
  EXPECT_EQ(gpu.draws(&set, style).size(), 2u);
  EXPECT_TRUE(gpu.draws(nullptr, style).empty());
}

TEST_F(PinsAndRoutesTest, ARouteIsThinnerThanATrackOfTheSamePointsDashedAndInItsColour) {
  // The same line twice, 150 m apart: a recorded track above, a route (metres along it as its
  // values) below, both pure red for the classifier.
  const auto line = [&](double north_m) {
    return test::geometry_of({polyline(frame_, {{-250, north_m, 0}, {250, north_m, 0}}, {0.0f, 500.0f})});
  };
  scene::Track recorded = test::track_of(line(75.0));
  recorded.geometry.segments[0].values.clear();
  scene::Track route = test::track_of(line(-75.0));
  route.is_route = true;
  scene::TrackSet tracks = test::track_set({recorded, route});
  scene::Scene scene = test::plain_scene(kPlace, 0.0);
  scene.style.tracks.width = {8.0, scene::TrackWidth::Unit::pixels};
  const test::WithAndWithout images = test::render_both(drawer_, camera_, scene, tracks);

  std::uint32_t tx = 0, ty = 0, rx = 0, ry = 0;
  ASSERT_TRUE(test::pixel_of(camera_, frame_.point(0, 75, 0), tx, ty));
  ASSERT_TRUE(test::pixel_of(camera_, frame_.point(0, -75, 0), rx, ry));
  // Widths: the alpha summed down each column, over the half of the image holding each line;
  // the route's at its dashes.
  double track_width = 0.0, route_width = 0.0;
  int route_columns = 0, gap_columns = 0, track_gaps = 0;
  const std::uint32_t mid = (ty + ry) / 2;
  for (std::uint32_t x = 30; x + 30 < images.with.width; ++x) {
    double t = 0.0, r = 0.0;
    for (std::uint32_t y = 0; y < images.with.height; ++y)
      (y < mid ? t : r) += test::track_alpha(images.with, images.without, x, y);
    track_width = std::max(track_width, t);
    track_gaps += t < 0.2;
    ++route_columns;
    if (r < 0.2)
      ++gap_columns;
    else
      route_width = std::max(route_width, r);
  }
  EXPECT_NEAR(track_width, 8.0, 1.5);
  EXPECT_NEAR(route_width, 4.0, 1.5);
  EXPECT_EQ(track_gaps, 0);
  // Dashes: gaps along about half the route, never the whole.
  EXPECT_GT(gap_columns, route_columns / 4);
  EXPECT_LT(gap_columns, route_columns * 3 / 4);

  // Its own colour: a blue route reads blue, the red track red.
  tracks[1].color_srgb = {0.0f, 0.0f, 1.0f};
  tracks[1].bump_revision();
  scene.tracks = &tracks;
  const scene::RgbaImage coloured = drawer_.draw(camera_, scene).image;
  int blue = 0, red = 0;
  for (std::uint32_t x = 30; x + 30 < coloured.width; ++x) {
    const auto p = coloured.pixel(x, ry);
    blue += p[2] > p[0] + 40;
    const auto q = coloured.pixel(x, ty);
    red += q[0] > q[2] + 40;
  }
  EXPECT_GT(blue, 20);
  EXPECT_GT(red, 60);
}

}  // namespace
}  // namespace trailray::render
