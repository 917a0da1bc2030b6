// The viewer's track model: per-point arrays (distance, time, altitude, ground, speed), the same
// geometry whether built for the viewer or for `render`, statistics of a range equal to `stats` of a file holding only
// that range, colour-by and curtain changes, the effective colour scale, and the tooltip's text.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "app/view/viewer_ui.hpp"
#include "scene/scene.hpp"
#include "scene/tracks/track_building.hpp"
#include "track/summary.hpp"
#include "ui/tooltip.hpp"
#include "ui/viewer_model.hpp"
#include "viewer_test_tracks.hpp"

namespace trailray::app::view {
namespace {

using namespace test_tracks;

// Two segments of 11 points, 100 m and 10 s apart, the second 5 km further east and 10 minutes
// later, at 500 m then 700 m.
std::vector<scene::LoadedTrackFile> two_segment_file() {
  return {file_of("walk.gpx", {track_of("walk", {line(11, 100.0, 10.0, 500.0),
                                                 line(11, 100.0, 10.0, 700.0, 5000.0, kT0 + 600.0)})})};
}

TEST(ViewerTrack, PerPointArraysFollowTheCleanedTrackAcrossSegments) {
  const auto tracks = viewer_tracks(two_segment_file());
  ASSERT_EQ(tracks.size(), 1u);
  const scene::Track& t = tracks[0];
  EXPECT_EQ(t.name, "walk");
  EXPECT_EQ(t.source, "walk.gpx");
  ASSERT_EQ(t.point_count(), 22u);
  EXPECT_EQ(t.segment_first, (std::vector<std::size_t>{0, 11}));
  EXPECT_EQ(t.segment_of(10), 0u);
  EXPECT_EQ(t.segment_of(11), 1u);
  EXPECT_EQ(t.segment_of(21), 1u);
  // Distance: 100 m a step within a segment, nothing across the gap.
  EXPECT_DOUBLE_EQ(t.distance_m[0], 0.0);
  EXPECT_NEAR(t.distance_m[10], 1000.0, 5.0);
  EXPECT_DOUBLE_EQ(t.distance_m[11], t.distance_m[10]);
  EXPECT_NEAR(t.distance_m[21], 2000.0, 10.0);
  for (std::size_t i = 1; i < t.point_count(); ++i) EXPECT_GE(t.distance_m[i], t.distance_m[i - 1]);
  // Time and elapsed time.
  EXPECT_DOUBLE_EQ(t.time_unix_s[3], kT0 + 30.0);
  EXPECT_DOUBLE_EQ(t.time_unix_s[11], kT0 + 600.0);
  EXPECT_DOUBLE_EQ(t.elapsed(11), 600.0);
  EXPECT_EQ(t.start_time(), kT0);
  EXPECT_EQ(t.end_time(), kT0 + 700.0);
  EXPECT_DOUBLE_EQ(t.altitude_m[5], 500.0);
  EXPECT_DOUBLE_EQ(t.altitude_m[15], 700.0);
  // 100 m per 10 s = 36 km/h, level.
  EXPECT_NEAR(t.speed_kmh[5], 36.0, 0.5);
  EXPECT_NEAR(t.vspeed_ms[5], 0.0, 1e-9);
  // No terrain, no heart rate.
  EXPECT_TRUE(std::isnan(t.ground_m[5]));
  EXPECT_TRUE(std::isnan(t.heart_rate(5)));
  EXPECT_TRUE(t.heart_rate_bpm.empty());  // no memory for a channel never recorded
  // Statistics as `stats` prints them.
  EXPECT_EQ(t.summary.clean.points, 22u);
  EXPECT_NEAR(t.summary.clean.distance_2d_m, 2000.0, 10.0);
}

TEST(ViewerTrack, GeometryAndColoursAreTheSameAsRendersBuild) {
  const auto files = two_segment_file();
  StyleArgs args;
  args.color_by = "speed";
  const auto tracks = viewer_tracks(files, args);
  struct {
    std::vector<scene::Track> tracks;
  } scene;
  scene::CollectedDiagnostics ignored;
  scene.tracks = scene::build_tracks(files, parse_style(args).tracks, {}, ignored);
  ASSERT_EQ(tracks.size(), scene.tracks.size());
  const scene::Track& t = tracks[0];
  ASSERT_EQ(t.geometry.segments.size(), scene.tracks[0].geometry.segments.size());
  std::size_t flat = 0;
  for (std::size_t s = 0; s < t.geometry.segments.size(); ++s) {
    const auto& mine = t.geometry.segments[s];
    const auto& theirs = scene.tracks[0].geometry.segments[s];
    ASSERT_EQ(mine.points_ecef.size(), theirs.points_ecef.size());
    for (std::size_t i = 0; i < mine.points_ecef.size(); ++i, ++flat) {
      EXPECT_EQ(mine.points_ecef[i], theirs.points_ecef[i]);
      EXPECT_EQ(t.ecef(flat), theirs.points_ecef[i]);
      EXPECT_EQ(mine.values[i], theirs.values[i]);
    }
  }
  EXPECT_EQ(t.color_srgb, scene.tracks[0].color_srgb);
}

TEST(ViewerTrack, RoutesAndSeveralTracksKeepRendersOrderAndNames) {
  scene::LoadedTrackFile f =
      file_of("day.gpx", {track_of("", {line(3, 100.0, 10.0, 500.0)}), track_of("b", {line(4, 100.0, 10.0, 500.0)})});
  f.file.routes.push_back({"planned", line(5, 100.0, kNoTime, 500.0).points});
  const auto tracks = viewer_tracks({f});
  ASSERT_EQ(tracks.size(), 3u);
  EXPECT_EQ(tracks[0].name, "day.gpx #1");
  EXPECT_EQ(tracks[0].point_count(), 3u);
  EXPECT_EQ(tracks[1].name, "b");
  EXPECT_EQ(tracks[1].point_count(), 4u);
  EXPECT_EQ(tracks[2].name, "planned");
  EXPECT_EQ(tracks[2].point_count(), 5u);
  EXPECT_FALSE(tracks[2].start_time().has_value());
}

TEST(ViewerTrack, RangeStatisticsAreStatsOfTheCutTrack) {
  const auto tracks = viewer_tracks(two_segment_file());
  const scene::Track& t = tracks[0];
  // Points 4..15: the end of segment 1 and the start of segment 2.
  const auto cut = cut_track(t, 4, 15);
  ASSERT_EQ(cut.segments.size(), 2u);
  EXPECT_EQ(cut.segments[0].points.size(), 7u);
  EXPECT_EQ(cut.segments[1].points.size(), 5u);
  const auto range = range_statistics(t, 4, 15);
  ASSERT_TRUE(range.has_value());
  // `stats` of a file holding just those points (raw: it cleans them itself).
  const track::Track file_part = track_of(
      "part", {line(7, 100.0, 10.0, 500.0, 400.0, kT0 + 40.0), line(5, 100.0, 10.0, 700.0, 5000.0, kT0 + 600.0)});
  const track::Statistics expected = track::summarize_track(file_part).clean;
  EXPECT_EQ(range->points, 12u);
  EXPECT_EQ(range->segments, 2u);
  EXPECT_NEAR(range->distance_2d_m, expected.distance_2d_m, 1e-6);
  EXPECT_NEAR(range->distance_2d_m, 1000.0, 5.0);  // 6 + 4 steps of 100 m
  ASSERT_TRUE(range->duration_s && expected.duration_s);
  EXPECT_DOUBLE_EQ(*range->duration_s, *expected.duration_s);
  EXPECT_DOUBLE_EQ(*range->duration_s, 100.0);  // 60 s + 40 s: the gap counts nothing
  EXPECT_EQ(range->moving_time_s, expected.moving_time_s);
  EXPECT_EQ(range->max_speed_kmh.has_value(), expected.max_speed_kmh.has_value());
  EXPECT_NEAR(*range->max_speed_kmh, *expected.max_speed_kmh, 1e-9);
  EXPECT_NEAR(range->min_elevation_m.value_or(0.0), 500.0, 1e-6);  // cleaning goes through ECEF and back
  EXPECT_NEAR(range->max_elevation_m.value_or(0.0), 700.0, 1e-6);
  // The whole track is the track's own clean statistics; an empty or reversed range is none.
  const auto whole = range_statistics(t, 0, 1000);
  ASSERT_TRUE(whole.has_value());
  EXPECT_EQ(whole->points, t.summary.clean.points);
  EXPECT_DOUBLE_EQ(whole->distance_2d_m, t.summary.clean.distance_2d_m);
  EXPECT_FALSE(range_statistics(t, 5, 4).has_value());
}

TEST(ViewerTrack, ClimbOfARangeCountsOnlyItsPoints) {
  // Up 100 m over 10 points, down again: each half climbs (descends) what its own cleaned
  // altitudes rise (fall); the smoothing rounds the summit, so that is a little under 100 m.
  track::Segment s = line(21, 100.0, 10.0, 0.0);
  for (int i = 0; i <= 20; ++i)
    s.points[static_cast<std::size_t>(i)].ele = i <= 10 ? 100.0 + 10.0 * i : 200.0 - 10.0 * (i - 10);
  const auto tracks = viewer_tracks({file_of("hill.gpx", {track_of("hill", {s})})});
  const scene::Track& t = tracks[0];
  const auto up = range_statistics(t, 0, 10);
  const auto down = range_statistics(t, 10, 20);
  ASSERT_TRUE(up && down);
  EXPECT_NEAR(up->elevation_gain_m.value_or(-1), t.altitude_m[10] - t.altitude_m[0], 1e-9);
  EXPECT_GT(up->elevation_gain_m.value_or(-1), 90.0);
  EXPECT_NEAR(up->elevation_loss_m.value_or(-1), 0.0, 1e-9);
  EXPECT_NEAR(down->elevation_gain_m.value_or(-1), 0.0, 1e-9);
  EXPECT_NEAR(down->elevation_loss_m.value_or(-1), t.altitude_m[10] - t.altitude_m[20], 1e-9);
  EXPECT_NEAR(up->elevation_gain_m.value_or(-1), t.summary.clean.elevation_gain_m.value_or(-2), 1e-9);
}

TEST(ViewerTrack, ColourByChangesValuesAndRevision) {
  auto tracks = viewer_tracks(two_segment_file());
  scene::Track& t = tracks[0];
  EXPECT_TRUE(t.geometry.segments[0].values.empty());
  const std::uint64_t before = t.revision;
  apply_color_metric(tracks, track::ColorMetric::altitude);
  EXPECT_GT(t.revision, before);
  ASSERT_EQ(t.geometry.segments[1].values.size(), 11u);
  EXPECT_FLOAT_EQ(t.geometry.segments[1].values[3], 700.0f);
  scene::Style settings;
  settings.tracks.color_by = track::ColorMetric::altitude;
  const auto range = scene::color_range(tracks, settings);
  ASSERT_TRUE(range.has_value());
  EXPECT_NEAR(range->min, 500.0, 1e-6);
  EXPECT_NEAR(range->max, 700.0, 1e-6);
  // A manual range wins; a hidden track (or one drawn solid) leaves the automatic range.
  settings.tracks.range = track::ValueRange{0.0, 1000.0};
  EXPECT_EQ(scene::color_range(tracks, settings)->max, 1000.0);
  settings.tracks.range.reset();
  t.visible = false;
  EXPECT_FALSE(scene::color_range(tracks, settings).has_value());
  // Back to solid: no values.
  apply_color_metric(tracks, track::ColorMetric::solid);
  EXPECT_TRUE(t.geometry.segments[0].values.empty());
}

// The viewer keeps the colour scale until what it depends on changes: the metric, the given
// range, a track's visibility, colouring or revision.
TEST(ViewerModel, ColourRangeIsKeptUntilWhatItDependsOnChanges) {
  ViewerModel model;
  model.tracks = viewer_tracks(two_segment_file());
  model.settings.style.tracks.color_by = track::ColorMetric::altitude;
  EXPECT_FALSE(model.color_range().has_value()) << "no values yet: the tracks were built solid";
  apply_color_metric(model.tracks, track::ColorMetric::altitude);  // a new revision
  ASSERT_TRUE(model.color_range().has_value());
  EXPECT_NEAR(model.color_range()->max, 700.0, 1e-6);
  // Values changed in place without a new revision are not seen (the revision is the contract)...
  model.tracks[0].geometry.segments[1].values.assign(11, 900.0f);
  EXPECT_NEAR(model.color_range()->max, 700.0, 1e-6);
  // ...and are once the revision says so.
  model.tracks[0].bump_revision();
  EXPECT_NEAR(model.color_range()->max, 900.0, 1e-6);
  model.tracks[0].visible = false;
  EXPECT_FALSE(model.color_range().has_value());
  model.tracks[0].visible = true;
  model.settings.style.tracks.range = track::ValueRange{0.0, 50.0};
  EXPECT_EQ(model.color_range()->max, 50.0);
  model.settings.style.tracks.color_by = track::ColorMetric::solid;
  EXPECT_FALSE(model.color_range().has_value());
}

TEST(ViewerTrack, CurtainHeightsFromAltitudeAndGround) {
  auto tracks = viewer_tracks(two_segment_file());
  scene::Track& t = tracks[0];
  std::vector<std::vector<double>> ground{std::vector<double>(11, 420.0), std::vector<double>(11, track::kMissing)};
  scene::fill_point_arrays(t, ground);
  apply_curtain(tracks, true);
  ASSERT_EQ(t.geometry.segments[0].heights_above_ground_m.size(), 11u);
  EXPECT_FLOAT_EQ(t.geometry.segments[0].heights_above_ground_m[2], 80.0f);
  EXPECT_TRUE(std::isnan(t.geometry.segments[1].heights_above_ground_m[2]));
  apply_curtain(tracks, false);
  EXPECT_TRUE(t.geometry.segments[0].heights_above_ground_m.empty());
  // Where the ground is unknown, down to the neutral ground (as the tracks are built).
  apply_curtain(tracks, true, 450.0);
  EXPECT_FLOAT_EQ(t.geometry.segments[0].heights_above_ground_m[2], 80.0f);
  EXPECT_FLOAT_EQ(t.geometry.segments[1].heights_above_ground_m[2],
                  static_cast<float>(t.altitude_m[t.segment_first[1] + 2] - 450.0));
}

TEST(ViewerTrack, FillPointArraysRejectsMismatchedGround) {
  auto tracks = viewer_tracks(two_segment_file());
  EXPECT_THROW(scene::fill_point_arrays(tracks[0], {std::vector<double>(11, 0.0)}), std::invalid_argument);
  EXPECT_THROW(scene::fill_point_arrays(tracks[0], {std::vector<double>(11, 0.0), std::vector<double>(3, 0.0)}),
               std::invalid_argument);
}

TEST(Tooltip, KnownPointReadsItsValuesWithUnits) {
  track::Segment s = line(11, 100.0, 10.0, 500.0);
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    s.points[i].ele = 500.0 + 5.0 * static_cast<double>(i);  // 0.5 m/s up
    s.points[i].heart_rate = 140.0f;
  }
  auto tracks = viewer_tracks({file_of("climb.gpx", {track_of("climb", {s})})});
  scene::fill_point_arrays(tracks[0], {std::vector<double>(11, 450.0)});
  const auto lines = tooltip_lines(tracks[0], 4);
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0], "time: 2024-06-18 10:00:40 UTC");
  EXPECT_EQ(lines[1], "altitude: 520 m");
  EXPECT_EQ(lines[2], "height above ground: 70 m");
  // 100 m on a sphere of the equatorial radius are 100.17 m on the WGS84 ellipsoid at 46.7 N.
  EXPECT_EQ(lines[3], "speed: 36.1 km/h");
  EXPECT_EQ(lines[4], "vertical speed: 0.5 m/s");
  EXPECT_EQ(lines[5], "heart rate: 140 bpm");
  EXPECT_TRUE(tooltip_lines(tracks[0], 11).empty());
}

TEST(Tooltip, MissingValuesReadADash) {
  const auto tracks = viewer_tracks({file_of("plain.gpx", {track_of("plain", {line(5, 100.0, kNoTime, 500.0)})})});
  const auto lines = tooltip_lines(tracks[0], 2);
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0], "time: \u2014");
  EXPECT_EQ(lines[1], "altitude: 500 m");
  EXPECT_EQ(lines[2], "height above ground: \u2014");  // no terrain
  EXPECT_EQ(lines[3], "speed: \u2014");
  EXPECT_EQ(lines[4], "vertical speed: \u2014");
  EXPECT_EQ(lines[5], "heart rate: \u2014");
}

}  // namespace
}  // namespace trailray::app::view
