// What the legend says about a track scene: a colour bar titled with the metric and unit, its
// ends formatted as the metric prints them (checked against the values the track pipeline
// computes for a track whose speed doubles halfway), a "0" on signed scales; a key of names
// only for several solid tracks; --legend off draws nothing, on draws only in the bottom-left.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/options/style_options.hpp"
#include "app/track_cli_support.hpp"
#include "scene/pictures/rgba_image.hpp"
#include "scene/text/legend.hpp"
#include "scene/text/legend_content.hpp"
#include "scene/tracks/track_building.hpp"
#include "track/clean.hpp"
#include "track/color_values.hpp"
#include "track/metrics.hpp"

namespace trailray::app {
namespace {

constexpr double kLat = 46.70, kLon = 7.85;
constexpr double kT0 = 1718704800.0;  // 2024-06-18T10:00:00Z

track::Segment segment_of(const std::vector<test::GpxPoint>& points) {
  track::Segment s;
  for (const auto& g : points) {
    track::TrackPoint p;
    p.lat = g.lat;
    p.lon = g.lon;
    p.ele = g.ele;
    p.time = g.time;
    s.points.push_back(p);
  }
  return s;
}

// Points every 10 s: 40 of them 28 m apart (10.08 km/h), then 40 more 56 m apart (20.16 km/h).
track::Track doubling_speed_track() {
  auto points = test::east_line(kLat, kLon, 0.0, 40, 28.0, kT0, 10.0, 1000.0);
  const auto fast = test::east_line(kLat, kLon, 40 * 28.0, 40, 56.0, kT0 + 400.0, 10.0, 1000.0);
  points.insert(points.end(), fast.begin(), fast.end());
  track::Track t;
  t.name = "Doubling";
  t.segments.push_back(segment_of(points));
  return t;
}

track::Track east_track(const std::string& name, double north_m) {
  track::Track t;
  t.name = name;
  t.segments.push_back(segment_of(test::east_line(kLat, kLon, 0.0, 10, 30.0, kT0, 10.0, 1000.0, north_m)));
  return t;
}

std::vector<scene::LoadedTrackFile> files_with(std::vector<track::Track> tracks) {
  scene::LoadedTrackFile f;
  f.path = "tracks.gpx";
  f.file.tracks = std::move(tracks);
  return {f};
}

scene::Style style_of(const std::string& metric, const std::string& colormap = {}, const std::string& legend = "on") {
  StyleArgs args;
  args.color_by = metric;
  args.colormap = colormap;
  args.legend = legend;
  return parse_style(args);
}

// The files' tracks as `render` builds them, and the scene that draws them in a style.
struct TestScene {
  scene::TrackSet tracks;
  scene::Scene scene;

