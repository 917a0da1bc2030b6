// A film's clock, trail and cameras (scene/film): frames = duration x fps; the instants of
// --from/--to; a trail cut at a time with its ends interpolated; the follow camera above the
// terrain and seeing the followed point all along a path past a hill, looking where it goes.

#include <gtest/gtest.h>

#include <string>

#include <cmath>

#include "geo/wgs84.hpp"
#include "scene/film/film_camera.hpp"
#include "scene/film/film_timing.hpp"
#include "scene/film/film_tracks.hpp"

namespace trailray::scene {
namespace {

constexpr double kT0 = 1718704800.0;  // 2024-06-18T10:00:00Z
constexpr double kLat = 46.70, kLon = 7.85;
constexpr double kMetresPerDegLat = 111200.0;

double lon_at(double east_m) { return kLon + east_m / (kMetresPerDegLat * std::cos(kLat * 3.14159265358979 / 180.0)); }

TEST(FilmTiming, FramesAreDurationTimesFpsAndSpanTheTimes) {
  const auto timing = make_film_timing({kT0, kT0 + 600.0}, {2.0, std::nullopt}, 10.0);
  ASSERT_TRUE(timing.ok()) << timing.error;
  EXPECT_EQ(timing.value->frames, 20u);
  EXPECT_DOUBLE_EQ(timing.value->time_of(0), kT0);
  EXPECT_DOUBLE_EQ(timing.value->time_of(19), kT0 + 600.0);
  EXPECT_NEAR(timing.value->time_of(1) - timing.value->time_of(0), 600.0 / 19.0, 1e-6);
  const auto by_speed = make_film_timing({kT0, kT0 + 600.0}, {std::nullopt, 100.0}, 30.0);
  ASSERT_TRUE(by_speed.ok());
  EXPECT_EQ(by_speed.value->frames, 180u);  // 6 s of film
  EXPECT_FALSE(make_film_timing({kT0, kT0 + 600.0}, {0.0, std::nullopt}, 30.0).ok());
  EXPECT_FALSE(make_film_timing({kT0, kT0 + 600.0}, {1.0, std::nullopt}, 0.0).ok());
}

TEST(FilmTiming, ParsesLengthsSpeedsAndInstants) {
  EXPECT_DOUBLE_EQ(*parse_film_duration("60s").value, 60.0);
  EXPECT_DOUBLE_EQ(*parse_film_duration("1m30s").value, 90.0);
  EXPECT_DOUBLE_EQ(*parse_film_duration("45").value, 45.0);
  EXPECT_FALSE(parse_film_duration("1m30").ok());
  EXPECT_FALSE(parse_film_duration("soon").ok());
  EXPECT_DOUBLE_EQ(*parse_film_speed("50x").value, 50.0);
  EXPECT_FALSE(parse_film_speed("-2x").ok());
  // 4e306 minutes is more seconds than a double holds: no length (the fuzzer found it taken as
  // an infinite one); a number too long for a double is none either.
  const std::string huge = "4" + std::string(306, '0');
  EXPECT_TRUE(parse_film_duration(huge).ok());
  EXPECT_FALSE(parse_film_duration(huge + "m").ok());
  EXPECT_FALSE(parse_film_duration("1h" + huge + "m").ok());
  EXPECT_FALSE(parse_film_duration(huge + "000000s").ok());
  EXPECT_FALSE(parse_film_speed(huge + "000000x").ok());
  const TimeSpan span{kT0, kT0 + 7200.0};  // 10:00 to 12:00 UTC
  EXPECT_DOUBLE_EQ(*parse_film_instant("0.25", span, "--from").value, kT0 + 1800.0);
  EXPECT_DOUBLE_EQ(*parse_film_instant("+10m", span, "--from").value, kT0 + 600.0);
  EXPECT_DOUBLE_EQ(*parse_film_instant("11:30", span, "--from").value, kT0 + 5400.0);
  EXPECT_DOUBLE_EQ(*parse_film_instant("2024-06-18T10:15:00Z", span, "--from").value, kT0 + 900.0);
  const auto outside = parse_film_instant("13:00", span, "--to");
  EXPECT_FALSE(outside.ok());
  EXPECT_NE(outside.error.find("--to"), std::string::npos);
  EXPECT_FALSE(parse_trail_mode("sometimes").ok());
  EXPECT_EQ(parse_trail_mode("10m").value->kind, TrailKind::tail);
  EXPECT_DOUBLE_EQ(parse_trail_mode("10m").value->tail_s, 600.0);
}

// A track east along the parallel: 11 points 100 m apart, 10 s apart, at 1000 m; in two
// segments (points 0-5 and 6-10) when `gap`.
Track east_track(bool gap) {
  Track t;
  t.name = "East";
  TrackPolyline line;
  for (int i = 0; i <= 10; ++i) {
    t.distance_m.push_back(i * 100.0);
    t.time_unix_s.push_back(kT0 + i * 10.0);
    t.timed_points.push_back(static_cast<std::uint32_t>(i));
    line.points_ecef.push_back(geo::ecef_from_geodetic(kLat, lon_at(i * 100.0), 1000.0));
    line.values.push_back(static_cast<float>(i));
  }
  t.segment_first = {0};
  if (gap) {
    t.segment_first.push_back(6);
    TrackPolyline second;
    second.points_ecef.assign(line.points_ecef.begin() + 6, line.points_ecef.end());
    second.values.assign(line.values.begin() + 6, line.values.end());
    line.points_ecef.resize(6);
    line.values.resize(6);
    t.geometry.segments = {line, second};
  } else {
    t.geometry.segments = {line};
  }
  return t;
}

TEST(FilmTracks, TheTrailEndsAtTheMarkerAndTheGhostGoesOn) {
  TrackSet source;
  source.add(east_track(false));
  const WaypointSet none;
  FilmTracks film(source, none, {TrailKind::all, 0.0}, 1000.0);
  film.set_time(kT0 + 25.0);            // halfway between points 2 and 3
  ASSERT_EQ(film.tracks().size(), 2u);  // the trail and the ghosted future
  const TrackGeometry& past = film.tracks()[0].geometry;
  ASSERT_EQ(past.segments.size(), 1u);
  ASSERT_EQ(past.segments[0].points_ecef.size(), 4u);  // points 0, 1, 2 and the marker
  const glm::dvec3 marker = geo::ecef_from_geodetic(kLat, lon_at(250.0), 1000.0);
  EXPECT_LT(glm::length(past.segments[0].points_ecef.back() - marker), 0.5);
  EXPECT_FLOAT_EQ(past.segments[0].values.back(), 2.5f);
  const TrackGeometry& future = film.tracks()[1].geometry;
  ASSERT_EQ(future.segments.size(), 1u);
  EXPECT_EQ(future.segments[0].points_ecef.size(), 9u);  // the marker, points 3..10
  EXPECT_LT(glm::length(future.segments[0].points_ecef.front() - marker), 0.5);
  ASSERT_EQ(film.waypoints().points.size(), 1u);
  EXPECT_EQ(film.waypoints().points[0].name, "East");
  EXPECT_LT(glm::length(film.waypoints().points[0].marker_ecef - marker), 0.5);
  // The renderer sees new revisions, so it uploads the trail again.
  const auto revision = film.tracks()[0].revision;
  film.set_time(kT0 + 55.0);
  EXPECT_NE(film.tracks()[0].revision, revision);
}

TEST(FilmTracks, ATailKeepsTheLastSecondsAndGapsStayOpen) {
  TrackSet source;
  source.add(east_track(true));
  const WaypointSet none;
  FilmTracks film(source, none, {TrailKind::tail, 40.0}, 1000.0);
  film.set_time(kT0 + 75.0);            // 3.5..7.5: across the gap between points 5 and 6
  ASSERT_EQ(film.tracks().size(), 1u);  // no ghost
  const TrackGeometry& tail = film.tracks()[0].geometry;
  ASSERT_EQ(tail.segments.size(), 2u);
  EXPECT_EQ(tail.segments[0].points_ecef.size(), 3u);  // 3.5, 4, 5
  EXPECT_EQ(tail.segments[1].points_ecef.size(), 3u);  // 6, 7, 7.5
  EXPECT_LT(glm::length(tail.segments[0].points_ecef.front() - geo::ecef_from_geodetic(kLat, lon_at(350.0), 1000.0)),
            0.5);
}

// Flat ground at 1000 m with a hill 900 m high (Gaussian, 300 m wide) 900 m south of the corner
// of the path (3 km east at 1100 m, then north): once the path turns north, a camera behind it at
// a low pitch would stand in the hill.
double terrain_at(double lat, double lon) {
  const double north = (lat - kLat) * kMetresPerDegLat;
  const double east = (lon - lon_at(0.0)) / (lon_at(1.0) - lon_at(0.0));
  const double d2 = (east - 3000.0) * (east - 3000.0) + (north + 900.0) * (north + 900.0);
  return 1000.0 + 900.0 * std::exp(-d2 / (2.0 * 300.0 * 300.0));
}

std::vector<double> heights_of(std::span<const geo::LatLon> points) {
  std::vector<double> out;
  for (const geo::LatLon& p : points) out.push_back(terrain_at(p.lat, p.lon));
  return out;
}

TEST(FilmCamera, FollowStaysAboveTheTerrainAndSeesThePoint) {
  // 3 km east in 300 s, then a turn north: the camera must pass the hill's flank.
  const auto position = [](double t) {
    const double s = std::clamp(t - kT0, 0.0, 400.0);
    const double east = std::min(s, 300.0) * 10.0, north = std::max(0.0, s - 300.0) * 10.0;
    return geo::ecef_from_geodetic(kLat + north / kMetresPerDegLat, lon_at(east), 1100.0);
  };
  std::vector<double> times;
  for (int i = 0; i < 200; ++i) times.push_back(kT0 + i * 2.0);
  FilmCameraSettings settings;
  settings.distance_m = 1200.0;
  settings.pitch_deg = -10.0;
  settings.heading_window_s = 20.0;
  settings.position_window_s = 2.0;
  settings.raise_window = 10;
  settings.clearance_m = 25.0;
  const std::vector<FilmLook> looks = follow_looks(times, position, settings, heights_of);
  ASSERT_EQ(looks.size(), times.size());
  int raised = 0;
  for (std::size_t i = 0; i < looks.size(); ++i) {
    const glm::dvec3 camera = camera_position(looks[i]);
    const geo::Geodetic g = geo::geodetic_from_ecef(camera);
    EXPECT_GE(g.height_m, terrain_at(g.lat_deg, g.lon_deg) + settings.clearance_m - 1e-6) << "frame " << i;
    // The line of sight to the followed point is clear of the terrain.
    for (double f = 0.05; f < 0.9; f += 0.05) {
      const geo::Geodetic s = geo::geodetic_from_ecef(camera + (looks[i].target - camera) * f);
      EXPECT_GT(s.height_m, terrain_at(s.lat_deg, s.lon_deg) - 5.0) << "frame " << i << " at " << f;
    }
    raised += looks[i].pitch_deg < settings.pitch_deg - 1.0 ? 1 : 0;
    // Successive frames never jump: the smoothing holds.
    if (i > 0) {
      EXPECT_LT(glm::length(camera - camera_position(looks[i - 1])), 150.0) << "frame " << i;
    }
  }
  EXPECT_GT(raised, 5);    // the hill made it climb ...
  EXPECT_LT(raised, 150);  // ... only near the hill
  // It looks where the track goes: east at first, north at the end.
  EXPECT_NEAR(looks[20].heading_deg, 90.0, 3.0);
  EXPECT_NEAR(looks[199].heading_deg, 0.0, 3.0);
}

TEST(FilmCamera, OrbitTurnsOnceAroundTheCentre) {
  const glm::dvec3 centre = geo::ecef_from_geodetic(kLat, kLon, 1000.0);
  FilmCameraSettings settings;
  settings.distance_m = 3000.0;
  settings.pitch_deg = -30.0;
  const std::vector<FilmLook> looks = orbit_looks(centre, 8, 0.0, settings, {});
  ASSERT_EQ(looks.size(), 8u);
  for (std::size_t i = 0; i < looks.size(); ++i) {
    EXPECT_NEAR(looks[i].heading_deg, 45.0 * static_cast<double>(i), 1e-9);
    EXPECT_NEAR(glm::length(camera_position(looks[i]) - centre), 3000.0, 1e-6);
  }
}

}  // namespace
}  // namespace trailray::scene
