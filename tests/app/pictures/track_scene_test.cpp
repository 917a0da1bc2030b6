// scene::build_tracks on track files held in memory: segments and points kept (empty segments
// dropped, gaps not joined), routes drawn as tracks, names, colour values per point (NaN where a
// point has none, never Inf), the colour scale's range (--range over automatic), --color once
// or per track, points without elevation on the ground, curtain heights.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/options/style_options.hpp"
#include "app/track_model_builders.hpp"
#include "scene/camera/camera.hpp"
#include "scene/pictures/colormap.hpp"
#include "scene/scene.hpp"
#include "scene/tracks/track_building.hpp"
#include "terrain/synthetic_height_source.hpp"
#include "track/clean.hpp"
#include "track/color_values.hpp"
#include "track/metrics.hpp"
#include "track/summary.hpp"

namespace trailray::app {
namespace {

using namespace test_tracks;  // line, track_of, file_of, kLat, kLon, kT0

scene::Style style_of(StyleArgs args = {}) { return parse_style(args); }

scene::Style style_by(const std::string& metric, const std::string& range = {}) {
  StyleArgs args;
  args.color_by = metric;
  args.range = range;
  return parse_style(args);
}

struct Warnings {
  scene::CollectedDiagnostics diagnostics;
  const std::vector<std::string>& seen = diagnostics.warnings;
};

// The tracks of the files as `render` builds them, the colour scale over them, their points.
struct Built {
  scene::TrackSet tracks;
  std::optional<track::ValueRange> range;
  std::size_t points = 0;
};

Built build_with(const std::vector<scene::LoadedTrackFile>& files, const scene::Style& style,
                 const scene::TrackBuildOptions& options, Warnings* warnings = nullptr) {
  Warnings ignored;
  Built out;
  for (scene::Track& t :
       scene::build_tracks(files, style.tracks, options, (warnings != nullptr ? warnings : &ignored)->diagnostics)) {
    out.points += t.point_count();
    out.tracks.add(std::move(t));
  }
  out.range = scene::color_range(out.tracks, style);
  return out;
}

Built build(const std::vector<scene::LoadedTrackFile>& files, const scene::Style& style, Warnings* warnings = nullptr,
            bool smooth = true) {
  scene::TrackBuildOptions options;
  options.neutral_ground_m = 900.0;
  options.analysis.clean.smooth = smooth;
  return build_with(files, style, options, warnings);
}

TEST(TrackScene, KeepsSegmentsAndPointsAndDropsEmptySegments) {
  const auto files =
      std::vector{file_of("walk.gpx", {track_of("Walk", {line(20, 25.0, 10.0, 1000.0), track::Segment{},
                                                         line(15, 25.0, 10.0, 1000.0, 2000.0, kT0 + 1000.0)})})};
  const Built scene = build(files, style_of());
  ASSERT_EQ(scene.tracks.size(), 1u);
  const auto& segments = scene.tracks[0].geometry.segments;
  ASSERT_EQ(segments.size(), 2u) << "the empty segment is dropped, the two others stay apart";
  EXPECT_EQ(segments[0].points_ecef.size(), 20u);
  EXPECT_EQ(segments[1].points_ecef.size(), 15u);
  EXPECT_EQ(scene.points, 35u);
  // Solid: no values, no range, no curtain heights.
  EXPECT_TRUE(segments[0].values.empty());
  EXPECT_TRUE(segments[0].heights_above_ground_m.empty());
  EXPECT_FALSE(scene.range.has_value());
  // The gap is not bridged: the second segment starts 2 km east, where its first point is.
  const double gap = glm::length(segments[1].points_ecef.front() - segments[0].points_ecef.back());
  EXPECT_NEAR(gap, 2000.0 - 19 * 25.0, 5.0);
}

TEST(TrackScene, PointsWithoutSmoothingAreTheRecordedOnesInEcef) {
  const track::Segment recorded = line(10, 30.0, 10.0, 1234.0);
  const Built scene = build({file_of("a.gpx", {track_of("A", {recorded})})}, style_of(), nullptr, false);
  ASSERT_EQ(scene.tracks.size(), 1u);
  const auto& points = scene.tracks[0].geometry.segments.at(0).points_ecef;
  ASSERT_EQ(points.size(), recorded.points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = recorded.points[i];
    const glm::dvec3 expected = scene::ecef_from({p.lat, p.lon, p.ele});
    EXPECT_LT(glm::length(points[i] - expected), 1e-6) << "point " << i;
  }
}

TEST(TrackScene, PointsWithoutElevationLieOnTheNeutralGroundAndCurtainsReachIt) {
  StyleArgs args;
  args.curtain = true;
  track::Segment flat = line(8, 30.0, 10.0, track::kMissing);
  track::Segment high = line(8, 30.0, 10.0, 1150.0, 0.0, kT0 + 500.0);
  const Built scene = build({file_of("a.gpx", {track_of("A", {flat, high})})}, style_of(args), nullptr, false);
  const auto& segments = scene.tracks.at(0).geometry.segments;
  ASSERT_EQ(segments.size(), 2u);
  for (std::size_t i = 0; i < flat.points.size(); ++i) {
    const glm::dvec3 ground = scene::ecef_from({flat.points[i].lat, flat.points[i].lon, 900.0});
    EXPECT_LT(glm::length(segments[0].points_ecef[i] - ground), 1e-6) << "point " << i << " is on the ground";
  }
  ASSERT_EQ(segments[0].heights_above_ground_m.size(), flat.points.size());
  ASSERT_EQ(segments[1].heights_above_ground_m.size(), high.points.size());
  for (float h : segments[0].heights_above_ground_m) EXPECT_FLOAT_EQ(h, 0.0f);
  // Without a terrain source the ground is the neutral ground: 1150 - 900 m.
  for (float h : segments[1].heights_above_ground_m) EXPECT_FLOAT_EQ(h, 250.0f);
}

TEST(TrackScene, SpeedValuesOnePerPointAndFinite) {
  // 25 m every 10 s: 9 km/h everywhere.
  const auto files = std::vector{file_of("a.gpx", {track_of("A", {line(30, 25.0, 10.0, 1000.0)})})};
  const Built scene = build(files, style_by("speed"));
  const auto& segment = scene.tracks.at(0).geometry.segments.at(0);
  ASSERT_EQ(segment.values.size(), segment.points_ecef.size());
  for (float v : segment.values) {
    ASSERT_TRUE(std::isfinite(v));
    EXPECT_NEAR(v, 9.0, 0.3);
  }
  EXPECT_EQ(scene.tracks[0].points_with_value(), segment.points_ecef.size());
  ASSERT_TRUE(scene.range.has_value());
  // Every value the same: the range is widened around it, not empty.
  EXPECT_LT(scene.range->min, 9.0);
  EXPECT_GT(scene.range->max, 9.0);
}

TEST(TrackScene, MissingValuesStayNaNAndARangeComesFromTheOthers) {
  // Track B has no times: no speed anywhere on it, NaN (the renderer's neutral colour).
  const auto files = std::vector{file_of("a.gpx", {track_of("A", {line(30, 25.0, 10.0, 1000.0)}),
                                                   track_of("B", {line(30, 25.0, track::kMissing, 1000.0, 0.0)})})};
  Warnings warnings;
  const Built scene = build(files, style_by("speed"), &warnings);
  ASSERT_EQ(scene.tracks.size(), 2u);
  const auto& b = scene.tracks[1].geometry.segments.at(0);
  ASSERT_EQ(b.values.size(), b.points_ecef.size());
  for (float v : b.values) EXPECT_TRUE(std::isnan(v));
  EXPECT_EQ(scene.tracks[1].points_with_value(), 0u);
  EXPECT_EQ(scene.tracks[0].points_with_value(), scene.tracks[0].geometry.segments[0].points_ecef.size());
  ASSERT_TRUE(scene.range.has_value());
  EXPECT_TRUE(std::isfinite(scene.range->min) && std::isfinite(scene.range->max));
  EXPECT_TRUE(warnings.seen.empty());
}

TEST(TrackScene, NoValueAnywhereWarnsAndHasNoRange) {
  const auto files = std::vector{file_of("a.gpx", {track_of("A", {line(30, 25.0, track::kMissing, 1000.0)})})};
  Warnings warnings;
  const Built scene = build(files, style_by("speed"), &warnings);
  EXPECT_FALSE(scene.range.has_value());
  ASSERT_EQ(warnings.seen.size(), 1u);
  EXPECT_NE(warnings.seen[0].find("speed"), std::string::npos) << warnings.seen[0];
  const auto& values = scene.tracks.at(0).geometry.segments.at(0).values;
  ASSERT_FALSE(values.empty());
  for (float v : values) EXPECT_TRUE(std::isnan(v));
}

TEST(TrackScene, AutomaticRangeIsTheRobustRangeOfAllValues) {
  // Speed doubles halfway: 28 m then 56 m every 10 s.
  track::Segment s = line(40, 28.0, 10.0, 1000.0);
  const track::Segment fast = line(40, 56.0, 10.0, 1000.0, 40 * 28.0, kT0 + 400.0);
  s.points.insert(s.points.end(), fast.points.begin(), fast.points.end());
  const auto files = std::vector{file_of("a.gpx", {track_of("A", {s})})};
  const Built scene = build(files, style_by("speed"));
  ASSERT_TRUE(scene.range.has_value());
  std::vector<std::vector<float>> all;
  for (const auto& t : scene.tracks.tracks())
    for (const auto& seg : t.geometry.segments) all.push_back(seg.values);
  const auto expected = track::robust_range(all, false);
  ASSERT_TRUE(expected.has_value());
  EXPECT_DOUBLE_EQ(scene.range->min, expected->min);
  EXPECT_DOUBLE_EQ(scene.range->max, expected->max);
  EXPECT_NEAR(scene.range->min, 28.0 * 0.36, 0.2);
  EXPECT_NEAR(scene.range->max, 56.0 * 0.36, 0.3);

  // --range wins over the automatic one.
  const Built given = build(files, style_by("speed", "0:50"));
  ASSERT_TRUE(given.range.has_value());
  EXPECT_EQ(given.range->min, 0.0);
  EXPECT_EQ(given.range->max, 50.0);
}

// A track keeps no metrics: colouring it again works them out from its cleaned points with the
// options it was built with, so the values equal those of a track built coloured so.
TEST(TrackScene, RecolouringWorksTheMetricsOutAgainWithTheBuildOptions) {
  track::Segment s = line(40, 25.0, 10.0, 1000.0);
  for (std::size_t i = 20; i < s.points.size(); ++i) s.points[i].lat += 0.0009 * static_cast<double>(i - 19);
  const auto files = std::vector{file_of("a.gpx", {track_of("A", {s})})};
  scene::TrackBuildOptions options;
  options.analysis.clean.smooth = false;
  options.analysis.metrics.speed_window_s = 120.0;  // not the default: a wide window
  const Built coloured = build_with(files, style_by("speed"), options);
  Built recoloured = build_with(files, style_of(), options);
  ASSERT_TRUE(recoloured.tracks[0].geometry.segments.at(0).values.empty());
  scene::apply_color_metric(recoloured.tracks[0], track::ColorMetric::speed);
  const auto& want = coloured.tracks[0].geometry.segments.at(0).values;
  const auto& got = recoloured.tracks[0].geometry.segments.at(0).values;
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_FLOAT_EQ(got[i], want[i]) << i;
  // The default window gives other speeds where the pace changes: the options mattered.
  const Built narrow = build(files, style_by("speed"), nullptr, false);
  EXPECT_GT(std::abs(narrow.tracks[0].geometry.segments.at(0).values[20] - want[20]), 1.0f);
}

TEST(TrackScene, VerticalSpeedRangeIsSymmetricAboutZero) {
  track::Segment s = line(40, 20.0, 10.0, 1000.0);
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const double n = static_cast<double>(i);
    s.points[i].ele = 1000.0 + (i < 20 ? 5.0 * n : 100.0 - 2.0 * (n - 20.0));
  }
  const Built scene = build({file_of("a.gpx", {track_of("A", {s})})}, style_by("vspeed"));
  ASSERT_TRUE(scene.range.has_value());
  EXPECT_DOUBLE_EQ(scene.range->min, -scene.range->max);
  EXPECT_NEAR(scene.range->max, 0.5, 0.1);  // 5 m per 10 s climbing
}

TEST(TrackScene, RoutesAreDrawnAsTracks) {
  scene::LoadedTrackFile f = file_of("plan.gpx", {});
  track::Route route;
  route.name = "Planned";
  route.points = line(12, 40.0, track::kMissing, 1000.0).points;
  f.file.routes.push_back(route);
  const Built scene = build({f}, style_of());
  ASSERT_EQ(scene.tracks.size(), 1u);
  EXPECT_EQ(scene.tracks[0].name, "Planned");
  ASSERT_EQ(scene.tracks[0].geometry.segments.size(), 1u);
  EXPECT_EQ(scene.tracks[0].geometry.segments[0].points_ecef.size(), 12u);
}

TEST(TrackScene, NamesAreTheTracksOwnElseTheFileNameAndNumber) {
  scene::LoadedTrackFile several =
      file_of("/some/folder/walk.gpx",
              {track_of("Morning", {line(5, 30.0, 10.0, 1000.0)}), track_of("", {line(5, 30.0, 10.0, 1000.0, 500.0)})});
  track::Route route;
  route.points = line(5, 30.0, track::kMissing, 1000.0, 1000.0).points;
  several.file.routes.push_back(route);
  const scene::LoadedTrackFile single =
      file_of("other/ride.gpx", {track_of("", {line(5, 30.0, 10.0, 1000.0, 2000.0)})});
  const Built scene = build({several, single}, style_of());
  ASSERT_EQ(scene.tracks.size(), 4u);
  EXPECT_EQ(scene.tracks[0].name, "Morning");
  EXPECT_EQ(scene.tracks[1].name, "walk.gpx #2");
  EXPECT_EQ(scene.tracks[2].name, "walk.gpx #3");
  EXPECT_EQ(scene.tracks[3].name, "ride.gpx");
}

TEST(TrackScene, ColoursFromThePaletteOnceOrPerTrack) {
  const auto files = std::vector{file_of(
      "a.gpx", {track_of("A", {line(5, 30.0, 10.0, 1000.0)}), track_of("B", {line(5, 30.0, 10.0, 1000.0, 500.0)}),
                track_of("C", {line(5, 30.0, 10.0, 1000.0, 1000.0)})})};
  const Built palette = build(files, style_of());
  ASSERT_EQ(palette.tracks.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(palette.tracks[i].color_srgb, scene::palette_color(i)) << i;
  EXPECT_NE(palette.tracks[0].color_srgb, palette.tracks[1].color_srgb);

  StyleArgs once;
  once.colors = {"#00ff00"};
  const Built one_colour = build(files, style_of(once));
  for (const auto& t : one_colour.tracks.tracks()) EXPECT_EQ(t.color_srgb, glm::vec3(0.0f, 1.0f, 0.0f));

  StyleArgs each;
  each.colors = {"#ff0000", "#00ff00", "#0000ff"};
  const Built per_track = build(files, style_of(each));
  EXPECT_EQ(per_track.tracks[0].color_srgb, glm::vec3(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(per_track.tracks[1].color_srgb, glm::vec3(0.0f, 1.0f, 0.0f));
  EXPECT_EQ(per_track.tracks[2].color_srgb, glm::vec3(0.0f, 0.0f, 1.0f));

  StyleArgs two;
  two.colors = {"#ff0000", "#00ff00"};
  try {
    build(files, style_of(two));
    FAIL() << "two colours for three tracks were accepted";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("--color"), std::string::npos) << message;
    EXPECT_NE(message.find("once per track"), std::string::npos) << message;
  }
}

TEST(TrackScene, HeightAboveGroundNeedsTerrain) {
  const auto files = std::vector{file_of("a.gpx", {track_of("A", {line(5, 30.0, 10.0, 1000.0)})})};
  try {
    build(files, style_by("agl"));
    FAIL() << "agl without terrain was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("--terrain"), std::string::npos) << e.what();
  }
}

// Each track's cleaned points and metrics come out with the geometry, the same as cleaning the
// raw track again would give; with `inspect` (the viewer) its summary too, which `render` does
// not need.
TEST(TrackScene, KeptAnalysisIsTheCleanedTrackAndItsSummary) {
  track::Segment noisy = line(30, 25.0, 5.0, 800.0);
  noisy.points[10].ele = 5000.0;  // a spike cleaning removes or flattens
  const track::Track raw = track_of("A", {noisy, track::Segment{}, line(8, 40.0, 5.0, 900.0, 2000.0, kT0 + 900.0)});
  const auto files = std::vector{file_of("a.gpx", {raw})};
  scene::TrackBuildOptions inputs;
  inputs.neutral_ground_m = 900.0;
  inputs.inspect = true;
  const Built kept = build_with(files, style_by("speed"), inputs);
  ASSERT_EQ(kept.tracks.size(), 1u);
  const scene::Track& t = kept.tracks[0];

  track::CleanReport report;
  const track::Track cleaned = track::clean_track(raw, inputs.analysis.clean, report);
  ASSERT_EQ(t.cleaned.segments.size(), 3u);  // the empty segment too: indices match the raw track
  for (std::size_t s = 0; s < 3; ++s) {
    ASSERT_EQ(t.cleaned.segments[s].points.size(), cleaned.segments[s].points.size()) << s;
    for (std::size_t i = 0; i < cleaned.segments[s].points.size(); ++i)
      EXPECT_EQ(t.cleaned.segments[s].points[i].ele, cleaned.segments[s].points[i].ele) << s << " " << i;
  }
  const track::TrackSummary expected = track::summarize_track(raw, inputs.analysis);
  EXPECT_EQ(t.summary.raw.points, expected.raw.points);
  EXPECT_EQ(t.summary.clean.points, expected.clean.points);
  EXPECT_DOUBLE_EQ(t.summary.raw.distance_2d_m, expected.raw.distance_2d_m);
  EXPECT_DOUBLE_EQ(t.summary.clean.distance_2d_m, expected.clean.distance_2d_m);
  EXPECT_EQ(t.summary.clean.max_elevation_m, expected.clean.max_elevation_m);
  EXPECT_EQ(t.summary.raw.max_elevation_m, expected.raw.max_elevation_m);
  EXPECT_DOUBLE_EQ(*t.summary.raw.max_elevation_m, 5000.0);
  ASSERT_EQ(t.summary.segments.size(), 3u);
  EXPECT_EQ(t.summary.segments[2].clean.points, expected.segments[2].clean.points);
  for (double h : t.ground_m) EXPECT_TRUE(std::isnan(h)) << "no terrain was given";

  // The drawn points are the kept ones.
  ASSERT_EQ(t.geometry.segments.size(), 2u);
  EXPECT_EQ(t.geometry.segments[1].points_ecef.size(), t.cleaned.segments[2].points.size());

  const Built plain = build(files, style_by("speed"), nullptr, true);
  EXPECT_EQ(plain.tracks[0].cleaned.segments.size(), 3u);
  EXPECT_EQ(plain.tracks[0].summary.raw.points, 0u) << "no summary without inspect";
}

// With terrain the viewer gets the ground below every point, not only where a metric needs it.
TEST(TrackScene, KeptAnalysisHasTheGroundBelowEveryPointWithTerrain) {
  test::SyntheticHeightSource heights(65, terrain::SampleLayout::pixel_is_point, 12);
  const auto files = std::vector{file_of("a.gpx", {track_of("A", {line(6, 30.0, 10.0, 1500.0)})})};
  scene::TrackBuildOptions inputs;
  inputs.heights = &heights;
  inputs.inspect = true;
  const Built scene = build_with(files, style_of(), inputs);
  ASSERT_EQ(scene.tracks.size(), 1u);
  const scene::Track& t = scene.tracks[0];
  ASSERT_EQ(t.ground_m.size(), t.cleaned.segments[0].points.size());
  for (double h : t.ground_m) {
    EXPECT_TRUE(std::isfinite(h));
    EXPECT_GT(h, 100.0);  // the synthetic plane rises from 100 m at the world's corner
  }
  // Without inspect the ground is sampled only where the style needs it: not here.
  inputs.inspect = false;
  const Built plain = build_with(files, style_of(), inputs);
  for (double h : plain.tracks[0].ground_m) EXPECT_TRUE(std::isnan(h));
}

}  // namespace
}  // namespace trailray::app
