// The density view and the thermal map on built scene tracks: the counts each point gets, routes
// left out, the whole-number scale, the legend naming the radius, recounting with another
// radius; flights climbing in the same thermal counted together, and no climb at all a warning.
#include "scene/tracks/track_density.hpp"

#include <gtest/gtest.h>

#include <GeographicLib/Geodesic.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "track/flight/synthetic_flight.hpp"
#include "scene/text/legend_content.hpp"
#include "scene/scene.hpp"
#include "scene/tracks/track_building.hpp"

namespace trailray::scene {
namespace {

// A line northwards over 2 km, `east` metres east of (46.5, 7.5), a fix every 20 m.
std::vector<track::TrackPoint> line_at(double east) {
  std::vector<track::TrackPoint> out;
  const auto& g = GeographicLib::Geodesic::WGS84();
  for (double s = 0; s <= 2000; s += 20) {
    double lat = 0, lon = 0;
    track::TrackPoint p;
    g.Direct(46.5, 7.5, 0.0, s, lat, lon);
    g.Direct(lat, lon, 90.0, east, p.lat, p.lon);
    p.ele = 800;
    out.push_back(p);
  }
  return out;
}

LoadedTrackFile file_of(const std::string& name, std::vector<track::TrackPoint> points) {
  LoadedTrackFile f;
  f.path = name + ".gpx";
  track::Track t;
  t.segments.push_back({std::move(points)});
  f.file.tracks.push_back(std::move(t));
  return f;
}

std::vector<Track> built(const std::vector<LoadedTrackFile>& files, track::ColorMetric metric,
                         std::optional<double> radius, CollectedDiagnostics& diagnostics) {
  TrackStyle style;
  style.color_by = metric;
  style.neighbour_radius_m = radius;
  return build_tracks(files, style, {}, diagnostics);
}

bool all_equal(const std::vector<float>& values, float v) {
  return !values.empty() && std::all_of(values.begin(), values.end(), [v](float x) { return x == v; });
}

TEST(TrackDensity, EachPointCountsTheTracksWithinTheRadiusItsOwnIncluded) {
  // a and b 60 m apart, c 300 m away; a planned route right on a (not counted, keeps its metres).
  std::vector<LoadedTrackFile> files{file_of("a", line_at(0)), file_of("b", line_at(60)), file_of("c", line_at(300))};
  track::Route route;
  route.points = line_at(0);
  files[0].file.routes.push_back(route);
  CollectedDiagnostics diagnostics;
  std::vector<Track> tracks = built(files, track::ColorMetric::density, std::nullopt, diagnostics);
  ASSERT_EQ(tracks.size(), 4u);
  EXPECT_TRUE(tracks[1].is_route);
  EXPECT_TRUE(all_equal(tracks[0].geometry.segments.at(0).values, 2.0f));
  EXPECT_TRUE(all_equal(tracks[2].geometry.segments.at(0).values, 2.0f));
  EXPECT_TRUE(all_equal(tracks[3].geometry.segments.at(0).values, 1.0f));
  EXPECT_EQ(tracks[1].geometry.segments.at(0).values.back(), 2000.0f) << "the route's metres along it";
  EXPECT_TRUE(diagnostics.warnings.empty());

  // The scale: whole numbers from 1; the legend says what they count and within what.
  TrackSet set;
  for (Track& t : tracks) set.add(t);
  Style style;
  style.tracks.color_by = track::ColorMetric::density;
  const auto range = color_range(set, style);
  ASSERT_TRUE(range);
  EXPECT_EQ(range->min, 1.0);
  EXPECT_EQ(range->max, 2.0);
  const auto legend = color_legend_for(style.tracks, range);
  ASSERT_TRUE(legend);
  EXPECT_EQ(legend->title, "Tracks within 100 m (own included)");
  EXPECT_EQ(legend->min_label, "1");
  EXPECT_EQ(legend->max_label, "2");
  EXPECT_EQ(style.tracks.colormap, Colormap::turbo) << "the style as given";
  EXPECT_EQ(default_colormap(track::ColorMetric::density), Colormap::magma);

  // A wider radius takes c in: every track counts 3; the revision changes.
  const auto revision = tracks[0].revision;
  EXPECT_EQ(apply_neighbour_counts(tracks, track::ColorMetric::density, 400.0), 3u);
  EXPECT_GT(tracks[0].revision, revision);
  for (std::size_t i : {0u, 2u, 3u}) EXPECT_TRUE(all_equal(tracks[i].geometry.segments.at(0).values, 3.0f)) << i;
  style.tracks.neighbour_radius_m = 1500.0;
  EXPECT_EQ(color_legend_for(style.tracks, range)->title, "Tracks within 1.5 km (own included)");

  EXPECT_THROW(apply_neighbour_counts(tracks, track::ColorMetric::speed, 100.0), std::invalid_argument);
  EXPECT_THROW(apply_neighbour_counts(tracks, track::ColorMetric::density, 0.1), std::invalid_argument);
}

TEST(TrackDensity, SwitchingAMetricAwayAndBackKeepsTheShapes) {
  CollectedDiagnostics diagnostics;
  std::vector<Track> tracks =
      built({file_of("a", line_at(0)), file_of("b", line_at(50))}, track::ColorMetric::speed, 100.0, diagnostics);
  for (Track& t : tracks) apply_color_metric(t, track::ColorMetric::density);
  EXPECT_TRUE(std::isnan(tracks[0].geometry.segments[0].values.front())) << "no count before all are counted";
  apply_neighbour_counts(tracks, track::ColorMetric::density, 100.0);
  EXPECT_EQ(tracks[0].geometry.segments[0].values.size(), tracks[0].cleaned.segments[0].points.size());
  EXPECT_TRUE(all_equal(tracks[1].geometry.segments[0].values, 2.0f));
}

// A flight from the simulator's start: `glide_s` s of glide towards `heading`, then a 2 m/s
// thermal, a glide and the landing.
track::Track flight(double heading, int glide_s) {
  track::test::SyntheticFlight sim;
  sim.ground(120);
  sim.glide(glide_s, heading);
  sim.circle(180, true, 2.0);
  sim.glide(200, heading + 180.0);
  sim.ground(60);
  return sim.track();
}

TEST(TrackDensity, ThermalsCountTheFlightsThatClimbedNearby) {
  // a and b climb in the same thermal 1.2 km north of the start; c in its own, 6 km east.
  std::vector<LoadedTrackFile> files(3);
  for (std::size_t i = 0; i < 3; ++i) files[i].path = "flight" + std::to_string(i) + ".igc";
  files[0].file.tracks.push_back(flight(0.0, 120));
  files[1].file.tracks.push_back(flight(0.0, 120));
  files[2].file.tracks.push_back(flight(90.0, 600));
  CollectedDiagnostics diagnostics;
  const std::vector<Track> tracks = built(files, track::ColorMetric::thermals, std::nullopt, diagnostics);
  ASSERT_EQ(tracks.size(), 3u);
  EXPECT_TRUE(diagnostics.warnings.empty());
  for (std::size_t i = 0; i < 3; ++i) {
    const Track& t = tracks[i];
    ASSERT_TRUE(t.flights);
    ASSERT_EQ(t.flights->flights.size(), 1u);
    ASSERT_EQ(t.flights->flights[0].thermals.size(), 1u);
    const auto& thermal = t.flights->flights[0].thermals[0];
    const auto& points = t.cleaned.segments.at(0).points;
    const auto& values = t.geometry.segments.at(0).values;
    ASSERT_EQ(values.size(), points.size());
    int in_thermal = 0, far = 0;
    for (std::size_t k = 0; k < points.size(); ++k) {
      if (points[k].time > thermal.start.time + 5 && points[k].time < thermal.end.time - 5) {
        EXPECT_EQ(values[k], i < 2 ? 2.0f : 1.0f) << "flight " << i << " in its thermal";
        ++in_thermal;
      } else if (points[k].time < thermal.start.time - 60) {
        EXPECT_EQ(values[k], 0.0f) << "flight " << i << " before its thermal";
        ++far;
      }
    }
    EXPECT_GT(in_thermal, 100);
    EXPECT_GT(far, 30);
  }
  TrackSet set;
  for (const Track& t : tracks) set.add(t);
  Style style;
  style.tracks.color_by = track::ColorMetric::thermals;
  const auto range = color_range(set, style);
  ASSERT_TRUE(range);
  EXPECT_EQ(range->min, 0.0);
  EXPECT_EQ(range->max, 2.0);
  EXPECT_EQ(color_legend_for(style.tracks, range)->title, "Flights climbing within 200 m (own included)");
}

TEST(TrackDensity, ThermalsWithoutAnyClimbSayWhy) {
  CollectedDiagnostics diagnostics;
  const std::vector<Track> tracks = built({file_of("walk", line_at(0))}, track::ColorMetric::thermals, {}, diagnostics);
  ASSERT_EQ(tracks.size(), 1u);
  EXPECT_TRUE(all_equal(tracks[0].geometry.segments[0].values, 0.0f));
  ASSERT_EQ(diagnostics.warnings.size(), 1u);
  EXPECT_NE(diagnostics.warnings[0].find("no flight climbed"), std::string::npos) << diagnostics.warnings[0];
}

}  // namespace
}  // namespace trailray::scene
