// --color-by phase and thermal markers on a simulated flight whose thermals and glides are known
// (tests/track/flight/synthetic_flight.hpp): circling points carry their climb, gliding points
// the category value, the ground none; one marker per thermal at its top with its label; the
// legend's bar and key.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "track/flight/synthetic_flight.hpp"
#include "scene/text/legend_content.hpp"
#include "scene/scene.hpp"
#include "scene/pins/thermal_markers.hpp"
#include "scene/tracks/track_building.hpp"
#include "track/color_values.hpp"

namespace trailray::scene {
namespace {

using track::test::SyntheticFlight;

struct Simulated {
  track::Track track;
  double takeoff = 0, t1 = 0, t1_end = 0, t2 = 0, t2_end = 0, landing = 0;
};

// Ground, a glide, a 2 m/s thermal (right), a long glide, a 1 m/s thermal (left), a glide, ground.
Simulated simulated_flight() {
  Simulated s;
  SyntheticFlight sim;
  sim.ground(120);
  s.takeoff = sim.time();
  sim.glide(120, 0.0);
  s.t1 = sim.time();
  sim.circle(180, true, 2.0);
  s.t1_end = sim.time();
  sim.glide(300, 90.0, 10.0, 1.5);
  s.t2 = sim.time();
  sim.circle(160, false, 1.0, 50.0, 11.0);
  s.t2_end = sim.time();
  sim.glide(200, 330.0);
  s.landing = sim.time();
  sim.ground(120);
  s.track = sim.track();
  s.track.name = "sim";
  return s;
}

std::vector<Track> built(const Simulated& s, track::ColorMetric metric, bool analyse = false) {
  LoadedTrackFile loaded;
  loaded.path = "sim.igc";
  loaded.file.tracks.push_back(s.track);
  TrackStyle style;
  style.color_by = metric;
  TrackBuildOptions options;
  options.analyse_flights = analyse;
  CollectedDiagnostics diagnostics;
  return build_tracks({loaded}, style, options, diagnostics);
}

// The values of the drawn points by time: the middle of each known leg.
TEST(FlightPhaseScene, CirclingCarriesItsClimbGlidingTheCategoryGroundNothing) {
  const Simulated s = simulated_flight();
  const auto tracks = built(s, track::ColorMetric::phase);
  ASSERT_EQ(tracks.size(), 1u);
  const Track& t = tracks[0];
  ASSERT_TRUE(t.flights);
  ASSERT_EQ(t.geometry.segments.size(), 1u);
  const auto& values = t.geometry.segments[0].values;
  const auto& points = t.cleaned.segments[0].points;
  ASSERT_EQ(values.size(), points.size());
  int ground = 0, gliding = 0, first = 0, second = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double time = points[i].time;
    const float v = values[i];
    if (time < s.takeoff - 10 || time > s.landing + 10) {
      EXPECT_TRUE(std::isnan(v)) << "on the ground at " << time - s.takeoff << " s: " << v;
      ++ground;
    } else if (time > s.t1 + 20 && time < s.t1_end - 20) {
      EXPECT_NEAR(v, 2.0, 0.1) << "in the first thermal at " << time - s.takeoff << " s";
      ++first;
    } else if (time > s.t2 + 20 && time < s.t2_end - 20) {
      EXPECT_NEAR(v, 1.0, 0.1) << "in the second thermal at " << time - s.takeoff << " s";
      ++second;
    } else if ((time > s.takeoff + 20 && time < s.t1 - 20) || (time > s.t1_end + 20 && time < s.t2 - 20) ||
               (time > s.t2_end + 20 && time < s.landing - 20)) {
      EXPECT_TRUE(track::is_category_value(v)) << "gliding at " << time - s.takeoff << " s: " << v;
      ++gliding;
    }
  }
  // Cleaning drops most of the standing points, keeps the flying ones.
  EXPECT_GE(ground, 2);
  EXPECT_GT(first, 100);
  EXPECT_GT(second, 90);
  EXPECT_GT(gliding, 400);

