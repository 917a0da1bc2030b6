// Placing photos on tracks (pure math): by GPS position snapped to the polyline, by time on the
// timeline, and the reasons a photo is not placed.

#include <gtest/gtest.h>

#include <cmath>

#include "geo/geodesic.hpp"
#include "track/metrics.hpp"
#include "track/photos/photo_placement.hpp"

namespace trailray::track {
namespace {

constexpr double kT0 = 1700000000.0;  // 2023-11-14T22:13:20Z

// A track going north from (46.0, 8.0): a fix every 10 s, ~11.1 m apart, rising 1 m per fix.
Track north_track(std::size_t n = 50, double lon = 8.0, double t0 = kT0) {
  Track t;
  t.name = "north";
  t.segments.emplace_back();
  for (std::size_t i = 0; i < n; ++i) {
    TrackPoint p;
    p.lat = 46.0 + 1e-4 * static_cast<double>(i);
    p.lon = lon;
    p.ele = 1000.0 + static_cast<double>(i);
    p.time = t0 + 10.0 * static_cast<double>(i);
    t.segments.back().points.push_back(p);
  }
  return t;
}

PhotoMetadata photo_at(double lat, double lon, double local_s = std::nan(""), std::optional<int> offset = {}) {
  PhotoMetadata p;
  p.path = "photo.jpg";
  p.has_exif = true;
  p.lat_deg = lat;
  p.lon_deg = lon;
  p.taken_local_s = local_s;
  p.offset_s = offset;
  return p;
}

PhotoMetadata photo_taken(double utc_s, int offset_s = 7200) {
  return photo_at(std::nan(""), std::nan(""), utc_s + offset_s, offset_s);
}

TEST(PhotoPlacement, PhotoAtAFixTimeLandsAtThatFixDistanceExactly) {
  const Track t = north_track();
  const TrackMetrics m = compute_metrics(t);
  for (std::size_t k : {0u, 1u, 17u, 49u}) {
    const PhotoPlacement r = place_photos({photo_taken(kT0 + 10.0 * static_cast<double>(k))}, {&t});
    ASSERT_EQ(r.placed.size(), 1u) << k;
    const PlacedPhoto& p = r.placed[0];
    EXPECT_EQ(p.placed_by, PhotoPlacedBy::time);
    EXPECT_EQ(p.track, 0u);
    EXPECT_NEAR(p.distance_m, m.segments[0].distance_m[k], 1e-6) << k;
    EXPECT_EQ(p.distance_m, m.segments[0].distance_m[k]) << k;  // not just close: the same number
    EXPECT_EQ(p.lat_deg, t.segments[0].points[k].lat);
    EXPECT_EQ(p.ele_m, t.segments[0].points[k].ele);
    EXPECT_EQ(p.time_unix_s, kT0 + 10.0 * static_cast<double>(k));
    EXPECT_TRUE(std::isnan(p.gps_offset_m));
  }
}

TEST(PhotoPlacement, PhotoBetweenFixesIsInterpolated) {
  const Track t = north_track();
  const TrackMetrics m = compute_metrics(t);
  const PhotoPlacement r = place_photos({photo_taken(kT0 + 52.5)}, {&t});  // a quarter past fix 5
  ASSERT_EQ(r.placed.size(), 1u);
  const double d5 = m.segments[0].distance_m[5], d6 = m.segments[0].distance_m[6];
  EXPECT_NEAR(r.placed[0].distance_m, d5 + 0.25 * (d6 - d5), 1e-9);
  EXPECT_NEAR(r.placed[0].ele_m, 1005.25, 1e-9);
  EXPECT_NEAR(r.placed[0].lat_deg, 46.0 + 5.25e-4, 1e-12);
}

TEST(PhotoPlacement, GpsPositionThirtyMetresOffSnapsToTheTrack) {
  const Track t = north_track();
  const TrackMetrics m = compute_metrics(t);
  // 30 m east of the step between fixes 20 and 21, a third of the way along it.
  const double lat = 46.0 + 20.333e-4;
  const double dlon = 30.0 / (111320.0 * std::cos(lat * M_PI / 180.0));
  const PhotoPlacement r = place_photos({photo_at(lat, 8.0 + dlon)}, {&t});
  ASSERT_EQ(r.placed.size(), 1u);
  const PlacedPhoto& p = r.placed[0];
  EXPECT_EQ(p.placed_by, PhotoPlacedBy::gps);
  EXPECT_NEAR(p.gps_offset_m, 30.0, 0.2);
  EXPECT_NEAR(p.lon_deg, 8.0, 1e-9);
  EXPECT_NEAR(p.lat_deg, lat, 1e-8);
  const double d20 = m.segments[0].distance_m[20], d21 = m.segments[0].distance_m[21];
  EXPECT_NEAR(p.distance_m, d20 + 0.333 * (d21 - d20), 0.01);
  EXPECT_NEAR(p.ele_m, 1020.333, 1e-3);
  EXPECT_NEAR(p.time_unix_s, kT0 + 203.33, 1e-3);  // no time of its own: the track's there
  EXPECT_TRUE(r.unplaced.empty());
}

TEST(PhotoPlacement, GpsPositionOnAFixGivesItsDistance) {
  const Track t = north_track();
  const TrackMetrics m = compute_metrics(t);
  const auto& fix = t.segments[0].points[30];
  const PhotoPlacement r = place_photos({photo_at(fix.lat, fix.lon)}, {&t});
  ASSERT_EQ(r.placed.size(), 1u);
  EXPECT_EQ(r.placed[0].distance_m, m.segments[0].distance_m[30]);
  EXPECT_EQ(r.placed[0].gps_offset_m, 0.0);
}

TEST(PhotoPlacement, FiveHundredMetresOffWithoutTimeIsNotPlaced) {
  const Track t = north_track();
  const double dlon = 500.0 / (111320.0 * std::cos(46.002 * M_PI / 180.0));
  const PhotoPlacement r = place_photos({photo_at(46.002, 8.0 + dlon)}, {&t});
  EXPECT_TRUE(r.placed.empty());
  ASSERT_EQ(r.unplaced.size(), 1u);
  EXPECT_EQ(r.unplaced[0].photo, 0u);
  const std::string why = r.unplaced[0].reason.to_string();
  EXPECT_EQ(why.rfind("photo.jpg: not placed: its GPS position is 50", 0), 0u) << why;  // 500 m, give or take
  EXPECT_NE(why.find("no time"), std::string::npos) << why;
}

TEST(PhotoPlacement, FarGpsPositionWithATimeInsideTheTrackIsPlacedByTimeWithAWarning) {
  const Track t = north_track();
  PhotoMetadata p = photo_at(46.5, 8.5, kT0 + 100.0 + 3600.0, 3600);
  const PhotoPlacement r = place_photos({p}, {&t});
  ASSERT_EQ(r.placed.size(), 1u);
  EXPECT_EQ(r.placed[0].placed_by, PhotoPlacedBy::time);
  EXPECT_EQ(r.placed[0].distance_m, compute_metrics(t).segments[0].distance_m[10]);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].message.find("placed by its time instead"), std::string::npos) << r.warnings[0].message;
}

