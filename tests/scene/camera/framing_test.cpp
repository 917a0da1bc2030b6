#include "scene/camera/framing.hpp"

#include <gtest/gtest.h>
#include <GeographicLib/Geodesic.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "test_support.hpp"

namespace trailray::scene {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

// A point `east` and `north` metres from (lat, lon) (along the geodesic), at `height`.
GeoPosition offset_point(double lat, double lon, double east, double north, double height) {
  GeoPosition p;
  GeographicLib::Geodesic::WGS84().Direct(lat, lon, std::atan2(east, north) / kRadPerDeg, std::hypot(east, north),
                                          p.lat_deg, p.lon_deg);
  p.height_m = height;
  return p;
}

// A straight track of `length` metres through (lat, lon) at `azimuth_deg`, with a little wiggle.
std::vector<GeoPosition> straight_track(double lat, double lon, double azimuth_deg, double length, double height) {
  std::vector<GeoPosition> points;
  const double az = azimuth_deg * kRadPerDeg;
  for (int i = 0; i <= 200; ++i) {
    const double along = (i / 200.0 - 0.5) * length, aside = 30.0 * std::sin(i * 0.3);
    points.push_back(offset_point(lat, lon, along * std::sin(az) + aside * std::cos(az),
                                  along * std::cos(az) - aside * std::sin(az), height + 50.0 * std::sin(i * 0.05)));
  }
  return points;
}

// An elliptic loop, `long_axis` x `short_axis` metres, the long axis at `azimuth_deg`.
std::vector<GeoPosition> loop_track(double lat, double lon, double azimuth_deg, double long_axis, double short_axis,
                                    double height) {
  std::vector<GeoPosition> points;
  const double az = azimuth_deg * kRadPerDeg;
  for (int i = 0; i < 500; ++i) {
    const double t = 2.0 * std::numbers::pi * i / 500.0;
    const double u = 0.5 * long_axis * std::cos(t), v = 0.5 * short_axis * std::sin(t);
    points.push_back(offset_point(lat, lon, u * std::sin(az) + v * std::cos(az), u * std::cos(az) - v * std::sin(az),
                                  height + 300.0 * std::sin(t)));
  }
  return points;
}

struct ImageSpan {
  double min_x = 1e300, max_x = -1e300, min_y = 1e300, max_y = -1e300;
};

// Every point projects inside the image with (almost) the margin; returns their pixel bounds.
ImageSpan expect_inside_with_margin(const Camera& camera, const std::vector<GeoPosition>& points, double margin) {
  const double w = camera.lens().width_px, h = camera.lens().height_px;
  ImageSpan span;
  for (const GeoPosition& p : points) {
    const auto s = camera.project(ecef_from(p));
    EXPECT_TRUE(s) << p.lat_deg << ", " << p.lon_deg << " is behind the camera";
    if (!s) continue;
    span.min_x = std::min(span.min_x, s->x_px), span.max_x = std::max(span.max_x, s->x_px);
    span.min_y = std::min(span.min_y, s->y_px), span.max_y = std::max(span.max_y, s->y_px);
    EXPECT_LT(s->depth_m, camera.depth_range().far_m);
    EXPECT_GT(s->depth_m, camera.depth_range().near_m);
  }
  EXPECT_GE(span.min_x, margin * w - 0.5);
  EXPECT_LE(span.max_x, (1.0 - margin) * w + 0.5);
  EXPECT_GE(span.min_y, margin * h - 0.5);
  EXPECT_LE(span.max_y, (1.0 - margin) * h + 0.5);
  return span;
}

double heading_difference(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

Framing framed(const std::vector<GeoPosition>& points, const FramingOptions& options = {}) {
  Result<Framing> r = frame_points(points, options);
  EXPECT_TRUE(r.ok()) << r.error;
  if (!r.ok()) throw std::runtime_error(r.error);
  return *r.value;
}

TEST(Framing, LoopTrackFitsWithMarginAndSpreadsAcrossTheImage) {
  const std::vector<GeoPosition> track = loop_track(46.69, 7.86, 30.0, 6000.0, 2500.0, 1200.0);
  const FramingOptions options;
  const Framing f = framed(track, options);
  EXPECT_GE(f.camera.pitch_deg(), -50.0);
  EXPECT_LE(f.camera.pitch_deg(), -40.0);
  const ImageSpan span = expect_inside_with_margin(f.camera, track, options.margin_fraction);
  EXPECT_GE(span.max_x - span.min_x, 0.5 * options.lens.width_px);
  // Fitted tightly: one pair of edges touches the margin, and the image is centred.
  const double w = options.lens.width_px, h = options.lens.height_px;
  EXPECT_TRUE(span.max_x - span.min_x > (1.0 - 2.0 * options.margin_fraction) * w - 2.0 ||
              span.max_y - span.min_y > (1.0 - 2.0 * options.margin_fraction) * h - 2.0);
  EXPECT_NEAR(span.min_x + span.max_x, w, 2.0);
  EXPECT_NEAR(span.min_y + span.max_y, h, 2.0);
  // The long axis (30 degrees) lies across the screen: the view is along 120 or 300 degrees.
  EXPECT_LT(
      std::min(heading_difference(f.look_at.heading_deg, 120.0), heading_difference(f.look_at.heading_deg, 300.0)),
      3.0);
  // The camera is above the track, looking down at it from a few km.
  EXPECT_GT(f.camera.geodetic().height_m, 1500.0);
  EXPECT_GT(f.look_at.distance_m, 3000.0);
  EXPECT_LT(f.look_at.distance_m, 20000.0);
}

TEST(Framing, NorthSouthTrackIsSeenFromTheSide) {
  const Framing f = framed(straight_track(46.69, 7.86, 0.0, 10000.0, 800.0));
  EXPECT_LT(
      std::min(heading_difference(f.camera.heading_deg(), 90.0), heading_difference(f.camera.heading_deg(), 270.0)),
      4.0)
      << f.camera.heading_deg();
  const Framing g = framed(straight_track(-33.9, 151.2, 180.0, 3000.0, 50.0));
  EXPECT_LT(
      std::min(heading_difference(g.camera.heading_deg(), 90.0), heading_difference(g.camera.heading_deg(), 270.0)),
      4.0)
      << g.camera.heading_deg();
}

TEST(Framing, EastWestTrackIsSeenFromNorthOrSouth) {
  const std::vector<GeoPosition> track = straight_track(46.69, 7.86, 90.0, 12000.0, 800.0);
  const Framing f = framed(track);
  EXPECT_LT(
      std::min(heading_difference(f.camera.heading_deg(), 0.0), heading_difference(f.camera.heading_deg(), 180.0)), 4.0)
      << f.camera.heading_deg();
  const ImageSpan span = expect_inside_with_margin(f.camera, track, 0.08);
  EXPECT_GE(span.max_x - span.min_x, 0.8 * 1920.0);  // a line across the screen fills its width
  // Of the two sides, the preferred heading's.
  FramingOptions from_south;
  from_south.preferred_heading_deg = 170.0;
  EXPECT_LT(heading_difference(framed(track, from_south).camera.heading_deg(), 180.0), 4.0);
}

TEST(Framing, DiagonalTrackAcrossTheAntimeridian) {
  const std::vector<GeoPosition> track = straight_track(-17.0, 179.99, 45.0, 20000.0, 10.0);
  ASSERT_TRUE(std::any_of(track.begin(), track.end(), [](const GeoPosition& p) { return p.lon_deg < 0.0; }));
  const Framing f = framed(track);
  const ImageSpan span = expect_inside_with_margin(f.camera, track, 0.08);
  EXPECT_GE(span.max_x - span.min_x, 0.5 * 1920.0);
  EXPECT_LT(
      std::min(heading_difference(f.camera.heading_deg(), 135.0), heading_difference(f.camera.heading_deg(), 315.0)),
      4.0);
}

TEST(Framing, RoundTrackUsesThePreferredHeading) {
  FramingOptions options;
  options.preferred_heading_deg = 30.0;
  const std::vector<GeoPosition> circle = loop_track(60.0, 25.0, 0.0, 4000.0, 4000.0, 100.0);
  const Framing f = framed(circle, options);
  EXPECT_NEAR(f.look_at.heading_deg, 30.0, 1e-9);
  expect_inside_with_margin(f.camera, circle, options.margin_fraction);
}

TEST(Framing, SinglePointOrTinyTrackGivesASaneCamera) {
  const GeoPosition summit{46.5372, 7.9627, 4158.0};  // the Jungfrau
  for (const std::vector<GeoPosition>& points :
       {std::vector<GeoPosition>{summit},
        std::vector<GeoPosition>{summit, offset_point(summit.lat_deg, summit.lon_deg, 2.0, 3.0, 4159.0),
                                 offset_point(summit.lat_deg, summit.lon_deg, -1.0, 4.0, 4157.0)}}) {
    FramingOptions options;
    options.ground_height_m = 4150.0;
    const Framing f = framed(points, options);
    EXPECT_DOUBLE_EQ(f.look_at.pitch_deg, -45.0);
    EXPECT_NEAR(f.camera.pitch_deg(), -45.0, 0.05);  // its own frame is tilted by the Earth's curvature
    EXPECT_TRUE(std::isfinite(f.camera.position().x) && std::isfinite(f.camera.position().y) &&
                std::isfinite(f.camera.position().z));
    // Terrain context: at least the minimum width of ground in view at the target.
    const double view_width = 2.0 * f.look_at.distance_m * std::tan(22.5 * kRadPerDeg) * options.lens.aspect();
    EXPECT_GE(view_width, options.min_view_width_m * 0.999);
    EXPECT_LT(view_width, options.min_view_width_m * 1.01);
    EXPECT_GT(f.camera.geodetic().height_m, summit.height_m + 500.0);
    const auto s = f.camera.project(ecef_from(summit));
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->x_px, 960.0, 5.0);
    EXPECT_NEAR(s->y_px, 540.0, 5.0);
  }
}

// A paraglider climbing in thermals 2000 m above the valley floor and gliding across it.
TEST(Framing, HighFlightFitsWhole) {
  std::vector<GeoPosition> flight;
  const double ground = 600.0;
  for (int i = 0; i < 3000; ++i) {
    const double t = i / 3000.0;
    const double east = 8000.0 * t + 150.0 * std::cos(i * 0.2),
                 north = 2500.0 * std::sin(3.0 * t) + 150.0 * std::sin(i * 0.2);
    flight.push_back(offset_point(46.69, 7.86, east, north, ground + 100.0 + 2000.0 * std::sin(std::numbers::pi * t)));
  }
  FramingOptions options;
  options.ground_height_m = ground;
  options.lens = Lens{45.0, 1280, 720};
  const Framing f = framed(flight, options);
  const ImageSpan span = expect_inside_with_margin(f.camera, flight, options.margin_fraction);
  EXPECT_GE(span.max_x - span.min_x, 0.5 * 1280.0);
  // The ground under the flight's ends is in view too (the track is seen against the terrain).
  for (const GeoPosition& end : {flight.front(), flight.back()}) {
    const auto s = f.camera.project(ecef_from(GeoPosition{end.lat_deg, end.lon_deg, ground}));
    ASSERT_TRUE(s);
    EXPECT_GT(s->y_px, 0.0);
    EXPECT_LT(s->y_px, 720.0);
  }
}

TEST(Framing, PointsWithoutHeightSitOnTheGround) {
  std::vector<GeoPosition> track = straight_track(45.0, 14.0, 60.0, 5000.0, 500.0);
  for (std::size_t i = 0; i < track.size(); i += 2) track[i].height_m = std::nan("");
  const Framing f = framed(track);
  for (GeoPosition& p : track) {
    if (std::isnan(p.height_m)) p.height_m = 450.0;  // the lowest height (500 - 50)
  }
  expect_inside_with_margin(f.camera, track, 0.08);
}

TEST(Framing, UnusablePointsAreLeftOutAndNoneIsAnError) {
  std::vector<GeoPosition> track = straight_track(46.69, 7.86, 0.0, 5000.0, 800.0);
  std::vector<GeoPosition> with_junk = track;
  with_junk.push_back({std::nan(""), 7.0, 100.0});
  with_junk.push_back({95.0, 7.0, 100.0});
  with_junk.push_back({46.0, std::numeric_limits<double>::infinity(), 100.0});
  const Framing f = framed(with_junk);
  expect_inside_with_margin(f.camera, track, 0.08);

  const Result<Framing> none = frame_points(std::vector<GeoPosition>{{std::nan(""), 7.0, 1.0}, {91.0, 0.0, 0.0}});
  EXPECT_FALSE(none.ok());
  EXPECT_NE(none.error.find("none of the 2 points"), std::string::npos) << none.error;
  EXPECT_FALSE(frame_points(std::vector<GeoPosition>{}).ok());

  FramingOptions bad;
  bad.pitch_deg = 10.0;
  const Result<Framing> up = frame_points(track, bad);
  EXPECT_FALSE(up.ok());
  EXPECT_NE(up.error.find("pitch 10 is outside -90..-5"), std::string::npos) << up.error;
  bad = FramingOptions{};
  bad.lens.vertical_fov_deg = 0.0;
  EXPECT_NE(frame_points(track, bad).error.find("--fov 0"), std::string::npos);
  bad = FramingOptions{};
  bad.margin_fraction = 0.6;
  EXPECT_FALSE(frame_points(track, bad).ok());
}

TEST(Framing, OtherPitchesAndPortraitImages) {
  const std::vector<GeoPosition> track = loop_track(47.0, 11.0, 0.0, 8000.0, 3000.0, 2000.0);
  FramingOptions options;
  options.pitch_deg = -70.0;
  options.lens = Lens{30.0, 600, 1000};
  const Framing f = framed(track, options);
  EXPECT_NEAR(f.camera.pitch_deg(), -70.0, 0.1);
  expect_inside_with_margin(f.camera, track, options.margin_fraction);
}

// Kept-clear corners (a legend drawn over the picture)

// The corner's rectangle in pixels: left, top, right, bottom.
struct CornerBox {
  double left, top, right, bottom;
};
CornerBox corner_box(const KeptClearCorner& k, const Lens& lens) {
  const double w = lens.width_px, h = lens.height_px;
  const bool left = k.corner == ImageCorner::top_left || k.corner == ImageCorner::bottom_left;
  const bool top = k.corner == ImageCorner::top_left || k.corner == ImageCorner::top_right;
  return {left ? 0.0 : w - k.width_px, top ? 0.0 : h - k.height_px, left ? k.width_px : w, top ? k.height_px : h};
}

// How many of the points project into the corner.
std::size_t points_in_corner(const Camera& camera, const std::vector<GeoPosition>& points, const KeptClearCorner& k) {
  const CornerBox box = corner_box(k, camera.lens());
  std::size_t n = 0;
  for (const GeoPosition& p : points) {
    const auto s = camera.project(ecef_from(p));
    if (s && s->x_px >= box.left && s->x_px <= box.right && s->y_px >= box.top && s->y_px <= box.bottom) ++n;
  }
  return n;
}

TEST(Framing, KeptClearCornerGetsNoPointWhileAllStayInTheImage) {
  // An L: 2 km north, then 2 km east. Seen across its long side (from the south-east), its
  // start is near and on the left: low left in the picture, where a legend goes.
  std::vector<GeoPosition> hike;
  for (int i = 0; i <= 200; ++i) hike.push_back(offset_point(46.69, 7.86, 0.0, 10.0 * i - 2000.0, 900.0));
  for (int i = 1; i <= 200; ++i) hike.push_back(offset_point(46.69, 7.86, 10.0 * i, 0.0, 900.0));
  // A flight climbing 5 km on a 9 km line: its start is low on the left.
  std::vector<GeoPosition> flight;
  for (int i = 0; i < 600; ++i) {
    const double t = i / 600.0;
    flight.push_back(offset_point(47.0, 11.0, 9000.0 * t, 200.0 * std::sin(10.0 * t), 800.0 + 5000.0 * t));
  }
  const Lens lens{kDefaultVerticalFovDeg, 1280, 720};
  for (const auto& [name, track] : {std::pair{"hike", hike}, std::pair{"flight", flight}})
    for (const ImageCorner corner :
         {ImageCorner::bottom_left, ImageCorner::bottom_right, ImageCorner::top_left, ImageCorner::top_right}) {
      SCOPED_TRACE(std::string(name) + " corner " + std::to_string(static_cast<int>(corner)));
      FramingOptions options;
      options.lens = lens;
      const Framing before = framed(track, options);
      options.keep_clear = {corner, 0.3 * lens.width_px, 0.3 * lens.height_px};
      const Framing after = framed(track, options);
      // Without the corner kept clear, the centred framing would have put points into it.
      const std::size_t hidden = points_in_corner(before.camera, track, options.keep_clear);
      if (corner == ImageCorner::bottom_left) {
        EXPECT_GT(hidden, 0u) << "a test that cannot fail";
      }
      if (hidden == 0) {
        EXPECT_EQ(after.look_at.distance_m, before.look_at.distance_m) << "moved without need";
        continue;
      }
      EXPECT_EQ(points_in_corner(after.camera, track, options.keep_clear), 0u);
      const ImageSpan span = expect_inside_with_margin(after.camera, track, options.margin_fraction);
      // The same look direction, the points moved away from the corner rather than shrunk to a dot.
      EXPECT_DOUBLE_EQ(after.look_at.heading_deg, before.look_at.heading_deg);
      EXPECT_DOUBLE_EQ(after.look_at.pitch_deg, before.look_at.pitch_deg);
      EXPECT_LT(after.look_at.distance_m, 1.5 * before.look_at.distance_m);
      const bool left = corner == ImageCorner::top_left || corner == ImageCorner::bottom_left;
      const bool top = corner == ImageCorner::top_left || corner == ImageCorner::top_right;
      const double moved_x = 0.5 * (span.min_x + span.max_x) - 0.5 * lens.width_px;
      const double moved_y = 0.5 * (span.min_y + span.max_y) - 0.5 * lens.height_px;
      EXPECT_GE(left ? moved_x : -moved_x, -1.0);
      EXPECT_GE(top ? moved_y : -moved_y, -1.0);
      EXPECT_GT(std::abs(moved_x) + std::abs(moved_y), 10.0) << "the points' image did not move";
    }
}

TEST(Framing, KeptClearCornerChangesNothingWhenNoPointIsThereOrItCannotBeCleared) {
  // A straight track seen from the side lies across the middle of the picture.
  const std::vector<GeoPosition> track = straight_track(46.69, 7.86, 0.0, 10000.0, 800.0);
  FramingOptions options;
  const Framing plain = framed(track, options);
  options.keep_clear = {ImageCorner::bottom_left, 400.0, 250.0};
  ASSERT_EQ(points_in_corner(plain.camera, track, options.keep_clear), 0u);
  Framing f = framed(track, options);
  EXPECT_EQ(f.look_at.distance_m, plain.look_at.distance_m);
  EXPECT_EQ(f.look_at.target.lat_deg, plain.look_at.target.lat_deg);
  EXPECT_EQ(f.look_at.target.lon_deg, plain.look_at.target.lon_deg);

  // A corner as large as the picture cannot be kept clear: the framing without it.
  options.keep_clear = {ImageCorner::bottom_left, 1920.0, 1080.0};
  f = framed(track, options);
  EXPECT_EQ(f.look_at.distance_m, plain.look_at.distance_m);
  EXPECT_EQ(f.look_at.target.lat_deg, plain.look_at.target.lat_deg);

  // A size that is none.
  options.keep_clear = {ImageCorner::bottom_left, -5.0, 100.0};
  EXPECT_NE(frame_points(track, options).error.find("kept-clear corner"), std::string::npos);
  options.keep_clear = {ImageCorner::bottom_left, std::nan(""), 100.0};
  EXPECT_FALSE(frame_points(track, options).ok());
}

// A viewer's panels leave part of the window free: the points are framed into that area as into
// a whole image (margin inside it, centred in it, spread across it), seen from the same side.
TEST(Framing, AnAreaOfTheImageTakesThePointsAsTheWholeImageWould) {
  const std::vector<GeoPosition> track = loop_track(46.69, 7.86, 30.0, 6000.0, 2500.0, 1200.0);
  FramingOptions options;
  options.lens = {kDefaultVerticalFovDeg, 1280, 720};
  const Framing whole = framed(track, options);
  options.area = ImageArea{350.0, 30.0, 1270.0, 490.0};  // right of a panel column, above a chart
  const Framing f = framed(track, options);
  const ImageArea& a = *options.area;
  const double mx = options.margin_fraction * (a.right_px - a.left_px);
  const double my = options.margin_fraction * (a.bottom_px - a.top_px);
  ImageSpan span;
  for (const GeoPosition& p : track) {
    const auto s = f.camera.project(ecef_from(p));
    ASSERT_TRUE(s);
    span.min_x = std::min(span.min_x, s->x_px), span.max_x = std::max(span.max_x, s->x_px);
    span.min_y = std::min(span.min_y, s->y_px), span.max_y = std::max(span.max_y, s->y_px);
  }
  EXPECT_GE(span.min_x, a.left_px + mx - 0.5);
  EXPECT_LE(span.max_x, a.right_px - mx + 0.5);
  EXPECT_GE(span.min_y, a.top_px + my - 0.5);
  EXPECT_LE(span.max_y, a.bottom_px - my + 0.5);
  EXPECT_NEAR(span.min_x + span.max_x, a.left_px + a.right_px, 2.0);
  EXPECT_NEAR(span.min_y + span.max_y, a.top_px + a.bottom_px, 2.0);
  // Fitted tightly to the area, from the same heading and pitch, further away than for the whole
  // image (the area is smaller).
  EXPECT_TRUE(span.max_x - span.min_x > (a.right_px - a.left_px) - 2.0 * mx - 2.0 ||
              span.max_y - span.min_y > (a.bottom_px - a.top_px) - 2.0 * my - 2.0);
  EXPECT_DOUBLE_EQ(f.look_at.heading_deg, whole.look_at.heading_deg);
  EXPECT_DOUBLE_EQ(f.look_at.pitch_deg, whole.look_at.pitch_deg);
  EXPECT_GT(f.look_at.distance_m, whole.look_at.distance_m);

  // The whole image as the area is the framing without one.
  options.area = ImageArea{0.0, 0.0, 1280.0, 720.0};
  const Framing same = framed(track, options);
  EXPECT_DOUBLE_EQ(same.look_at.distance_m, whole.look_at.distance_m);

  // An area outside the image, empty, NaN, or without the image's centre is an error naming it.
  for (const ImageArea bad : {ImageArea{-10.0, 0.0, 700.0, 500.0}, ImageArea{0.0, 0.0, 1300.0, 500.0},
                              ImageArea{400.0, 300.0, 400.0, 600.0}, ImageArea{std::nan(""), 0.0, 700.0, 500.0},
                              ImageArea{700.0, 0.0, 1280.0, 720.0}, ImageArea{0.0, 400.0, 1280.0, 720.0}}) {
    options.area = bad;
    EXPECT_NE(frame_points(track, options).error.find("framing area"), std::string::npos);
  }
}

// Real flights from ../shared/data: B records of IGC files (latitude, longitude, GPS altitude).
std::vector<GeoPosition> igc_fixes(const std::filesystem::path& file) {
  std::vector<GeoPosition> fixes;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (line.size() < 35 || line[0] != 'B') continue;
    const double lat = std::stod(line.substr(7, 2)) + std::stod(line.substr(9, 5)) / 60000.0;
    const double lon = std::stod(line.substr(15, 3)) + std::stod(line.substr(18, 5)) / 60000.0;
    fixes.push_back({line[14] == 'S' ? -lat : lat, line[23] == 'W' ? -lon : lon, std::stod(line.substr(30, 5))});
  }
  return fixes;
}

