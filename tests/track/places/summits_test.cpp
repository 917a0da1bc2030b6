#include "track/places/summits.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "geo/geodesic.hpp"
#include "test_support.hpp"
#include "track/io/load.hpp"

namespace trailray::track::places {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A point `east_m` east and `north_m` north of (lat, lon): flat, for tens to hundreds of metres.
std::pair<double, double> offset(double lat, double lon, double east_m, double north_m) {
  return {lat + north_m / 111320.0, lon + east_m / (111320.0 * std::cos(lat * kPi / 180.0))};
}

Place peak(const std::string& name, std::pair<double, double> at, double ele) {
  Place p;
  p.name = name;
  p.kind = PlaceKind::Peak;
  p.lat_deg = at.first;
  p.lon_deg = at.second;
  p.ele_m = ele;
  return p;
}

Place hut(const std::string& name, std::pair<double, double> at) {
  Place p = peak(name, at, NAN);
  p.kind = PlaceKind::AlpineHut;
  return p;
}

// The Mojstrovka hike (Julian Alps, 184 fixes with times and elevations), its highest fix.
struct Hike {
  Track track;
  TrackPoint top;
};

Hike mojstrovka(const std::filesystem::path& path) {
  ReadResult read = load_track_file(path.string());
  EXPECT_TRUE(read.ok());
  Hike h{read.file.tracks.at(0), {}};
  h.top.ele = -1e9;
  for (const Segment& s : h.track.segments)
    for (const TrackPoint& p : s.points)
      if (p.ele > h.top.ele) h.top = p;
  return h;
}

TEST(Summits, APeakOnTheHighestFixIsReachedAtItsTime) {
  TRAILRAY_REQUIRE_DATA(path, "gpx/gpxpy_Mojstrovka.gpx");
  const Hike h = mojstrovka(path);
  const PlacesVisited v = places_visited(h.track, {peak("Top", {h.top.lat, h.top.lon}, h.top.ele)});
  ASSERT_EQ(v.summits.size(), 1u);
  EXPECT_EQ(v.summits[0].place.name, "Top");
  EXPECT_LT(v.summits[0].distance_m, 0.01);
  EXPECT_DOUBLE_EQ(v.summits[0].time_unix_s, h.top.time);
  EXPECT_TRUE(v.huts.empty());
}

TEST(Summits, APeak500MetresOffIsNot) {
  TRAILRAY_REQUIRE_DATA(path, "gpx/gpxpy_Mojstrovka.gpx");
  const Hike h = mojstrovka(path);
  // 500 m north and east of the top are both off the hike; checked against the whole track.
  for (auto [e, n] : {std::pair{500.0, 0.0}, std::pair{0.0, 500.0}}) {
    const Place far = peak("Far", offset(h.top.lat, h.top.lon, e, n), h.top.ele);
    double nearest = 1e9;
    for (const TrackPoint& p : h.track.segments[0].points)
      nearest = std::min(nearest, geo::geodesic_distance_m(p.lat, p.lon, far.lat_deg, far.lon_deg));
    if (nearest < 100.0) continue;  // the hike passes there: no claim
    EXPECT_TRUE(places_visited(h.track, {far}).summits.empty()) << e << " " << n;
  }
}

TEST(Summits, ATrack40MetresBelowTheSummitDidNotReachIt) {
  TRAILRAY_REQUIRE_DATA(path, "gpx/gpxpy_Mojstrovka.gpx");
  const Hike h = mojstrovka(path);
  EXPECT_TRUE(places_visited(h.track, {peak("Higher", {h.top.lat, h.top.lon}, h.top.ele + 40.0)}).summits.empty());
  // 20 m below its ele: within the 30 m a summit's ele and a GPS height may differ.
  EXPECT_EQ(places_visited(h.track, {peak("Close", {h.top.lat, h.top.lon}, h.top.ele + 20.0)}).summits.size(), 1u);
  // Without the summit's ele: its position alone.
  EXPECT_EQ(places_visited(h.track, {peak("No ele", {h.top.lat, h.top.lon}, NAN)}).summits.size(), 1u);
}

TEST(Summits, ATrackWithoutElevationsReachesByPositionAndWithoutTimesHasNone) {
  TRAILRAY_REQUIRE_DATA(path, "gpx/gpxpy_Mojstrovka.gpx");
  Hike h = mojstrovka(path);
  for (Segment& s : h.track.segments)
    for (TrackPoint& p : s.points) {
      p.ele = NAN;
      p.time = NAN;
    }
  const PlacesVisited v = places_visited(h.track, {peak("Top", {h.top.lat, h.top.lon}, h.top.ele + 500.0)});
  ASSERT_EQ(v.summits.size(), 1u);
  EXPECT_TRUE(std::isnan(v.summits[0].time_unix_s));
}

// A walk due north from (46.4, 13.8), a fix every 200 m and 100 s, climbing 10 m per fix.
Track walk_north(int fixes) {
  Track t;
  t.segments.emplace_back();
  for (int i = 0; i < fixes; ++i) {
    TrackPoint p;
    std::tie(p.lat, p.lon) = offset(46.4, 13.8, 0.0, 200.0 * i);
    p.ele = 1500.0 + 10.0 * i;
    p.time = 1'700'000'000.0 + 100.0 * i;
    t.segments[0].points.push_back(p);
  }
  return t;
}

TEST(Summits, HutsPassedWithin50MetresBetweenSparseFixes) {
  const Track t = walk_north(10);
  // Beside the middle of the leg from fix 3 to fix 4 (700 m north): 30 m east is passed, 80 m is not.
  const PlacesVisited v = places_visited(t, {hut("Near", offset(46.4, 13.8, 30.0, 700.0)),
                                              hut("Far", offset(46.4, 13.8, 80.0, 700.0))});
  ASSERT_EQ(v.huts.size(), 1u);
  EXPECT_EQ(v.huts[0].place.name, "Near");
  EXPECT_NEAR(v.huts[0].distance_m, 30.0, 0.5);
  // The time and the track's elevation interpolated halfway along the leg.
  EXPECT_NEAR(v.huts[0].time_unix_s, 1'700'000'350.0, 0.5);
  EXPECT_NEAR(v.huts[0].track_ele_m, 1535.0, 0.1);
  EXPECT_TRUE(v.summits.empty());
}

TEST(Summits, ListedInTheOrderTheTrackReachedThem) {
  const Track t = walk_north(10);
  const PlacesVisited v = places_visited(
      t, {peak("Second", offset(46.4, 13.8, 0.0, 1600.0), 1600.0), peak("First", offset(46.4, 13.8, 10.0, 200.0), 1500.0),
          hut("Not a summit", offset(46.4, 13.8, 0.0, 1000.0))});
  ASSERT_EQ(v.summits.size(), 2u);
  EXPECT_EQ(v.summits[0].place.name, "First");
  EXPECT_EQ(v.summits[1].place.name, "Second");
  EXPECT_NEAR(v.summits[1].time_unix_s, 1'700'000'800.0, 0.5);
  ASSERT_EQ(v.huts.size(), 1u);
}

TEST(Summits, AGapInTheRecordingIsNoWalk) {
  Track t = walk_north(2);
  t.segments[0].points[1] = t.segments[0].points[0];
  std::tie(t.segments[0].points[1].lat, t.segments[0].points[1].lon) = offset(46.4, 13.8, 0.0, 5000.0);
  // 2.5 km along a 5 km straight gap: not reached.
  EXPECT_TRUE(places_visited(t, {peak("Gap", offset(46.4, 13.8, 0.0, 2500.0), NAN)}).summits.empty());
}

// Many places, many points: a country's 100,000 peaks against a 20,000-fix track stays fast (the
// grid), and still finds the one on the track.
TEST(Summits, ManyPlacesManyPoints) {
  const Track t = walk_north(20000);
  std::vector<Place> places;
  for (int i = 0; i < 100000; ++i)
    places.push_back(peak("p" + std::to_string(i), {45.0 + (i % 317) * 0.01, 12.0 + (i / 317) * 0.01}, NAN));
  places.push_back(peak("On it", offset(46.4, 13.8, 5.0, 123456.0), NAN));
  const PlacesVisited v = places_visited(t, places);
  bool found = false;
  for (const PlaceVisit& s : v.summits) found = found || s.place.name == "On it";
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace trailray::track::places
