// The track pass's geometry in whole frames (headless, llvmpipe in CI): the tube's width on
// screen in metres and in pixels, the minimum width of a distant track, a segment seen end-on,
// colour by value, and inputs that must neither crash nor vanish (empty, single points, 100k
// points, 200 tracks). Pixels are read as the red track's alpha over the grey neutral ground
// (track_test_support.hpp).
#include "render/passes/track_pass.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl_test_support.hpp"
#include "scene/pictures/colormap.hpp"
#include "render/renderer.hpp"
#include "scene_test_support.hpp"
#include "track_test_support.hpp"

namespace trailray::render {
namespace {

using test::column_alpha;
using test::GlTest;
using test::keep_image;
using test::kTrackRed;
using test::LocalFrame;
using test::looking_down;
using test::pixel_of;
using test::plain_scene;
using test::polyline;
using test::render_both;
using test::track_alpha;

constexpr scene::GeoPosition kPlace{46.5, 10.0, 0.0};
const scene::Lens kLens{30.0, 320, 240};

// The silhouette width (pixels) of a tube of radius r whose axis is parallel to the image plane
// at distance d: its outline lines sit at r sqrt(1 - r^2/d^2) from the axis, d - r^2/d deep.
double silhouette_width_px(double radius_m, double distance_m) {
  return 2.0 * radius_m * test::focal_length_px(kLens) / std::sqrt(distance_m * distance_m - radius_m * radius_m);
}

scene::TrackStyle width_settings(double value, scene::TrackWidth::Unit unit) {
  scene::TrackStyle style;
  style.width = {value, unit};
  return style;
}

// The red track's footprint: alpha summed over the picture, and how many columns and rows hold a
// pixel at least half covered.
struct Footprint {
  double area_px = 0.0;
  int columns = 0, rows = 0;
};
Footprint footprint(const test::WithAndWithout& images) {
  Footprint f;
  std::vector<bool> column(images.with.width, false), row(images.with.height, false);
  for (std::uint32_t y = 0; y < images.with.height; ++y)
    for (std::uint32_t x = 0; x < images.with.width; ++x) {
      const double a = track_alpha(images.with, images.without, x, y);
      f.area_px += a;
      if (a >= 0.5) column[x] = row[y] = true;
    }
  f.columns = static_cast<int>(std::count(column.begin(), column.end(), true));
  f.rows = static_cast<int>(std::count(row.begin(), row.end(), true));
  return f;
}

// A disc of `radius_px` (a sphere, or a capsule end-on): the alpha's area gives its radius (the
// anti-aliased fringe adds about an eighth of a pixel), the half-covered columns and rows its
// diameter both ways.
void expect_disc(const Footprint& f, double radius_px, const std::string& what) {
  EXPECT_NEAR(std::sqrt(f.area_px / M_PI), radius_px, 1.0) << what << ": area " << f.area_px << " px";
  EXPECT_NEAR(f.columns, 2.0 * radius_px, 2.0) << what;
  EXPECT_NEAR(f.rows, 2.0 * radius_px, 2.0) << what;
  EXPECT_LE(std::abs(f.columns - f.rows), 1) << what << ": not round (" << f.columns << " x " << f.rows << ")";
}

class TrackPassTest : public GlTest {};

// An 8 m tube 200 m below the camera, running east-west across the whole picture, seen square-on.
TEST_F(TrackPassTest, AMetreWideTubeIsTwoRFOverDPixelsWide) {
  const LocalFrame frame(kPlace);
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Camera camera = looking_down({kPlace.lat_deg, kPlace.lon_deg, 1000.0}, kLens, 10.0);
  const scene::TrackSet buffer = test::track_set(
      {test::track_of(test::geometry_of({polyline(frame, {{-150, 0, 800}, {150, 0, 800}})}))});
  scene::Scene options = plain_scene(kPlace, 0.0);
  options.style.tracks = width_settings(8.0, scene::TrackWidth::Unit::metres);
  const auto images = render_both(renderer, camera, options, buffer);
  keep_image(images.with, "track_width_8m.png");

  const double expected = silhouette_width_px(4.0, 200.0);  // 17.9 px
  for (std::uint32_t x = 10; x < kLens.width_px - 10; x += 15)
    EXPECT_NEAR(column_alpha(images.with, images.without, x), expected, 1.0) << "column " << x;
  // The tube is opaque in its middle (the classification sees it whole, not a faint tint).
  std::uint32_t cx = 0, cy = 0;
  ASSERT_TRUE(pixel_of(camera, frame.point(0, 0, 800), cx, cy));
  EXPECT_GT(track_alpha(images.with, images.without, cx, cy), 0.95);
}

// `--width 9px`: 9 pixels wide 200 m away and 5 km away.
TEST_F(TrackPassTest, APixelWideTubeKeepsItsWidthAtAnyDistance) {
  const LocalFrame frame(kPlace);
  test::SceneDrawer renderer(nullptr, nullptr);
  // Cut into 100 m segments: one 8 km segment has ragged edges (ALongSegmentHasStraightEdges).
  std::vector<glm::dvec3> line;
  for (double east = -4000.0; east <= 4000.0; east += 100.0) line.push_back({east, 0, 800});
  const scene::TrackSet buffer = test::track_set({test::track_of(test::geometry_of({polyline(frame, line)}))});
  scene::Scene options = plain_scene(kPlace, 0.0);
  options.style.tracks = width_settings(9.0, scene::TrackWidth::Unit::pixels);
  for (const double distance : {200.0, 5000.0}) {
    const scene::Camera camera = looking_down({kPlace.lat_deg, kPlace.lon_deg, 800.0 + distance}, kLens, distance / 20.0);
    const auto images = render_both(renderer, camera, options, buffer);
    keep_image(images.with, "track_width_9px_" + std::to_string(static_cast<int>(distance)) + "m.png");
    for (std::uint32_t x = 10; x < kLens.width_px - 10; x += 15)
      EXPECT_NEAR(column_alpha(images.with, images.without, x), 9.0, 1.0) << distance << " m away, column " << x;
  }
}

// A straight tube seen square-on has straight edges: along its length every column holds the
// same width. One segment 8 km long, 9 px wide, 5 km below the camera, against the same line cut
// into 100 m segments (rounding in the ray-capsule intersection grows with the segment's length
// and would make the long segment's edges ragged).
TEST_F(TrackPassTest, ALongSegmentHasStraightEdges) {
  const LocalFrame frame(kPlace);
  test::SceneDrawer renderer(nullptr, nullptr);
  std::vector<glm::dvec3> cut;
  for (double east = -4000.0; east <= 4000.0; east += 100.0) cut.push_back({east, 0, 800});
  const scene::TrackSet one = test::track_set(
      {test::track_of(test::geometry_of({polyline(frame, {{-4000, 0, 800}, {4000, 0, 800}})}))});
  const scene::TrackSet many = test::track_set({test::track_of(test::geometry_of({polyline(frame, cut)}))});
  scene::Scene options = plain_scene(kPlace, 0.0);
  options.style.tracks = width_settings(9.0, scene::TrackWidth::Unit::pixels);
  const scene::Camera camera = looking_down({kPlace.lat_deg, kPlace.lon_deg, 5800.0}, kLens, 250.0);
  for (const scene::TrackSet* buffer : {&many, &one}) {
    const std::string what = buffer == &one ? "one 8 km segment" : "80 segments of 100 m";
    const auto images = render_both(renderer, camera, options, *buffer);
    keep_image(images.with, buffer == &one ? "track_long_segment.png" : "track_cut_segments.png");
    double least = 1.0e9, most = 0.0;
    for (std::uint32_t x = 10; x < kLens.width_px - 10; ++x) {
      const double width = column_alpha(images.with, images.without, x);
      least = std::min(least, width);
      most = std::max(most, width);
    }
    EXPECT_LT(most - least, 0.6) << what << ": column widths from " << least << " to " << most << " px";
  }
}

// A 1 m tube 20 km away (0.02 px) is drawn 1.5 px wide, with no gaps: every column it crosses
// holds a half-covered pixel. The track runs 30 degrees off east, so it crosses rows too.
TEST_F(TrackPassTest, ADistantThinTubeKeepsTheMinimumWidthWithoutGaps) {
  const LocalFrame frame(kPlace);
  test::SceneDrawer renderer(nullptr, nullptr);
  const double c = std::cos(M_PI / 6.0), s = std::sin(M_PI / 6.0);
  const scene::TrackSet buffer = test::track_set(
      {test::track_of(test::geometry_of({polyline(frame, {{-5000 * c, -5000 * s, 10}, {5000 * c, 5000 * s, 10}})}))});
  const scene::Camera camera = looking_down({kPlace.lat_deg, kPlace.lon_deg, 20010.0}, kLens, 1000.0);
  scene::Scene options = plain_scene(kPlace, 0.0);
  options.style.tracks = width_settings(1.0, scene::TrackWidth::Unit::metres);
  ASSERT_DOUBLE_EQ(options.style.tracks.min_width_px, 1.5);
  const auto images = render_both(renderer, camera, options, buffer);
  keep_image(images.with, "track_min_width.png");

  std::uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  ASSERT_TRUE(pixel_of(camera, frame.point(-4000 * c, -4000 * s, 10), x0, y0));
  ASSERT_TRUE(pixel_of(camera, frame.point(4000 * c, 4000 * s, 10), x1, y1));
  ASSERT_GT(x1, x0 + 100);
  const double expected = 1.5 / c;  // a 1.5 px band crossing a column at 30 degrees
  for (std::uint32_t x = x0; x <= x1; ++x) {
    double column_max = 0.0;
    for (std::uint32_t y = 0; y < images.with.height; ++y)
      column_max = std::max(column_max, track_alpha(images.with, images.without, x, y));
    EXPECT_GE(column_max, 0.5) << "a gap in column " << x;
    EXPECT_NEAR(column_alpha(images.with, images.without, x), expected, 0.9) << "column " << x;
  }
}

// A capsule pointing at the camera (vertical, under a camera looking straight down) is a disc
// of its near end's silhouette radius, not the far end's and not a square.
TEST_F(TrackPassTest, ASegmentSeenEndOnIsARoundDiscOfItsNearEnd) {
  const LocalFrame frame(kPlace);
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Camera camera = looking_down({kPlace.lat_deg, kPlace.lon_deg, 1000.0}, kLens, 10.0);
  const scene::TrackSet buffer = test::track_set(
      {test::track_of(test::geometry_of({polyline(frame, {{0, 0, 800}, {0, 0, 700}})}))});
  scene::Scene options = plain_scene(kPlace, 0.0);
  options.style.tracks = width_settings(8.0, scene::TrackWidth::Unit::metres);
  const auto images = render_both(renderer, camera, options, buffer);
  keep_image(images.with, "track_end_on.png");
  // The near end's cap: a sphere of 4 m radius 200 m away (the far end's would be 6 px).
  expect_disc(footprint(images), 0.5 * silhouette_width_px(4.0, 200.0), "end-on");
}

// Colour by value: values 10 on the first half of the points, 20 on the second, range 0..20:
// the halves show turbo at 0.5 and at 1.0, as the same tube drawn in those solid colours does.
TEST_F(TrackPassTest, ValuesPickTheirColormapColours) {
  const LocalFrame frame(kPlace);
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Camera camera = looking_down({kPlace.lat_deg, kPlace.lon_deg, 1000.0}, kLens, 10.0);
  const std::vector<glm::dvec3> points{{-150, 0, 800}, {-110, 0, 800}, {-70, 0, 800}, {-40, 0, 800},
                                       {40, 0, 800},   {70, 0, 800},   {110, 0, 800}, {150, 0, 800}};
  const scene::TrackSet valued = test::track_set(
      {test::track_of(test::geometry_of({polyline(frame, points, {10, 10, 10, 10, 20, 20, 20, 20})}), kTrackRed,
                      true)});
  scene::Scene options = plain_scene(kPlace, 0.0);
  options.style.tracks = width_settings(8.0, scene::TrackWidth::Unit::metres);
  options.style.tracks.colormap = scene::Colormap::turbo;
  options.color_range = track::ValueRange{0.0, 20.0};
  options.tracks = &valued;
  const scene::RgbaImage by_value = renderer.draw(camera, options).image;
  keep_image(by_value, "track_by_value.png");

  const glm::vec3 half = scene::colormap_color(scene::Colormap::turbo, 0.5f), full = scene::colormap_color(scene::Colormap::turbo, 1.0f);
  ASSERT_GT(glm::length(half - full), 0.3f) << "the two colours must be told apart";
  for (const auto& [east, colour] : {std::pair{-60.0, half}, std::pair{60.0, full}}) {
    const scene::TrackSet plain = test::track_set(
        {test::track_of(test::geometry_of({polyline(frame, points)}), colour)});
    options.tracks = &plain;
    const scene::RgbaImage solid = renderer.draw(camera, options).image;
    std::uint32_t x = 0, y = 0;
    ASSERT_TRUE(pixel_of(camera, frame.point(east, 0, 800), x, y));
    // Across the tube's middle (lit alike in both pictures): the same colour.
    for (std::uint32_t row = y - 5; row <= y + 5; ++row) {
      const auto a = by_value.pixel(x, row), b = solid.pixel(x, row);
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(a[ch], b[ch], 3) << east << " m east, row " << row << ", channel " << ch;
    }
  }
}

// Nothing to draw: the picture is the picture without tracks.
TEST_F(TrackPassTest, AnEmptyTrackDrawsNothing) {
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Camera camera = looking_down({kPlace.lat_deg, kPlace.lon_deg, 1000.0}, kLens, 10.0);
  scene::TrackGeometry empty_segment;
  empty_segment.segments.emplace_back();
  const TrackBuffer none{scene::TrackGeometry{}}, hollow(empty_segment);
  EXPECT_EQ(none.point_count(), 0u);
  EXPECT_TRUE(hollow.segments().empty());
  const scene::TrackSet tracks =
      test::track_set({test::track_of(scene::TrackGeometry{}), test::track_of(empty_segment)});
  const auto images = render_both(renderer, camera, plain_scene(kPlace, 0.0), tracks);
  EXPECT_EQ(images.with.rgba, images.without.rgba);
}

// A segment of one point, and one of two identical points: a sphere, a round disc.
TEST_F(TrackPassTest, OnePointAndTwoIdenticalPointsDrawASphere) {
  const LocalFrame frame(kPlace);
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Camera camera = looking_down({kPlace.lat_deg, kPlace.lon_deg, 1000.0}, kLens, 10.0);
  scene::Scene options = plain_scene(kPlace, 0.0);
  options.style.tracks = width_settings(8.0, scene::TrackWidth::Unit::metres);
  const scene::TrackSet one = test::track_set({test::track_of(test::geometry_of({polyline(frame, {{20, 10, 800}})}))});
  const scene::TrackSet two = test::track_set(
      {test::track_of(test::geometry_of({polyline(frame, {{20, 10, 800}, {20, 10, 800}})}))});
  for (const scene::TrackSet* buffer : {&one, &two}) {
    const auto images = render_both(renderer, camera, options, *buffer);
    const std::string what = buffer == &one ? "one point" : "two identical points";
    keep_image(images.with, buffer == &one ? "track_one_point.png" : "track_two_points.png");
    std::uint32_t x = 0, y = 0;
    ASSERT_TRUE(pixel_of(camera, frame.point(20, 10, 800), x, y));
    EXPECT_GT(track_alpha(images.with, images.without, x, y), 0.95) << what;
    // 20 m off the centre of the picture the disc is stretched outwards by 1 %: still round.
    expect_disc(footprint(images), 0.5 * silhouette_width_px(4.0, std::hypot(200.0, 22.4)), what);
  }
}

// 100,000 points on a circle (49 texture rows, 391 block origins): the ring is whole.
TEST_F(TrackPassTest, AHundredThousandPointsDrawAWholeRing) {
  const LocalFrame frame(kPlace);
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Camera camera = looking_down({kPlace.lat_deg, kPlace.lon_deg, 1000.0}, kLens, 10.0);
  constexpr int kPoints = 100000;
  constexpr double kRadius = 40.0;
  std::vector<glm::dvec3> ring;
  for (int i = 0; i < kPoints; ++i) {
    const double a = 2.0 * M_PI * i / (kPoints - 1);
    ring.push_back({kRadius * std::cos(a), kRadius * std::sin(a), 800.0});
  }
  const scene::TrackGeometry geometry = test::geometry_of({polyline(frame, ring)});
  const TrackBuffer uploaded(geometry);
  EXPECT_EQ(uploaded.point_count(), static_cast<std::size_t>(kPoints));
  EXPECT_LE(uploaded.gpu_bytes(), 20u * kPoints) << "the issue's memory budget";
  const scene::TrackSet buffer = test::track_set({test::track_of(geometry)});
  scene::Scene options = plain_scene(kPlace, 0.0);
  options.style.tracks = width_settings(4.0, scene::TrackWidth::Unit::metres);
  const auto images = render_both(renderer, camera, options, buffer);
  keep_image(images.with, "track_100k_ring.png");
  for (int degree = 0; degree < 360; ++degree) {
    const double a = degree * M_PI / 180.0;
    std::uint32_t x = 0, y = 0;
    ASSERT_TRUE(pixel_of(camera, frame.point(kRadius * std::cos(a), kRadius * std::sin(a), 800), x, y));
    EXPECT_GT(track_alpha(images.with, images.without, x, y), 0.9) << "a gap at " << degree << " degrees";
  }
  std::uint32_t cx = 0, cy = 0;
  ASSERT_TRUE(pixel_of(camera, frame.point(0, 0, 800), cx, cy));
  EXPECT_LT(track_alpha(images.with, images.without, cx, cy), 0.02) << "the ring's middle is empty";
}

// 200 tracks, each its own buffer: every one is drawn, and the ground between them is not.
TEST_F(TrackPassTest, TwoHundredTracksAreAllDrawn) {
  const LocalFrame frame(kPlace);
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Camera camera = looking_down({kPlace.lat_deg, kPlace.lon_deg, 1000.0}, kLens, 10.0);
  scene::TrackSet draws;
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 20; ++i) {
      const double east = -60.0 + 6.0 * i, north = -45.0 + 10.0 * j;
      draws.add(test::track_of(test::geometry_of({polyline(frame, {{east - 2, north, 800}, {east + 2, north, 800}})})));
    }
  scene::Scene options = plain_scene(kPlace, 0.0);
  options.style.tracks = width_settings(1.0, scene::TrackWidth::Unit::metres);
  const auto images = render_both(renderer, camera, options, draws);
  keep_image(images.with, "track_200_tracks.png");
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 20; ++i) {
      const double east = -60.0 + 6.0 * i, north = -45.0 + 10.0 * j;
      std::uint32_t x = 0, y = 0;
      ASSERT_TRUE(pixel_of(camera, frame.point(east, north, 800), x, y));
      EXPECT_GT(track_alpha(images.with, images.without, x, y), 0.7) << "track " << j * 20 + i;
      ASSERT_TRUE(pixel_of(camera, frame.point(east, north + 5, 800), x, y));
      EXPECT_LT(track_alpha(images.with, images.without, x, y), 0.02) << "between rows " << j << " and " << j + 1;
    }
}

// Bad input is refused with a message naming the segment and the point, before any drawing.
TEST_F(TrackPassTest, ABufferRefusesMismatchedValuesAndNonFinitePoints) {
  const LocalFrame frame(kPlace);
  scene::TrackPolyline mismatched = polyline(frame, {{0, 0, 800}, {10, 0, 800}}, {1.0f});
  try {
    const TrackBuffer buffer(test::geometry_of({mismatched}));
    FAIL() << "one value for two points was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("segment 0"), std::string::npos) << e.what();
  }
  scene::TrackPolyline broken = polyline(frame, {{0, 0, 800}, {10, 0, 800}});
  broken.points_ecef[1].y = std::nan("");
  try {
    const TrackBuffer buffer(test::geometry_of({polyline(frame, {{0, 0, 800}}), broken}));
    FAIL() << "a NaN point was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("segment 1 point 1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace trailray::render