TEST(Framing, RealFlightsFit) {
  TRAILRAY_REQUIRE_DATA(paraglider, "igc/goigc_0100_interlaken.igc");
  TRAILRAY_REQUIRE_DATA(sailplane, "igc/goigc_Kz9PYR1v.igc");
  for (const auto& file : {paraglider, sailplane}) {
    const std::vector<GeoPosition> fixes = igc_fixes(file);
    ASSERT_GT(fixes.size(), 1000u) << file;
    const Framing f = framed(fixes);
    const ImageSpan span = expect_inside_with_margin(f.camera, fixes, 0.08);
    EXPECT_GE(span.max_x - span.min_x, 0.5 * 1920.0) << file;
    EXPECT_NEAR(f.camera.pitch_deg(), -45.0, 1.0);
  }
}

}  // namespace
}  // namespace trailray::scene

namespace trailray::scene {
namespace {

// Framing the scene's tracks from their ECEF points (no geodetic conversion) gives the camera
// framing the same points from latitude, longitude and height does.
TEST(Framing, TracksFramedFromTheirEcefPointsAsFromTheirPositions) {
  const std::vector<GeoPosition> points = straight_track(46.7, 7.85, 35.0, 8000.0, 1500.0);
  Track t;
  TrackPolyline line;
  for (const GeoPosition& p : points) {
    line.points_ecef.push_back(ecef_from(p));
    t.altitude_m.push_back(p.height_m);
  }
  t.geometry.segments.push_back(line);
  TrackSet set;
  set.add(t);
  FramingOptions options;
  options.lens = {45.0, 960, 540};
  const auto from_positions = frame_points(points, options);
  const auto from_tracks = frame_tracks(set, options);
  ASSERT_TRUE(from_positions.ok()) << from_positions.error;
  ASSERT_TRUE(from_tracks.ok()) << from_tracks.error;
  EXPECT_LT(glm::length(from_tracks.value->camera.position() - from_positions.value->camera.position()), 0.01);
  EXPECT_NEAR(from_tracks.value->look_at.heading_deg, from_positions.value->look_at.heading_deg, 1e-6);
  EXPECT_DOUBLE_EQ(from_tracks.value->ground_height_m, from_positions.value->ground_height_m);
  set[0].visible = false;
  EXPECT_FALSE(frame_tracks(set, options).ok()) << "only visible tracks are framed";
}

// An area that holds the image's centre only inside its margin (a tall legend under the view)
// is refused by name, not searched in vain: the points' image shrinks toward the centre, which
// would lie outside the box they must fit in.
TEST(Framing, AnAreaWhoseMarginsMissTheCentreIsRefused) {
  const Lens lens{kDefaultVerticalFovDeg, 1280, 720};
  EXPECT_TRUE(area_holds_centre({340.0, 22.0, 1280.0, 494.0}, lens, 0.08));
  EXPECT_FALSE(area_holds_centre({340.0, 22.0, 1280.0, 386.0}, lens, 0.08));  // 360 > 386 - 29
  EXPECT_TRUE(area_holds_centre({340.0, 22.0, 1280.0, 386.0}, lens, 0.0));
  FramingOptions options;
  options.lens = lens;
  options.area = ImageArea{340.0, 22.0, 1280.0, 386.0};
  const auto r = frame_points(straight_track(46.7, 7.85, 35.0, 8000.0, 1500.0), options);
  EXPECT_NE(r.error.find("framing area"), std::string::npos) << r.error;
}

Track track_through(const std::vector<GeoPosition>& points) {
  Track t;
  TrackPolyline line;
  for (const GeoPosition& p : points) {
    line.points_ecef.push_back(ecef_from(p));
    t.altitude_m.push_back(p.height_m);
    t.distance_m.push_back(0.0);
  }
  t.geometry.segments.push_back(line);
  return t;
}

// Flights over several countries: the group is the tracks near the one with the most neighbours,
// in the set's order; hidden tracks and tracks without points are not counted.
TEST(Framing, LargestTrackGroupIsTheTracksNearEachOther) {
  TrackSet set;
  set.add(track_through(straight_track(-43.5, 172.6, 10.0, 9000.0, 900.0)));  // New Zealand
  set.add(track_through(straight_track(46.7, 7.85, 35.0, 8000.0, 1500.0)));   // Interlaken
  set.add(track_through(straight_track(36.6, 32.0, 80.0, 5000.0, 700.0)));    // Alanya
  set.add(track_through(straight_track(47.45, 12.4, 0.0, 6000.0, 1500.0)));   // Kitzbuehel, 350 km east
  set.add(track_through(straight_track(46.6, 10.0, 50.0, 7000.0, 2000.0)));   // the Engadin
  std::vector<const Track*> group = largest_track_group(set);
  ASSERT_EQ(group.size(), 3u);  // the Engadin is within 300 km of Interlaken and of Kitzbuehel
  EXPECT_EQ(group[0], &set[1]);
  EXPECT_EQ(group[1], &set[3]);
  EXPECT_EQ(group[2], &set[4]);
  // A smaller radius: each alone; the first of equals wins.
  group = largest_track_group(set, 50000.0);
  ASSERT_EQ(group.size(), 1u);
  EXPECT_EQ(group[0], &set[0]);
  set[4].visible = false;  // without the Engadin, Interlaken and Kitzbuehel are 350 km apart
  group = largest_track_group(set);
  ASSERT_EQ(group.size(), 1u);
  EXPECT_EQ(group[0], &set[0]);
  // The group frames: all its points in the image.
  set[4].visible = true;
  group = largest_track_group(set);
  FramingOptions options;
  options.lens = {45.0, 960, 540};
  const auto framed = frame_tracks(group, options);
  ASSERT_TRUE(framed.ok()) << framed.error;
  for (const Track* t : group)
    for (const glm::dvec3& p : t->geometry.segments[0].points_ecef) EXPECT_TRUE(framed.value->camera.project(p));
  EXPECT_LT(framed.value->look_at.distance_m, 1.5e6);  // a view of the region, not of the globe
  EXPECT_TRUE(largest_track_group(TrackSet{}).empty());
}

}  // namespace
}  // namespace trailray::scene
