// The film's overlay (scene/film/film_overlay): the clock's text, the gauges read at a position
// between two points, the glide ratio only while sinking, panels painted where they are said to
// be and nothing painted with `none`.

#include <gtest/gtest.h>

#include <cmath>

#include "scene/film/film_overlay.hpp"
#include "scene/film/film_profile.hpp"
#include "scene/tracks/track_building.hpp"
#include "track/metrics.hpp"

namespace trailray::scene {
namespace {

TEST(FilmOverlay, ClockTextIsUtc) {
  EXPECT_EQ(film_clock_text(1718704800.0), "2024-06-18 10:00:00 UTC");
  EXPECT_EQ(film_clock_text(1718704800.0 + 3600 * 14 + 61.7), "2024-06-19 00:01:01 UTC");
  EXPECT_EQ(film_clock_text(951782400.0), "2000-02-29 00:00:00 UTC");
}

TEST(FilmOverlay, GaugesAreInterpolatedAtThePosition) {
  Track t;
  t.name = "Glider";
  t.altitude_m = {1000.0, 900.0};
  t.ground_m = {500.0, 600.0};
  t.speed_kmh = {36.0, 36.0};
  t.vspeed_ms = {-1.0, -1.0};
  t.heart_rate_bpm = {std::nan(""), std::nan("")};
  t.cadence_rpm = {std::nan(""), std::nan("")};
  t.power_w = {std::nan(""), std::nan("")};
  const GaugeReadings g = gauge_readings(t, {true, true, 0, 0.25, {}});
  EXPECT_DOUBLE_EQ(g.altitude_m, 975.0);
  EXPECT_DOUBLE_EQ(g.ground_m, 525.0);
  const std::vector<std::string> lines = gauge_lines(g);
  const std::vector<std::string> expected{"Alt 975 m", "AGL 450 m", "Speed 36 km/h", "Vario -1.0 m/s", "Glide 10.0"};
  EXPECT_EQ(lines, expected);
  // Climbing: no glide ratio; no heart rate where none was recorded.
  t.vspeed_ms = {2.0, 2.0};
  const auto climbing = gauge_lines(gauge_readings(t, {true, true, 0, 0.0, {}}));
  for (const std::string& l : climbing) {
    EXPECT_EQ(l.find("Glide"), std::string::npos) << l;
    EXPECT_EQ(l.find("HR"), std::string::npos) << l;
    EXPECT_EQ(l.find("Cadence"), std::string::npos) << l;
    EXPECT_EQ(l.find("Power"), std::string::npos) << l;
  }
}

// A ride's recorded channels reach the gauges from the track's points (through the scene track's
// per-point numbers), interpolated at the position; a point without power leaves the last value
// known before it; a track that never recorded them has no such gauges.
TEST(FilmOverlay, CadenceAndPowerGaugesWhenTheTrackRecordsThem) {
  track::Track ride;
  ride.segments.resize(1);
  for (int i = 0; i < 3; ++i) {
    track::TrackPoint p;
    p.lat = 46.7;
    p.lon = 7.85 + 0.001 * i;
    p.ele = 600.0;
    p.time = 1718704800.0 + 10.0 * i;
    p.heart_rate = 140.0f;
    p.cadence = 80.0f + 10.0f * static_cast<float>(i);                             // 80, 90, 100 rpm
    p.power = i == 2 ? track::kMissingF : 200.0f + 40.0f * static_cast<float>(i);  // 200, 240, none
    ride.segments[0].points.push_back(p);
  }
  Track t;
  t.name = "Ride";
  t.cleaned = ride;
  fill_point_arrays(t);
  ASSERT_EQ(t.cadence_rpm.size(), 3u);
  ASSERT_EQ(t.power_w.size(), 3u);
  EXPECT_TRUE(std::isnan(t.power_w[2]));

  const GaugeReadings quarter = gauge_readings(t, {true, true, 0, 0.3, {}});
  EXPECT_NEAR(quarter.cadence_rpm, 83.0, 1e-9);
  EXPECT_NEAR(quarter.power_w, 212.0, 1e-9);
  const std::vector<std::string> lines = gauge_lines(quarter);
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[lines.size() - 3], "HR 140 bpm");
  EXPECT_EQ(lines[lines.size() - 2], "Cadence 83 rpm");
  EXPECT_EQ(lines.back(), "Power 212 W");
  // Past the last point with power: that point's value, not a blend with "none".
  const GaugeReadings late = gauge_readings(t, {true, true, 1, 0.5, {}});
  EXPECT_DOUBLE_EQ(late.cadence_rpm, 95.0);
  EXPECT_DOUBLE_EQ(late.power_w, 240.0);
  // At the point without power: no power gauge, cadence still there.
  const std::vector<std::string> last = gauge_lines(gauge_readings(t, {true, true, 2, 0.0, {}}));
  EXPECT_EQ(last.back(), "Cadence 100 rpm");

