// Infringements on constructed cases: a track crossing a circle (entry and exit times and depth
// against the geodesic answer), a track above the ceiling, flight levels against pressure
// altitude, AGL limits with and without the ground, and the grid index against brute force.
#include <gtest/gtest.h>

#include <random>

#include "test_support.hpp"
#include "track/airspace/arc_geometry.hpp"
#include "track/airspace/infringement.hpp"
#include "track/airspace/openair_reader.hpp"

using namespace trailray::track::airspace;
using trailray::geo::LatLon;

namespace {

constexpr double kNaN = trailray::track::kMissing;

AirspaceFile file_of(const std::string& text) {
  auto r = read_openair(text, "test.txt");
  EXPECT_TRUE(r.ok());
  return r.file;
}

// A 5 km circle around 47 N 8 E between `floor` and `ceiling`.
std::string circle(const std::string& floor, const std::string& ceiling) {
  return "AC R\nAN Circle\nAL " + floor + "\nAH " + ceiling + "\nV X=47:00:00 N 008:00:00 E\nDC " +
         std::to_string(5000.0 / 1852.0) + "\n";
}

// Due north along 8 E from 46.9 to 47.1 in `n` fixes one second apart, at `msl` metres.
std::vector<CheckPoint> northbound(double msl, double pressure = kNaN, double ground = kNaN, int n = 2001) {
  std::vector<CheckPoint> out;
  for (int i = 0; i < n; ++i) {
    const double f = i / double(n - 1);
    out.push_back({46.9 + 0.2 * f, 8.0, 1000.0 + i, msl, pressure, ground});
  }
  return out;
}

}  // namespace

TEST(AirspaceInfringement, TrackThroughACircleEntryExitAndDepth) {
  const AirspaceFile f = file_of(circle("GND", "2000 m"));
  const AirspaceIndex index(f);
  const auto found = find_infringements(index, {northbound(1000)});
  ASSERT_EQ(found.size(), 1u);
  const Infringement& x = found[0];
  // Where the meridian meets the circle, on the ellipsoid: 5 km south and north of the centre.
  const LatLon south = geodesic_destination({47, 8}, 180, 5000), north = geodesic_destination({47, 8}, 0, 5000);
  const double seconds_per_deg = 2000 / 0.2;
  // The boundary is at most 1 m inside the circle (chord error); at 11.1 m/s that is 0.09 s.
  EXPECT_NEAR(x.entry_time, 1000 + (south.lat - 46.9) * seconds_per_deg, 0.1);
  EXPECT_NEAR(x.exit_time, 1000 + (north.lat - 46.9) * seconds_per_deg, 0.1);
  EXPECT_FALSE(x.inside_at_start);
  EXPECT_FALSE(x.inside_at_end);
  // The fix at 47 N is the centre: 5 km from the boundary, less at most the 1 m chord error.
  EXPECT_NEAR(x.max_horizontal_m, 5000 - 0.5, 0.51);
  EXPECT_NEAR(x.max_below_ceiling_m, 1000, 1e-9);
  EXPECT_TRUE(std::isnan(x.max_above_floor_m));  // GND without terrain: unknown
  EXPECT_TRUE(x.ground_assumed);
  EXPECT_EQ(x.ceiling_altitude, "gnss");
}

TEST(AirspaceInfringement, AboveTheCeilingIsNoInfringement) {
  const AirspaceFile f = file_of(circle("GND", "2000 m"));
  const AirspaceIndex index(f);
  EXPECT_TRUE(find_infringements(index, {northbound(2000.5)}).empty());
  EXPECT_EQ(find_infringements(index, {northbound(1999.5)}).size(), 1u);
}

TEST(AirspaceInfringement, FlightLevelsCompareWithPressureAltitude) {
  const AirspaceFile f = file_of(circle("FL 100", "FL 150"));  // 3048 m .. 4572 m pressure altitude
  const AirspaceIndex index(f);
  // GNSS says below the floor, the barometer (against 1013.25 hPa) says above it: inside.
  auto found = find_infringements(index, {northbound(2900, 3200)});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].floor_altitude, "pressure");
  EXPECT_NEAR(found[0].max_above_floor_m, 3200 - 3048, 1e-9);
  EXPECT_NEAR(found[0].max_vertical_m, 3200 - 3048, 1e-9);
  // And the other way round: GNSS inside, pressure below.
  EXPECT_TRUE(find_infringements(index, {northbound(3200, 2900)}).empty());
  // Without pressure altitude the one altitude there is is used.
  found = find_infringements(index, {northbound(3200)});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].floor_altitude, "gnss");
}

