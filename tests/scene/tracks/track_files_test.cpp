// What a scene takes from the recorded points before anything is cleaned: the lowest height and
// where and when the sun's day is.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/camera/sun_position.hpp"
#include "scene/tracks/track_files.hpp"

namespace trailray::scene {
namespace {

track::TrackPoint point(double lat, double lon, double ele, double time) {
  track::TrackPoint p;
  p.lat = lat;
  p.lon = lon;
  p.ele = ele;
  p.time = time;
  return p;
}

TEST(RecordedPoints, TakeTheLowestHeightAndTheFirstTimedPointOfTracksAndRoutes) {
  track::TrackFile file;
  file.tracks.resize(1);
  file.tracks[0].segments.push_back({{point(46.0, 7.0, 900.0, track::kMissing), point(46.0, 7.5, 700.0, 1.0e9)}});
  file.routes.push_back({"plan", {point(46.0, 8.0, 650.0, track::kMissing)}});
  RecordedPoints points;
  points.add(file);
  EXPECT_DOUBLE_EQ(points.lowest_m, 650.0);
  ASSERT_TRUE(points.first_time_s);
  EXPECT_DOUBLE_EQ(*points.first_time_s, 1.0e9);
  EXPECT_DOUBLE_EQ(points.first_time_lon_deg, 7.5);
  ASSERT_TRUE(points.any_lon_deg);
  EXPECT_DOUBLE_EQ(*points.any_lon_deg, 7.0);
  EXPECT_DOUBLE_EQ(default_sun_time(points), solar_noon_utc(1.0e9, 7.5));
}

TEST(RecordedPoints, AFileOfWaypointsAloneGivesTheSunThatPlacesNoon) {
  track::TrackFile file;
  file.waypoints.push_back({point(42.4, -71.06, track::kMissing, track::kMissing), "Boston", "", ""});
  RecordedPoints points;
  points.add(file);
  ASSERT_TRUE(points.any_lon_deg);
  EXPECT_DOUBLE_EQ(*points.any_lon_deg, -71.06);
  EXPECT_TRUE(std::isnan(points.lowest_m));
  EXPECT_EQ(points.lowest_or_sea_level(), 0.0);
  // Noon at 71 degrees west is near 16:44 UTC on any day.
  const double sun = default_sun_time(points);
  const double seconds_of_day = std::fmod(sun, 86400.0);
  EXPECT_NEAR(seconds_of_day, 12.0 * 3600.0 + 71.06 / 15.0 * 3600.0, 20.0 * 60.0);
}

}  // namespace
}  // namespace trailray::scene
