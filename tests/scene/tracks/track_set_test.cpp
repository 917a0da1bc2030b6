// The scene's track set: ids that stay with a track and differ between tracks, flat point
// numbers across segments (the chart, picking and the replay share them), the first and last
// timestamps, the colour scale over the visible tracks coloured by value.

#include "scene/tracks/track_set.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "scene/scene.hpp"

namespace trailray::scene {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A track of two drawn segments of 3 and 2 points; times on all but the first point; values
// 1..5 (by flat index) when `valued`.
Track two_segments(bool valued = true) {
  Track t;
  t.name = "t";
  t.segment_first = {0, 3};
  TrackPolyline a, b;
  a.points_ecef = {{1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  b.points_ecef = {{10, 0, 0}, {11, 0, 0}};
  if (valued) {
    a.values = {1, 2, 3};
    b.values = {4, 5};
  }
  t.geometry.segments = {a, b};
  t.time_unix_s = {kNaN, 100.0, 110.0, 200.0, 210.0};
  t.distance_m.assign(5, 0.0);
  return t;
}

TEST(TrackSet, IdsAreNewForEveryTrackAndFindThem) {
  TrackSet set;
  const TrackId a = set.add(two_segments());
  const TrackId b = set.add(two_segments());
  EXPECT_NE(a, b);
  ASSERT_NE(set.find(a), nullptr);
  EXPECT_EQ(set.find(a), &set[0]);
  EXPECT_EQ(set.find(b), &set[1]);
  EXPECT_EQ(set.find(a + b + 1000), nullptr);
  TrackSet other;
  EXPECT_NE(other.add(two_segments()), a) << "ids are unique across sets: one renderer caches by them";
}

TEST(Track, FlatPointsRunThroughTheSegments) {
  const Track t = two_segments();
  EXPECT_EQ(t.segment_of(0), 0u);
  EXPECT_EQ(t.segment_of(2), 0u);
  EXPECT_EQ(t.segment_of(3), 1u);
  EXPECT_EQ(t.segment_of(4), 1u);
  EXPECT_EQ(t.ecef(2), glm::dvec3(3, 0, 0));
  EXPECT_EQ(t.ecef(3), glm::dvec3(10, 0, 0));
  EXPECT_EQ(t.ecef(4), glm::dvec3(11, 0, 0));
  EXPECT_THROW(t.ecef(5), std::out_of_range);
  EXPECT_EQ(t.start_time(), 100.0);
  EXPECT_EQ(t.end_time(), 210.0);
  EXPECT_EQ(t.points_with_value(), 5u);
}

TEST(Scene, ColourRangeOverVisibleTracksColouredByValue) {
  TrackSet set;
  set.add(two_segments());
  Style style;
  EXPECT_FALSE(color_range(set, style).has_value()) << "solid colours have no scale";
  style.tracks.color_by = track::ColorMetric::altitude;
  const auto all = color_range(set, style);
  ASSERT_TRUE(all.has_value());
  EXPECT_GE(all->min, 1.0);
  EXPECT_LE(all->max, 5.0);
  EXPECT_LT(all->min, all->max);
  style.tracks.range = track::ValueRange{-1.0, 9.0};
  EXPECT_EQ(color_range(set, style)->max, 9.0) << "a given range wins";
  style.tracks.range.reset();
  set[0].visible = false;
  EXPECT_FALSE(color_range(set, style).has_value()) << "a hidden track's values do not count";
  set[0].visible = true;
  set[0].by_value = false;
  EXPECT_FALSE(color_range(set, style).has_value()) << "nor those of a track drawn solid";
}

}  // namespace
}  // namespace trailray::scene