TEST(AirspaceInfringement, AglLimitsUseTheGroundWhenKnownElseAssumeConservatively) {
  const AirspaceFile f = file_of(circle("1000 ft AGL", "FL 100"));  // floor 304.8 m above the ground
  const AirspaceIndex index(f);
  // 200 m above ground at 1000 m: below the floor.
  EXPECT_TRUE(find_infringements(index, {northbound(1200, 1200, 1000)}).empty());
  // 500 m above ground: inside, 195.2 m above the floor.
  auto found = find_infringements(index, {northbound(1500, 1500, 1000)});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].floor_altitude, "gnss-ground");
  EXPECT_NEAR(found[0].max_above_floor_m, 500 - 304.8, 1e-9);
  EXPECT_FALSE(found[0].ground_assumed);
  // Ground unknown: the floor as if the ground were at sea level (the lowest it can be).
  found = find_infringements(index, {northbound(1200)});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].ground_assumed);
  EXPECT_NEAR(found[0].max_above_floor_m, 1200 - 304.8, 1e-9);
}

TEST(AirspaceInfringement, InsideFromTheStartAndSegmentsApart) {
  const AirspaceFile f = file_of(circle("GND", "2000 m"));
  const AirspaceIndex index(f);
  auto track = northbound(1000);
  std::vector<CheckPoint> first(track.begin() + 1000, track.end());     // starts at the centre
  std::vector<CheckPoint> second(track.begin(), track.begin() + 1001);  // ends at the centre
  const auto found = find_infringements(index, {first, second});
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].segment, 0u);
  EXPECT_TRUE(found[0].inside_at_start);
  EXPECT_DOUBLE_EQ(found[0].entry_time, first.front().time);
  EXPECT_EQ(found[1].segment, 1u);
  EXPECT_TRUE(found[1].inside_at_end);
  EXPECT_DOUBLE_EQ(found[1].exit_time, second.back().time);
}

TEST(AirspaceInfringement, GridIndexFindsWhatBruteForceFinds) {
  TRAILRAY_REQUIRE_DATA(swiss, "airspace/openairrs_Switzerland.txt");
  const auto r = load_openair_file(swiss.string());
  ASSERT_TRUE(r.ok());
  const AirspaceIndex index(r.file);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> lat(45.6, 47.9), lon(5.4, 10.1);
  std::size_t hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const double la = lat(rng), lo = lon(rng);
    std::vector<std::uint32_t> found = index.candidates(la, lo);
    std::vector<std::uint32_t> inside;
    for (auto a : found)
      if (index.contains(a, la, lo)) inside.push_back(a);
    std::vector<std::uint32_t> brute;
    for (std::uint32_t a = 0; a < r.file.airspaces.size(); ++a)
      if (index.contains(a, la, lo)) brute.push_back(a);
    std::sort(inside.begin(), inside.end());
    ASSERT_EQ(inside, brute) << la << " " << lo;
    hits += brute.size();
  }
  EXPECT_GT(hits, 1000u);  // the sample does reach into airspaces
}

// An airspace across the antimeridian (an oceanic area east of New Zealand): its boundary's
// longitudes are continuous (past 180), points either side of the line are inside, one a
// turn away is compared a turn away, and a flight eastwards across the line enters it once.
TEST(AirspaceInfringement, AcrossTheAntimeridian) {
  const AirspaceFile f = file_of(
      "AC D\nAN Dateline\nAL GND\nAH FL 100\n"
      "DP 40:00:00 S 179:30:00 E\nDP 40:00:00 S 179:30:00 W\nDP 41:00:00 S 179:30:00 W\nDP 41:00:00 S 179:30:00 E\n");
  ASSERT_EQ(f.airspaces.size(), 1u);
  const auto& ring = f.airspaces[0].boundary;
  ASSERT_EQ(ring.size(), 4u);
  for (std::size_t i = 1; i < ring.size(); ++i) EXPECT_LE(std::abs(ring[i].lon - ring[i - 1].lon), 180.0) << i;
  EXPECT_NEAR(ring[1].lon, 180.5, 1e-9);

  const AirspaceIndex index(f);
  for (const double lon : {179.9, 180.0, -180.0, -179.9, 180.2 - 360.0}) {
    EXPECT_EQ(index.candidates(-40.5, lon).size(), 1u) << lon;
    EXPECT_TRUE(index.contains(0, -40.5, lon)) << lon;
  }
  for (const double lon : {179.0, -179.0, 0.0}) {
    EXPECT_FALSE(index.contains(0, -40.5, lon)) << lon;
    EXPECT_TRUE(index.candidates(-40.5, lon).empty()) << lon;
  }
  // 0.1 degree west of the line the boundary at 179.5 E is 0.4 degree away: about 34 km at 40.5 S.
  EXPECT_NEAR(index.distance_to_boundary_m(0, -40.5, -179.9), 0.4 * 111320.0 * std::cos(40.5 * M_PI / 180.0), 400.0);

  // Eastwards along 40.5 S from 179 E to 179 W, one fix a second: inside from 179.5 E to 179.5 W.
  std::vector<CheckPoint> east;
  for (int i = 0; i <= 2000; ++i) {
    double lon = 179.0 + 2.0 * i / 2000.0;
    if (lon > 180.0) lon -= 360.0;
    east.push_back({-40.5, lon, 1000.0 + i, 1000.0, kNaN, kNaN});
  }
  const auto found = find_infringements(index, {east});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NEAR(found[0].entry_time, 1000.0 + 500.0, 1.0);
  EXPECT_NEAR(found[0].exit_time, 1000.0 + 1500.0, 1.0);
}
