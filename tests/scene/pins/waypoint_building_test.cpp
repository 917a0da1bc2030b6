// Waypoints and place labels into a scene: the ground below sampled from the terrain, the marker
// at the recorded elevation (never under the ground), else on the ground, else the neutral
// ground; places from CSV and GPX files; routes marked and coloured apart from tracks.

#include "scene/pins/waypoint_building.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "geo/wgs84.hpp"
#include "scene/diagnostics.hpp"
#include "scene/text/legend_content.hpp"
#include "scene/tracks/track_building.hpp"
#include "terrain/east_profile_source.hpp"
#include "test_support.hpp"

namespace trailray::scene {
namespace {

constexpr double kLat = 46.0, kLon = 13.0;

// Terrain rising 0.1 m per metre east of kLon, 500 m there.
test::EastProfileSource slope() {
  return test::EastProfileSource("slope", kLat, kLon, [](double east) { return 500.0 + 0.1 * east; });
}

track::Waypoint point(double lat, double lon, double ele, const char* name) {
  track::Waypoint w;
  w.point.lat = lat;
  w.point.lon = lon;
  w.point.ele = ele;
  w.name = name;
  return w;
}

double height_of(const glm::dvec3& ecef) { return geo::geodetic_from_ecef(ecef).height_m; }

TEST(WaypointBuilding, GroundSampledAndMarkerAtElevationOrOnTheGround) {
  auto source = slope();
  const double east_lon = kLon + 1000.0 / (111320.0 * std::cos(kLat * M_PI / 180.0));
  const std::vector<track::Waypoint> points{
      point(kLat, kLon, 800.0, "above"), point(kLat, east_lon, track::kMissing, "no elevation"),
      point(kLat, kLon, 450.0, "under the ground"), point(95.0, kLon, 10.0, "invalid")};
  const auto built = build_waypoints(points, "w.gpx", WaypointKind::Waypoint, {&source, 123.0});
  ASSERT_EQ(built.size(), 3u);  // the invalid one dropped

  EXPECT_EQ(built[0].name, "above");
  EXPECT_EQ(built[0].source, "w.gpx");
  EXPECT_EQ(built[0].priority, kWaypointPriority);
  EXPECT_NEAR(built[0].ground_m, 500.0, 0.5);
  EXPECT_NEAR(height_of(built[0].ground_ecef), 500.0, 0.5);
  EXPECT_NEAR(height_of(built[0].marker_ecef), 800.0, 1e-3);

  EXPECT_NEAR(built[1].ground_m, 600.0, 1.0);  // 1 km east: 100 m higher
  EXPECT_TRUE(std::isnan(built[1].ele_m));
  EXPECT_NEAR(height_of(built[1].marker_ecef), built[1].ground_m, 1e-3);

  // A recorded height under the terrain would bury the pin: the marker stays on the ground.
  EXPECT_NEAR(height_of(built[2].marker_ecef), built[2].ground_m, 1e-3);
  EXPECT_DOUBLE_EQ(built[2].ele_m, 450.0);
}

TEST(WaypointBuilding, WithoutTerrainOnTheNeutralGround) {
  const std::vector<track::Waypoint> points{point(kLat, kLon, track::kMissing, "a"), point(kLat, kLon, 40.0, "b"),
                                            point(kLat, kLon, 400.0, "c")};
  const auto built = build_waypoints(points, "w.gpx", WaypointKind::Waypoint, {nullptr, 123.0});
  ASSERT_EQ(built.size(), 3u);
  EXPECT_TRUE(std::isnan(built[0].ground_m));
  EXPECT_NEAR(height_of(built[0].ground_ecef), 123.0, 1e-3);
  EXPECT_NEAR(height_of(built[0].marker_ecef), 123.0, 1e-3);
  // Under the neutral ground (drawn where there is no terrain) it would be buried too.
  EXPECT_NEAR(height_of(built[1].marker_ecef), 123.0, 1e-3);
  EXPECT_NEAR(height_of(built[1].ground_ecef), 123.0, 1e-3);
  EXPECT_NEAR(height_of(built[2].marker_ecef), 400.0, 1e-3);
}

TEST(WaypointBuilding, PlacesFromCsvAndGpx) {
  const test::TempFile csv("huts.csv", "name;lon;lat;ele\nKoca;13.01;46.01;1500\nDom;13.02;46.02;\n");
  const test::TempFile gpx("peaks.gpx",
                           "<?xml version=\"1.0\"?><gpx version=\"1.1\" creator=\"t\"><wpt lat=\"46.1\" lon=\"13.2\">"
                           "<ele>2000</ele><name>Peak</name><desc>high</desc></wpt></gpx>");
  CollectedDiagnostics diagnostics;
  auto source = slope();
  const auto places = read_place_labels({csv.str(), gpx.str()}, {}, {&source, 0.0}, diagnostics);
  ASSERT_EQ(places.size(), 3u);
  for (const Waypoint& p : places) {
    EXPECT_EQ(p.kind, WaypointKind::Place);
    EXPECT_EQ(p.priority, kPlacePriority);
    EXPECT_FALSE(std::isnan(p.ground_m));
  }
  EXPECT_EQ(places[0].name, "Koca");
  EXPECT_EQ(places[0].source, csv.str());
  EXPECT_DOUBLE_EQ(places[0].lat_deg, 46.01);
  EXPECT_NEAR(height_of(places[0].marker_ecef), 1500.0, 1e-3);
  EXPECT_NEAR(height_of(places[1].marker_ecef), places[1].ground_m, 1e-3);
  EXPECT_EQ(places[2].name, "Peak");
  EXPECT_EQ(places[2].description, "high");
  EXPECT_EQ(places[2].source, gpx.str());
}

TEST(WaypointBuilding, PlaceFileErrorsNameFileAndLine) {
  CollectedDiagnostics diagnostics;
  const test::TempFile bad("huts.csv", "name,lat,lon\nA,46,13\nB,46,east\n");
  try {
    read_place_labels({bad.str()}, {}, {}, diagnostics);
    FAIL() << "a bad row must fail";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(bad.str() + ":3: "), std::string::npos) << e.what();
  }
  const test::TempFile empty("none.csv", "name,lat,lon\n");
  EXPECT_THROW(read_place_labels({empty.str()}, {}, {}, diagnostics), std::runtime_error);
}

TEST(WaypointBuilding, FileWaypointsOfRealGpx) {
  TRAILRAY_REQUIRE_DATA(path, "gpx/gpxpy_cerknicko-jezero.gpx");
  CollectedDiagnostics diagnostics;
  const auto files = read_track_files({path.string()}, {}, diagnostics);
  const auto built = file_waypoints(files, {nullptr, 0.0});
  ASSERT_EQ(built.size(), files[0].file.waypoints.size());
  ASSERT_GT(built.size(), 0u);
  for (std::size_t i = 0; i < built.size(); ++i) {
    EXPECT_EQ(built[i].name, files[0].file.waypoints[i].name);
    EXPECT_EQ(built[i].kind, WaypointKind::Waypoint);
    EXPECT_EQ(built[i].source, path.string());
  }
}

TEST(WaypointBuilding, HidingBumpsTheRevision) {
  WaypointSet set;
  set.points = build_waypoints({point(kLat, kLon, 1.0, "a")}, "w", WaypointKind::Waypoint, {});
  const auto before = set.revision;
  set_waypoints_visible(set, false);
  EXPECT_FALSE(set.points[0].visible);
  EXPECT_NE(set.revision, before);
}

TEST(WaypointBuilding, HidingWaypointsLeavesTheThermalMarkers) {
  // --no-waypoints hides the files' waypoints and places; thermals have --thermals of their own.
  WaypointSet set;
  set.points = build_waypoints({point(kLat, kLon, 1.0, "hut")}, "w", WaypointKind::Waypoint, {});
  for (Waypoint& w : build_waypoints({point(kLat, kLon, 9.0, "+2.1 m/s")}, "w", WaypointKind::Thermal, {}))
    set.points.push_back(w);
  set_waypoints_visible(set, false);
  EXPECT_FALSE(set.points[0].visible);
  EXPECT_TRUE(set.points[1].visible);
}

TEST(RouteBuilding, RoutesAreMarkedSolidInTheRouteColourWithDistancesAlong) {
  LoadedTrackFile loaded;
  loaded.path = "plan.gpx";
  track::Track recorded;
  recorded.segments.push_back({{{kLat, kLon, 500.0}, {kLat + 0.01, kLon, 510.0}}});
  loaded.file.tracks.push_back(recorded);
  track::Route route;
  route.name = "plan";
  route.points = {{kLat, kLon, 500.0}, {kLat + 0.01, kLon, 500.0}, {kLat + 0.02, kLon, 500.0}};
  loaded.file.routes.push_back(route);
  TrackStyle style;
  style.color_by = track::ColorMetric::altitude;
  style.route_color = {0.1f, 0.2f, 0.3f};
  style.colors = {{1.0f, 0.0f, 0.0f}};
  CollectedDiagnostics diagnostics;
  const auto tracks = build_tracks({loaded}, style, {}, diagnostics);
  ASSERT_EQ(tracks.size(), 2u);
  EXPECT_FALSE(tracks[0].is_route);
  EXPECT_TRUE(tracks[0].by_value);
  EXPECT_EQ(tracks[0].color_srgb, glm::vec3(1.0f, 0.0f, 0.0f));
  const Track& r = tracks[1];
  EXPECT_TRUE(r.is_route);
  EXPECT_FALSE(r.by_value);
  EXPECT_EQ(r.color_srgb, style.route_color);
  ASSERT_EQ(r.geometry.segments.size(), 1u);
  const auto& along = r.geometry.segments[0].values;
  ASSERT_EQ(along.size(), 3u);
  EXPECT_FLOAT_EQ(along[0], 0.0f);
  EXPECT_NEAR(along[1], 1111.0f, 5.0f);
  EXPECT_NEAR(along[2], 2222.0f, 10.0f);
  // --color once per recorded track: the route is not counted.
  style.colors = {{1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
  EXPECT_THROW(build_tracks({loaded}, style, {}, diagnostics), std::runtime_error);
  // The key shows it as a route: dashed, its name whole.
  TrackSet set;
  style.colors.clear();
  style.color_by = track::ColorMetric::solid;
  for (Track& t : build_tracks({loaded}, style, {}, diagnostics)) set.add(std::move(t));
  const auto key = track_key_for(style, set);
  ASSERT_EQ(key.size(), 2u);
  EXPECT_EQ(key[1].name, "plan");
  EXPECT_TRUE(key[1].dashed);
  EXPECT_FALSE(key[0].dashed);
}

TEST(RouteBuilding, RoutesAreNotSmoothedTheirCornersStayWhereThePlanPutsThem) {
  // An L: five points north, then five east. Smoothing (meant for GPS noise) moves the corner of
  // a recorded track inwards; a route's corner is a planned place and stays.
  std::vector<track::TrackPoint> corner_points;
  for (int i = 0; i <= 5; ++i) corner_points.push_back({kLat + 0.001 * i, kLon, 500.0});
  for (int i = 1; i <= 5; ++i) corner_points.push_back({kLat + 0.005, kLon + 0.001 * i, 500.0});
  LoadedTrackFile loaded;
  loaded.path = "plan.gpx";
  track::Track recorded;
  recorded.segments.push_back({corner_points});
  loaded.file.tracks.push_back(recorded);
  loaded.file.routes.push_back({"plan", corner_points});
  TrackStyle style;
  CollectedDiagnostics diagnostics;
  const auto tracks = build_tracks({loaded}, style, {}, diagnostics);
  ASSERT_EQ(tracks.size(), 2u);
  const auto corner_of = [](const Track& t) { return t.cleaned.segments.at(0).points.at(5); };
  ASSERT_FALSE(tracks[0].is_route);
  EXPECT_GT(std::abs(corner_of(tracks[0]).lat - (kLat + 0.005)) + std::abs(corner_of(tracks[0]).lon - kLon), 1e-5)
      << "the recorded track's corner is smoothed (else this test shows nothing)";
  ASSERT_TRUE(tracks[1].is_route);
  EXPECT_DOUBLE_EQ(corner_of(tracks[1]).lat, kLat + 0.005);
  EXPECT_DOUBLE_EQ(corner_of(tracks[1]).lon, kLon);
}

}  // namespace
}  // namespace trailray::scene
