// The replay: a track's position at a clock time (interpolated between timed points, waiting
// before its start, after its end and across a segment gap), the common clock of several tracks
// with different starts, and the clock's speed, scrubbing and stop at the end.

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "app/view/viewer_ui.hpp"
#include "ui/replay.hpp"
#include "viewer_test_tracks.hpp"

namespace trailray::app::view {
namespace {

using namespace test_tracks;

// 11 points 100 m and 10 s apart, then after a 10-minute gap 11 more.
scene::Track gapped_track() {
  return viewer_tracks({file_of(
      "a.gpx", {track_of("a", {line(11, 100.0, 10.0, 500.0), line(11, 100.0, 10.0, 500.0, 5000.0, kT0 + 700.0)})})})[0];
}

TEST(PositionAt, InterpolatesBetweenPoints) {
  const scene::Track t = gapped_track();
  const TrackPosition p = position_at(t, kT0 + 25.0);
  ASSERT_TRUE(p.valid);
  EXPECT_TRUE(p.active);
  EXPECT_EQ(p.point, 2u);
  EXPECT_DOUBLE_EQ(p.fraction, 0.5);
  const glm::dvec3 mid = (t.ecef(2) + t.ecef(3)) * 0.5;
  EXPECT_LT(glm::length(p.ecef - mid), 1e-6);
  // On a point exactly.
  const TrackPosition on = position_at(t, kT0 + 30.0);
  EXPECT_EQ(on.point, 3u);
  EXPECT_DOUBLE_EQ(on.fraction, 0.0);
  EXPECT_EQ(on.ecef, t.ecef(3));
}

TEST(PositionAt, WaitsBeforeTheStartAfterTheEndAndInAGap) {
  const scene::Track t = gapped_track();
  const TrackPosition before = position_at(t, kT0 - 100.0);
  EXPECT_TRUE(before.valid);
  EXPECT_FALSE(before.active);
  EXPECT_EQ(before.point, 0u);
  EXPECT_EQ(before.ecef, t.ecef(0));
  const TrackPosition after = position_at(t, kT0 + 10000.0);
  EXPECT_FALSE(after.active);
  EXPECT_EQ(after.point, 21u);
  EXPECT_EQ(after.ecef, t.ecef(21));
  // In the gap (segment 1 ends at +100 s, segment 2 starts at +700 s): at segment 1's last point,
  // not somewhere on the straight line across the gap.
  const TrackPosition gap = position_at(t, kT0 + 400.0);
  EXPECT_TRUE(gap.active);
  EXPECT_EQ(gap.point, 10u);
  EXPECT_DOUBLE_EQ(gap.fraction, 0.0);
  EXPECT_EQ(gap.ecef, t.ecef(10));
  EXPECT_EQ(position_at(t, kT0 + 705.0).point, 11u);
}

TEST(PositionAt, TrackWithoutTimesHasNoPosition) {
  const scene::TrackSet tracks = viewer_tracks({file_of("r.gpx", {track_of("r", {line(5, 100.0, kNoTime, 500.0)})})});
  EXPECT_FALSE(position_at(tracks[0], kT0).valid);
  EXPECT_FALSE(common_time_span(tracks).has_value());
}

// The binary search over rising times finds what a scan in file order finds; times that go back
// (a later segment starting before the previous one ended) take the scan.
TEST(PositionAt, RisingTimesAreSearchedAndOthersScanned) {
  const scene::Track rising = gapped_track();
  ASSERT_TRUE(rising.times_rise);
  ASSERT_EQ(rising.timed_points.size(), 22u);
  scene::Track scanned = rising;
  scanned.times_rise = false;  // the same track through the scan
  for (double dt = -50.0; dt <= 1000.0; dt += 7.5) {
    const TrackPosition a = position_at(rising, kT0 + dt), b = position_at(scanned, kT0 + dt);
    EXPECT_EQ(a.point, b.point) << dt;
    EXPECT_DOUBLE_EQ(a.fraction, b.fraction) << dt;
    EXPECT_EQ(a.active, b.active) << dt;
  }
  // The second segment starts 50 s before the first ends: the scan stops at the first point
  // after the time, so at +20 s the marker is on the first segment.
  const scene::Track back = viewer_tracks({file_of(
      "b.gpx", {track_of("b", {line(11, 100.0, 10.0, 500.0), line(11, 100.0, 10.0, 500.0, 5000.0, kT0 + 50.0)})})})[0];
  EXPECT_FALSE(back.times_rise);
  EXPECT_EQ(position_at(back, kT0 + 20.0).point, 2u);
}

TEST(CommonTimeSpan, FromEarliestStartToLatestEnd) {
  const auto tracks =
      viewer_tracks({file_of("a.gpx", {track_of("early", {line(11, 100.0, 10.0, 500.0)}),
                                       track_of("late", {line(31, 100.0, 10.0, 500.0, 0.0, kT0 + 50.0)}),
                                       track_of("untimed", {line(3, 100.0, kNoTime, 500.0)})})});
  const auto span = common_time_span(tracks);
  ASSERT_TRUE(span.has_value());
  EXPECT_DOUBLE_EQ(span->start, kT0);
  EXPECT_DOUBLE_EQ(span->end, kT0 + 350.0);
  // On the common clock at +75 s the early track is between its points 7 and 8, the late one
  // between its points 2 and 3; at +200 s the early one has finished.
  EXPECT_EQ(position_at(tracks[0], kT0 + 75.0).point, 7u);
  EXPECT_EQ(position_at(tracks[1], kT0 + 75.0).point, 2u);
  EXPECT_DOUBLE_EQ(position_at(tracks[1], kT0 + 75.0).fraction, 0.5);
  EXPECT_FALSE(position_at(tracks[0], kT0 + 200.0).active);
  EXPECT_TRUE(position_at(tracks[1], kT0 + 200.0).active);
}

TEST(ReplayClock, AdvancesAtItsSpeedWhilePlaying) {
  ReplayClock clock;
  clock.advance(1.0);  // no span: nothing happens
  EXPECT_FALSE(clock.playing());
  clock.set_span({kT0, kT0 + 1000.0});
  EXPECT_DOUBLE_EQ(clock.time(), kT0);
  clock.advance(5.0);  // paused
  EXPECT_DOUBLE_EQ(clock.time(), kT0);
  clock.set_speed(20.0);
  clock.play();
  clock.advance(2.0);
  EXPECT_DOUBLE_EQ(clock.time(), kT0 + 40.0);
  EXPECT_DOUBLE_EQ(clock.fraction(), 0.04);
  clock.pause();
  clock.advance(2.0);
  EXPECT_DOUBLE_EQ(clock.time(), kT0 + 40.0);
}

TEST(ReplayClock, SpeedIsClampedToOneToAThousand) {
  ReplayClock clock;
  clock.set_speed(0.1);
  EXPECT_DOUBLE_EQ(clock.speed(), 1.0);
  clock.set_speed(5000.0);
  EXPECT_DOUBLE_EQ(clock.speed(), 1000.0);
  clock.set_speed(std::numeric_limits<double>::quiet_NaN());
  EXPECT_DOUBLE_EQ(clock.speed(), 1000.0);
}

TEST(ReplayClock, StopsAtTheEndAndPlayStartsOver) {
  ReplayClock clock;
  clock.set_span({kT0, kT0 + 100.0});
  clock.set_speed(1000.0);
  clock.play();
  clock.advance(1.0);
  EXPECT_DOUBLE_EQ(clock.time(), kT0 + 100.0);
  EXPECT_FALSE(clock.playing());
  clock.play();
  EXPECT_DOUBLE_EQ(clock.time(), kT0);
  EXPECT_TRUE(clock.playing());
}

TEST(ReplayClock, ScrubbingIsClampedToTheSpan) {
  ReplayClock clock;
  clock.set_span({kT0, kT0 + 100.0});
  clock.seek_fraction(0.25);
  EXPECT_DOUBLE_EQ(clock.time(), kT0 + 25.0);
  clock.seek(kT0 - 50.0);
  EXPECT_DOUBLE_EQ(clock.time(), kT0);
  clock.seek_fraction(3.0);
  EXPECT_DOUBLE_EQ(clock.time(), kT0 + 100.0);
  // A wider span keeps a time inside it; a span that no longer holds the time starts over.
  clock.set_span({kT0 - 100.0, kT0 + 200.0});
  EXPECT_DOUBLE_EQ(clock.time(), kT0 + 100.0);
  clock.set_span({kT0 + 500.0, kT0 + 600.0});
  EXPECT_DOUBLE_EQ(clock.time(), kT0 + 500.0);
}

}  // namespace
}  // namespace trailray::app::view