  // The scale: from 0 to the best climbs; the category left out of it.
  TrackSet set;
  set.add(t);
  Style style;
  style.tracks.color_by = track::ColorMetric::phase;
  const auto range = color_range(set, style);
  ASSERT_TRUE(range);
  EXPECT_EQ(range->min, 0.0);
  EXPECT_NEAR(range->max, 2.0, 0.15);
}

TEST(FlightPhaseScene, SwitchingToPhaseAndBackRecolours) {
  const Simulated s = simulated_flight();
  auto tracks = built(s, track::ColorMetric::speed, true);
  Track& t = tracks.at(0);
  const auto revision = t.revision;
  apply_color_metric(t, track::ColorMetric::phase);
  EXPECT_GT(t.revision, revision);
  const auto& values = t.geometry.segments[0].values;
  EXPECT_GT(std::count_if(values.begin(), values.end(), track::is_category_value), 400);
  // Without the analysis, phase cannot be coloured: a clear error, not a wrong picture.
  auto plain = built(s, track::ColorMetric::speed, false);
  EXPECT_FALSE(plain.at(0).flights);
  EXPECT_THROW(apply_color_metric(plain.at(0), track::ColorMetric::phase), std::invalid_argument);
}

TEST(FlightPhaseScene, OneMarkerPerThermalAtItsTopWithItsLabel) {
  const Simulated s = simulated_flight();
  const auto tracks = built(s, track::ColorMetric::solid, true);
  const std::vector<Waypoint> markers = thermal_markers(tracks.at(0));
  ASSERT_EQ(markers.size(), 2u);
  const auto& thermals = tracks.at(0).flights->flights.at(0).thermals;
  ASSERT_EQ(thermals.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const Waypoint& w = markers[k];
    const auto& th = thermals[k];
    EXPECT_EQ(w.kind, WaypointKind::Thermal);
    EXPECT_EQ(w.ele_m, th.end.alt);  // the top: where the glider left it
    EXPECT_EQ(w.time_unix_s, th.end.time);
    EXPECT_EQ(w.marker_ecef, w.ground_ecef);  // a flag on the track, not a pole from the ground
    EXPECT_EQ(w.priority, static_cast<int>(std::lround(th.gain_m)));
  }
  // Known climbs: 2 m/s for 180 s from the glide's end, 1 m/s for 160 s.
  EXPECT_GT(markers[0].ele_m - thermals[0].start.alt, 300.0);
  // The thermal's edges blur by a few seconds of glide (the analysis' turn window): near 2 and 1.
  EXPECT_NEAR(thermals[0].mean_climb_ms, 2.0, 0.15);
  EXPECT_NEAR(thermals[1].mean_climb_ms, 1.0, 0.15);
  for (std::size_t k = 0; k < 2; ++k)
    EXPECT_EQ(markers[k].name, fmt::format("{:+.1f} m/s \u00b7 {}\u2192{} m", thermals[k].mean_climb_ms,
                                           std::lround(thermals[k].start.alt), std::lround(thermals[k].end.alt)));
  // Stronger thermals win the label space.
  EXPECT_GT(markers[0].priority, markers[1].priority);
}

TEST(FlightPhaseScene, LabelSignsAndRounding) {
  track::flight::Thermal th;
  th.mean_climb_ms = -0.26;
  th.start.alt = 1650.4;
  th.end.alt = 1600.0;
  EXPECT_EQ(thermal_label(th), "\u22120.3 m/s \u00b7 1650\u21921600 m");
  th.mean_climb_ms = 0.04;
  EXPECT_EQ(thermal_label(th).substr(0, 8), "0.0 m/s ");
  th.mean_climb_ms = 2.35;
  th.start.alt = 1650;
  th.end.alt = 2380;
  EXPECT_EQ(thermal_label(th), "+2.4 m/s \u00b7 1650\u21922380 m");
}

TEST(FlightPhaseScene, NoThermalNoMarker) {
  SyntheticFlight sim;
  sim.ground(60);
  sim.glide(600, 45.0);
  sim.ground(60);
  LoadedTrackFile loaded;
  loaded.path = "glide.igc";
  loaded.file.tracks.push_back(sim.track());
  TrackBuildOptions options;
  options.analyse_flights = true;
  CollectedDiagnostics diagnostics;
  const auto tracks = build_tracks({loaded}, {}, options, diagnostics);
  ASSERT_TRUE(tracks.at(0).flights);
  EXPECT_EQ(tracks.at(0).flights->flights.size(), 1u);
  EXPECT_TRUE(thermal_markers(tracks.at(0)).empty());
}

TEST(FlightPhaseScene, LegendIsTheClimbBarOverAKeyOfGlidingAndNoValue) {
  TrackStyle style;
  style.color_by = track::ColorMetric::phase;
  style.colormap = default_colormap(style.color_by);
  EXPECT_EQ(style.colormap, Colormap::warm);
  const auto legend = color_legend_for(style, track::ValueRange{0.0, 2.5});
  ASSERT_TRUE(legend);
  EXPECT_EQ(legend->title, "Climb in thermals (m/s)");
  EXPECT_EQ(legend->min_label, "0.0");
  EXPECT_EQ(legend->max_label, "2.5");
  EXPECT_TRUE(legend->ticks.empty());
  const auto key = track_key_for(style, TrackSet{});
  ASSERT_EQ(key.size(), 2u);
  EXPECT_EQ(key[0].name, "gliding");
  EXPECT_EQ(key[0].color_srgb, kCategoryColorSrgb);
  EXPECT_EQ(key[1].color_srgb, kMissingValueColorSrgb);
  // The gliding colour is unlike every climb colour and unlike no value.
  for (float x = 0.0f; x <= 1.0f; x += 0.05f)
    EXPECT_GT(glm::length(colormap_color(Colormap::warm, x) - kCategoryColorSrgb), 0.4f) << x;
  EXPECT_GT(glm::length(kMissingValueColorSrgb - kCategoryColorSrgb), 0.3f);

  // Drawn into a picture: the key at the bottom, the bar above it, both inside the panel.
  TrackSet tracks;
  Scene scene;
  scene.tracks = &tracks;
  scene.style.tracks = style;
  scene.color_range = track::ValueRange{0.0, 2.5};
  const PixelRect panel = scene_legend_panel(1280, 720, scene);
  TextRasterizer text;
  const PixelRect key_panel = track_key_panel(1280, 720, text, key);
  EXPECT_FALSE(key_panel.empty());
  EXPECT_TRUE(panel.contains(key_panel));
  EXPECT_LT(panel.y, key_panel.y - key_panel.height / 2);  // the bar above the key
  RgbaImage image{1280, 720, std::vector<std::uint8_t>(std::size_t{1280} * 720 * 4, 255)};
  const RgbaImage before = image;
  draw_scene_legend(image, scene);
  // Something drawn above the key's panel (the bar's), nothing outside the panel.
  bool above = false, outside = false;
  for (int y = 0; y < 720; ++y)
    for (int x = 0; x < 1280; ++x) {
      const bool changed = image.pixel(x, y) != before.pixel(x, y);
      if (changed && y < key_panel.y) above = true;
      if (changed && !panel.contains(x, y)) outside = true;
    }
  EXPECT_TRUE(above);
  EXPECT_FALSE(outside);
}

}  // namespace
}  // namespace trailray::scene