  TestScene(const std::vector<scene::LoadedTrackFile>& files, const scene::Style& style) {
    scene::CollectedDiagnostics ignored;
    for (scene::Track& t : scene::build_tracks(files, style.tracks, {}, ignored)) tracks.add(std::move(t));
    scene.tracks = &tracks;
    scene.style = style;
    scene.color_range = scene::color_range(tracks, style);
  }
  TestScene(const TestScene&) = delete;
  TestScene& operator=(const TestScene&) = delete;
};

TestScene scene_of(const std::vector<scene::LoadedTrackFile>& files, const scene::Style& style) {
  return TestScene(files, style);
}

// The legend's content and drawing for the scene's tracks in `style` (which may differ from the
// one the tracks were built in, e.g. the legend switched off).
std::optional<scene::ColorLegend> color_legend_for(const scene::Style& style, const TestScene& built) {
  return scene::color_legend_for(style.tracks, built.scene.color_range);
}
std::vector<scene::TrackKeyEntry> track_key_for(const scene::Style& style, const TestScene& built) {
  return scene::track_key_for(style.tracks, built.tracks);
}
scene::Scene restyled(const TestScene& built, const scene::Style& style) {
  scene::Scene s = built.scene;
  s.style = style;
  return s;
}
void draw_scene_legend(scene::RgbaImage& image, const scene::Style& style, const TestScene& built) {
  scene::draw_scene_legend(image, restyled(built, style));
}
scene::PixelRect scene_legend_panel(std::uint32_t width, std::uint32_t height, const scene::Style& style,
                                    const TestScene& built) {
  return scene::scene_legend_panel(width, height, restyled(built, style));
}
using scene::legend_clearance;

scene::RgbaImage grey_image(std::uint32_t width, std::uint32_t height) {
  return {width, height, std::vector<std::uint8_t>(std::size_t{width} * height * 4, 128)};
}

TEST(TrackLegend, SpeedDoublingHalfwayGivesTheRangeOfItsTwoSpeeds) {
  const track::Track raw = doubling_speed_track();
  const scene::Style style = style_of("speed");
  const TestScene scene = scene_of(files_with({raw}), style);
  const auto legend = color_legend_for(style, scene);
  ASSERT_TRUE(legend.has_value());
  EXPECT_EQ(legend->title, "Speed (km/h)");
  EXPECT_EQ(legend->map, scene::Colormap::turbo);
  EXPECT_TRUE(legend->ticks.empty()) << "speed is not signed: no 0 tick";

  // The expected ends straight from the track pipeline: cleaned as the scene cleans, the metric
  // per point, its robust range, printed as the metric prints values.
  track::CleanReport report;
  const track::AnalysisOptions analysis;
  const track::Track cleaned = track::clean_track(raw, analysis.clean, report);
  const auto values =
      track::color_values(cleaned, track::compute_metrics(cleaned, analysis.metrics), track::ColorMetric::speed);
  const auto range = track::robust_range(values, false);
  ASSERT_TRUE(range.has_value());
  EXPECT_EQ(legend->min_label, track::format_color_value(track::ColorMetric::speed, range->min));
  EXPECT_EQ(legend->max_label, track::format_color_value(track::ColorMetric::speed, range->max));
  // And those are the two speeds of the track: 2.8 m/s and 5.6 m/s.
  EXPECT_NEAR(std::atof(legend->min_label.c_str()), 10.08, 0.15) << legend->min_label;
  EXPECT_NEAR(std::atof(legend->max_label.c_str()), 20.16, 0.15) << legend->max_label;
}

TEST(TrackLegend, RangeFromTheOptionIsWhatTheLegendShows) {
  StyleArgs args;
  args.color_by = "speed";
  args.range = "5:35";
  args.colormap = "viridis";
  const scene::Style style = parse_style(args);
  const auto legend = color_legend_for(style, scene_of(files_with({doubling_speed_track()}), style));
  ASSERT_TRUE(legend.has_value());
  EXPECT_EQ(legend->min_label, "5.0");
  EXPECT_EQ(legend->max_label, "35.0");
  EXPECT_EQ(legend->map, scene::Colormap::viridis);
}

TEST(TrackLegend, VerticalSpeedIsDivergingWithAZeroTick) {
  track::Track t = doubling_speed_track();
  auto& points = t.segments[0].points;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double n = static_cast<double>(i);
    points[i].ele = 1000.0 + (i < 40 ? 4.0 * n : 160.0 - 2.0 * (n - 40.0));
  }
  const scene::Style style = style_of("vspeed");
  const auto legend = color_legend_for(style, scene_of(files_with({t}), style));
  ASSERT_TRUE(legend.has_value());
  EXPECT_EQ(legend->title, "Vertical speed (m/s)");
  EXPECT_EQ(legend->map, scene::Colormap::diverging);
  ASSERT_EQ(legend->ticks.size(), 1u);
  EXPECT_EQ(legend->ticks[0].label, "0");
  EXPECT_NEAR(legend->ticks[0].position, 0.5, 1e-9) << "the range is symmetric about 0";
  EXPECT_EQ(legend->min_label.front(), '-') << legend->min_label;
}

TEST(TrackLegend, ElapsedTimeIsTitledInHoursAndMinutes) {
  const scene::Style style = style_of("time");
  const auto legend = color_legend_for(style, scene_of(files_with({doubling_speed_track()}), style));
  ASSERT_TRUE(legend.has_value());
  EXPECT_EQ(legend->title, "Elapsed time (h:mm)");
  EXPECT_NE(legend->max_label.find(':'), std::string::npos) << legend->max_label;
}

TEST(TrackLegend, NoColourBarForSolidTracksOrWithoutValues) {
  const scene::Style solid = style_of("solid");
  EXPECT_FALSE(color_legend_for(solid, scene_of(files_with({doubling_speed_track()}), solid)));
  // Heart rate: this track recorded none.
  const scene::Style hr = style_of("hr");
  EXPECT_FALSE(color_legend_for(hr, scene_of(files_with({doubling_speed_track()}), hr)));
}

TEST(TrackLegend, KeyListsSeveralSolidTracksByNameAndColour) {
  const scene::Style solid = style_of("solid");
  const TestScene scene =
      scene_of(files_with({east_track("Alpha", 0.0), east_track("", 300.0), east_track("Gamma", 600.0)}), solid);
  const auto key = track_key_for(solid, scene);
  ASSERT_EQ(key.size(), 3u);
  EXPECT_EQ(key[0].name, "Alpha");
  EXPECT_EQ(key[1].name, "tracks.gpx #2");
  EXPECT_EQ(key[2].name, "Gamma");
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(key[i].color_srgb, scene::palette_color(i)) << i;
}

TEST(TrackLegend, OneTrackOrColourByValueGetsNoKey) {
  const scene::Style solid = style_of("solid");
  EXPECT_TRUE(track_key_for(solid, scene_of(files_with({east_track("Alone", 0.0)}), solid)).empty());
  const scene::Style speed = style_of("speed");
  EXPECT_TRUE(
      track_key_for(speed, scene_of(files_with({east_track("A", 0.0), east_track("B", 300.0)}), speed)).empty());
}

// --legend off leaves the picture alone; on, only the bottom-left quarter changes (the panel).
TEST(TrackLegend, DrawnInTheBottomLeftOnlyWhenOn) {
  const auto files = files_with({doubling_speed_track()});
  for (const char* metric : {"speed", "solid"}) {
    const auto several = files_with({east_track("A", 0.0), east_track("B", 300.0)});
    const auto& used = std::string(metric) == "solid" ? several : files;
    const scene::Style on = style_of(metric), off = style_of(metric, {}, "off");
    const TestScene scene = scene_of(used, on);
    const scene::RgbaImage blank = grey_image(640, 360);
    scene::RgbaImage with = blank, without = blank;
    draw_scene_legend(with, on, scene);
    draw_scene_legend(without, off, scene);
    EXPECT_EQ(without.rgba, blank.rgba) << metric << ": --legend off drew something";
    std::size_t changed = 0;
    for (std::uint32_t y = 0; y < blank.height; ++y)
      for (std::uint32_t x = 0; x < blank.width; ++x)
        if (with.pixel(x, y) != blank.pixel(x, y)) {
          ++changed;
          ASSERT_LT(x, blank.width / 2) << metric << ": legend pixel right of the middle at " << x << "," << y;
          ASSERT_GE(y, blank.height / 2) << metric << ": legend pixel above the middle at " << x << "," << y;
        }
    EXPECT_GT(changed, 1000u) << metric << ": a panel with text";
  }
}

// What the framing keeps clear: the panel draw_scene_legend draws (measured, not drawn), and
// around it the gap it keeps from the edges; nothing with --legend off or without a legend.
TEST(TrackLegend, ClearanceIsTheDrawnPanelWithItsGap) {
  const auto files = files_with({doubling_speed_track()});
  const auto several = files_with({east_track("A", 0.0), east_track("B", 300.0)});
  for (const char* metric : {"speed", "solid"}) {
    SCOPED_TRACE(metric);
    const scene::Style on = style_of(metric), off = style_of(metric, {}, "off");
    const TestScene scene = scene_of(std::string(metric) == "solid" ? several : files, on);
    scene::RgbaImage image = grey_image(640, 360);
    const scene::RgbaImage blank = image;
    draw_scene_legend(image, on, scene);
    // The smallest rectangle around the changed pixels lies inside the measured panel.
    const scene::PixelRect panel = scene_legend_panel(640, 360, on, scene);
    ASSERT_FALSE(panel.empty());
    int min_x = 640, max_x = -1, min_y = 360, max_y = -1;
    for (std::uint32_t y = 0; y < 360; ++y)
      for (std::uint32_t x = 0; x < 640; ++x)
        if (image.pixel(x, y) != blank.pixel(x, y)) {
          min_x = std::min(min_x, int(x)), max_x = std::max(max_x, int(x));
          min_y = std::min(min_y, int(y)), max_y = std::max(max_y, int(y));
        }
    EXPECT_TRUE(panel.contains(scene::PixelRect{min_x, min_y, max_x - min_x + 1, max_y - min_y + 1}));
    EXPECT_LE(panel.width - (max_x - min_x + 1), 2);
    EXPECT_LE(panel.height - (max_y - min_y + 1), 2);

    const scene::KeptClearCorner clear = legend_clearance(panel, 360);
    EXPECT_EQ(clear.corner, scene::ImageCorner::bottom_left);
    EXPECT_DOUBLE_EQ(clear.width_px, panel.right() + panel.x);
    EXPECT_DOUBLE_EQ(clear.height_px, 360 - panel.y + (360 - panel.bottom()));
    EXPECT_TRUE(scene_legend_panel(640, 360, off, scene).empty());
    EXPECT_TRUE(legend_clearance(scene_legend_panel(640, 360, off, scene), 360).empty());
  }
  const scene::Style solid = style_of("solid");
  EXPECT_TRUE(scene_legend_panel(640, 360, solid, scene_of(files_with({east_track("Alone", 0.0)}), solid)).empty());
}

TEST(TrackLegend, OneSolidTrackDrawsNoLegend) {
  const scene::Style solid = style_of("solid");
  const TestScene scene = scene_of(files_with({east_track("Alone", 0.0)}), solid);
  const scene::RgbaImage blank = grey_image(320, 180);
  scene::RgbaImage image = blank;
  draw_scene_legend(image, solid, scene);
  EXPECT_EQ(image.rgba, blank.rgba);
}

}  // namespace
}  // namespace trailray::app