TEST(PhotoPlacement, TimeWithoutZoneNeedsTheDefaultOffset) {
  const Track t = north_track();
  PhotoMetadata p = photo_taken(kT0 + 200.0);
  p.offset_s.reset();  // the camera's 22:16:40 local, zone unknown
  PhotoPlacementOptions options;
  options.time_zone_hint = "give --photo-tz";
  const PhotoPlacement none = place_photos({p}, {&t}, options);
  ASSERT_EQ(none.unplaced.size(), 1u);
  EXPECT_NE(none.unplaced[0].reason.message.find("no time zone (no OffsetTimeOriginal): give --photo-tz"),
            std::string::npos)
      << none.unplaced[0].reason.message;
  options.default_offset_s = 7200;
  const PhotoPlacement with = place_photos({p}, {&t}, options);
  ASSERT_EQ(with.placed.size(), 1u);
  EXPECT_EQ(with.placed[0].distance_m, compute_metrics(t).segments[0].distance_m[20]);
  // A photo's own offset wins over the default.
  options.default_offset_s = 0;
  EXPECT_TRUE(place_photos({p}, {&t}, options).placed.empty());  // 2 h off: outside the track
}

TEST(PhotoPlacement, ClockOffsetShiftsThePlacement) {
  const Track t = north_track();
  const TrackMetrics m = compute_metrics(t);
  PhotoPlacementOptions options;
  options.clock_offset_s = 50.0;  // the camera's clock was 50 s slow: fix 10's time reads as fix 5's
  const PhotoPlacement r = place_photos({photo_taken(kT0 + 50.0)}, {&t}, options);
  ASSERT_EQ(r.placed.size(), 1u);
  EXPECT_EQ(r.placed[0].distance_m, m.segments[0].distance_m[10]);
  EXPECT_EQ(r.placed[0].time_unix_s, kT0 + 100.0);
  EXPECT_DOUBLE_EQ(photo_utc_time(photo_taken(kT0 + 50.0), options), kT0 + 100.0);
}

