#include "ui/places_statistics.hpp"

#include <gtest/gtest.h>

namespace trailray::ui {
namespace {

TEST(PlacesStatistics, LinesAndTheCacheFollowsTheRevision) {
  scene::Track t;
  t.id = 7;
  t.cleaned.segments.emplace_back();
  for (int i = 0; i < 3; ++i) {
    track::TrackPoint p;
    p.lat = 47.06 + 0.0004 * i;
    p.lon = 9.607;
    p.ele = 2565.0;
    p.time = 1'719'820'800.0 + 60.0 * i;  // 2024-07-01T08:00:00Z
    t.cleaned.segments[0].points.push_back(p);
  }
  track::places::Place peak;
  peak.name = "Naafkopf";
  peak.lat_deg = 47.0604;
  peak.lon_deg = 9.607;
  peak.ele_m = 2571.0;
  track::places::Place hut = peak;
  hut.name = "Hütte";
  hut.kind = track::places::PlaceKind::AlpineHut;
  hut.ele_m = NAN;
  hut.lat_deg = 47.06;
  PlacesVisitCache cache;
  const std::vector<std::string> lines = places_visited_panel_lines(cache.of(t, {peak, hut}));
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "Summits reached");
  EXPECT_EQ(lines[1], "  Naafkopf 2571 m  08:01:00 UTC");
  EXPECT_EQ(lines[2], "Huts passed");
  EXPECT_EQ(lines[3], "  Hütte  08:00:00 UTC");
  // Kept while the revision holds; worked out again when it changes.
  t.cleaned.segments[0].points.clear();
  EXPECT_EQ(cache.of(t, {peak, hut}).summits.size(), 1u);
  t.bump_revision();
  EXPECT_TRUE(cache.of(t, {peak, hut}).summits.empty());
}

}  // namespace
}  // namespace trailray::ui