  // The panel grows by those two lines.
  TextRasterizer text;
  GaugeReadings without = quarter;
  without.cadence_rpm = without.power_w = std::nan("");
  const auto with_panels = film_overlay_panels(640, 360, text, OverlayLevel::full, {quarter});
  const auto without_panels = film_overlay_panels(640, 360, text, OverlayLevel::full, {without});
  ASSERT_EQ(with_panels.size(), 2u);
  ASSERT_EQ(without_panels.size(), 2u);
  EXPECT_GT(with_panels[1].height, without_panels[1].height);
}

std::size_t changed_pixels(const RgbaImage& a, const RgbaImage& b, const PixelRect& inside) {
  std::size_t n = 0;
  for (std::uint32_t y = 0; y < a.height; ++y)
    for (std::uint32_t x = 0; x < a.width; ++x)
      if (inside.contains(static_cast<int>(x), static_cast<int>(y)) && a.pixel(x, y) != b.pixel(x, y)) ++n;
  return n;
}

TEST(FilmOverlay, PanelsArePaintedWhereTheySayAndNoneIsNothing) {
  RgbaImage blank{320, 180, std::vector<std::uint8_t>(320 * 180 * 4, 200)};
  TextRasterizer text;
  const std::vector<GaugeReadings> gauges{
      {"Glider", 975.0, 500.0, 36.0, -1.0, std::nan(""), std::nan(""), std::nan("")}};
  RgbaImage none = blank;
  EXPECT_TRUE(draw_film_overlay(none, text, OverlayLevel::none, 1718704800.0, gauges).empty());
  EXPECT_EQ(none.rgba, blank.rgba);

  RgbaImage full = blank;
  const auto rects = draw_film_overlay(full, text, OverlayLevel::full, 1718704800.0, gauges);
  ASSERT_EQ(rects.size(), 2u);  // the clock, one gauge panel
  const auto measured = film_overlay_panels(320, 180, text, OverlayLevel::full, gauges);
  ASSERT_EQ(measured.size(), rects.size());
  for (std::size_t i = 0; i < rects.size(); ++i) {
    EXPECT_EQ(measured[i].x, rects[i].x);
    EXPECT_EQ(measured[i].y, rects[i].y);
    EXPECT_EQ(measured[i].width, rects[i].width);
    EXPECT_EQ(measured[i].height, rects[i].height);
  }
  EXPECT_LT(rects[0].x, 160);  // the clock top left
  EXPECT_GT(rects[1].x, 160);  // the gauges top right
  for (const PixelRect& r : rects)
    EXPECT_GT(changed_pixels(full, blank, r), static_cast<std::size_t>(r.width * r.height / 2));
  // Nothing outside the panels changed.
  std::size_t outside = 0;
  for (std::uint32_t y = 0; y < 180; ++y)
    for (std::uint32_t x = 0; x < 320; ++x) {
      const bool in = rects[0].contains(static_cast<int>(x), static_cast<int>(y)) ||
                      rects[1].contains(static_cast<int>(x), static_cast<int>(y));
      if (!in && full.pixel(x, y) != blank.pixel(x, y)) ++outside;
    }
  EXPECT_EQ(outside, 0u);

  RgbaImage minimal = blank;
  EXPECT_EQ(draw_film_overlay(minimal, text, OverlayLevel::minimal, 1718704800.0, gauges).size(), 1u);
  // The map data's credits: one more panel, bottom right.
  RgbaImage credited = blank;
  const auto with_credits =
      draw_film_overlay(credited, text, OverlayLevel::minimal, 1718704800.0, gauges, "DEM: swisstopo");
  ASSERT_EQ(with_credits.size(), 2u);
  EXPECT_GT(with_credits[1].y, 120);
  EXPECT_GT(with_credits[1].x, 160);
  EXPECT_GT(changed_pixels(credited, blank, with_credits[1]), 10u);
}

TEST(FilmProfile, ClimbsWithTheTrackAndMarksNow) {
  // 11 points 10 s apart climbing from 1000 m to 2000 m over flat ground at 900 m.
  Track t;
  t.geometry.segments.resize(1);
  for (int i = 0; i <= 10; ++i) {
    t.geometry.segments[0].points_ecef.push_back(glm::dvec3(6.4e6, i * 100.0, 0.0));
    t.distance_m.push_back(i * 100.0);
    t.time_unix_s.push_back(1718704800.0 + i * 10.0);
    t.timed_points.push_back(static_cast<std::uint32_t>(i));
    t.altitude_m.push_back(1000.0 + i * 100.0);
    t.ground_m.push_back(900.0);
  }
  t.segment_first = {0};
  const TimeSpan span{1718704800.0, 1718704900.0};
  const FilmProfile p = film_profile(t, span, 50);
  ASSERT_EQ(p.altitude_m.size(), 50u);
  EXPECT_DOUBLE_EQ(p.altitude_m.front(), 1000.0);
  EXPECT_DOUBLE_EQ(p.altitude_m.back(), 2000.0);
  EXPECT_LT(p.low_m, 900.0);
  EXPECT_GT(p.high_m, 2000.0);

  RgbaImage image{320, 180, std::vector<std::uint8_t>(320 * 180 * 4, 200)};
  const PixelRect panel = draw_film_profile(image, p, span.start + 25.0);  // a quarter through
  ASSERT_FALSE(panel.empty());
  EXPECT_GT(panel.x, 160);  // bottom right
  EXPECT_GT(panel.y, 90);
  // The red "now" line stands a quarter of the way across; no red column elsewhere.
  const auto red_rows = [&](int x) {
    int n = 0;
    for (int y = panel.y; y < panel.bottom(); ++y) {
      const auto px = image.pixel(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
      n += px[0] > 200 && px[1] < 100 && px[2] < 100 ? 1 : 0;
    }
    return n;
  };
  int best = 0, best_x = 0;
  for (int x = panel.x; x < panel.right(); ++x)
    if (red_rows(x) > best) best = red_rows(x), best_x = x;
  EXPECT_GT(best, panel.height / 2);
  EXPECT_NEAR(best_x, panel.x + 4 + 0.25 * (panel.width - 9), 2.0);
  // The line climbs: white higher at the right end than at the left.
  const auto white_row = [&](int x) {
    for (int y = panel.y; y < panel.bottom(); ++y) {
      const auto px = image.pixel(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
      if (px[0] > 240 && px[1] > 240 && px[2] > 240) return y;
    }
    return -1;
  };
  const int left = white_row(panel.x + 4), right = white_row(panel.right() - 5);  // the first and last columns
  ASSERT_GE(left, 0);
  ASSERT_GE(right, 0);
  EXPECT_LT(right, left - panel.height / 3);
  // Without altitudes: nothing drawn.
  RgbaImage untouched{320, 180, std::vector<std::uint8_t>(320 * 180 * 4, 200)};
  EXPECT_TRUE(draw_film_profile(untouched, FilmProfile{}, span.start).empty());
  EXPECT_EQ(untouched.rgba, std::vector<std::uint8_t>(320 * 180 * 4, 200));
}

}  // namespace
}  // namespace trailray::scene