TEST(PhotoPlacement, OutsideTheTracksTimesSaysWhen) {
  const Track t = north_track();
  const PhotoPlacement r = place_photos({photo_taken(kT0 - 3600.0)}, {&t});
  ASSERT_EQ(r.unplaced.size(), 1u);
  EXPECT_NE(r.unplaced[0].reason.message.find(
                "it has no GPS position, and it was taken at 2023-11-14T21:13:20Z, outside the tracks' times "
                "(2023-11-14T22:13:20Z to 2023-11-14T22:21:30Z)"),
            std::string::npos)
      << r.unplaced[0].reason.message;
}

TEST(PhotoPlacement, NoExifAndNothingToPlaceByAreNotPlaced) {
  const Track t = north_track();
  PhotoMetadata bare;
  bare.path = "bare.jpg";
  PhotoMetadata empty_exif = bare;
  empty_exif.has_exif = true;
  const PhotoPlacement r = place_photos({bare, empty_exif}, {&t});
  ASSERT_EQ(r.unplaced.size(), 2u);
  EXPECT_EQ(r.unplaced[0].reason.to_string(), "bare.jpg: not placed: it has no EXIF block (no GPS position, no time)");
  EXPECT_EQ(r.unplaced[1].reason.to_string(), "bare.jpg: not placed: it has no GPS position and no time (no DateTimeOriginal)");
}

TEST(PhotoPlacement, TheTrackHoldingTheTimeAndTheNearestTrackAreChosen) {
  const Track morning = north_track(50, 8.0, kT0);
  const Track evening = north_track(50, 8.01, kT0 + 36000.0);  // 770 m east, ten hours later
  const PhotoPlacement by_time = place_photos({photo_taken(kT0 + 36000.0 + 30.0)}, {&morning, &evening});
  ASSERT_EQ(by_time.placed.size(), 1u);
  EXPECT_EQ(by_time.placed[0].track, 1u);
  const PhotoPlacement by_gps = place_photos({photo_at(46.001, 8.01)}, {&morning, &evening});
  ASSERT_EQ(by_gps.placed.size(), 1u);
  EXPECT_EQ(by_gps.placed[0].track, 1u);
  EXPECT_NEAR(by_gps.placed[0].gps_offset_m, 0.0, 1e-6);
  // A null track keeps the indices of the others.
  const PhotoPlacement skipped = place_photos({photo_at(46.001, 8.01)}, {nullptr, &evening});
  ASSERT_EQ(skipped.placed.size(), 1u);
  EXPECT_EQ(skipped.placed[0].track, 1u);
}

TEST(PhotoPlacement, InASegmentGapThePhotoGoesToTheNearerEnd) {
  Track t = north_track(20);
  Track second = north_track(20, 8.0, kT0 + 3600.0);
  t.segments.push_back(second.segments[0]);
  const TrackMetrics m = compute_metrics(t);
  const PhotoPlacement early = place_photos({photo_taken(kT0 + 190.0 + 600.0)}, {&t});
  ASSERT_EQ(early.placed.size(), 1u);
  EXPECT_EQ(early.placed[0].distance_m, m.segments[0].distance_m.back());
  const PhotoPlacement late = place_photos({photo_taken(kT0 + 3000.0)}, {&t});
  ASSERT_EQ(late.placed.size(), 1u);
  EXPECT_EQ(late.placed[0].distance_m, m.segments[1].distance_m.front());
}

TEST(PhotoPlacement, GpsTimeSuggestsTheZone) {
  PhotoMetadata p;
  p.taken_local_s = kT0 + 7200.0 + 41.0;  // UTC+2 and a camera 41 s fast
  p.gps_time_utc_s = kT0 + 86400.0;       // the GPS date a day off
  EXPECT_EQ(offset_suggested_by_gps_time(p), 7200);
  p.taken_local_s = kT0 + 7200.0 + 400.0;  // nowhere near a zone
  EXPECT_FALSE(offset_suggested_by_gps_time(p));
}

}  // namespace
}  // namespace trailray::track
