// Airspaces into the scene's volumes: colours by class, flight levels drawn by the standard
// atmosphere, limits above the ground standing on the sampled terrain, culling around the
// tracks and levelling by height, the cap on how many are drawn, the legend's classes, and the
// pick under the mouse.

#include "scene/volumes/airspace_volumes.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geo/wgs84.hpp"
#include "scene/text/label_layout.hpp"
#include "scene/text/legend_content.hpp"
#include "scene/volumes/volume_shapes.hpp"
#include "terrain/east_profile_source.hpp"
#include "test_support.hpp"
#include "track/airspace/openair_reader.hpp"

namespace trailray::scene {
namespace {

namespace air = track::airspace;

constexpr double kLat = 46.0, kLon = 13.0;
constexpr double kFootM = 0.3048;
const double kMetresPerDegLon = 111320.0 * std::cos(kLat * M_PI / 180.0);

// A point `east_m` east and `north_m` north of (kLat, kLon).
geo::LatLon at(double east_m, double north_m) { return {kLat + north_m / 111320.0, kLon + east_m / kMetresPerDegLon}; }

// A square `side_m` wide with its south-west corner at (east_m, north_m).
std::vector<geo::LatLon> square(double east_m, double north_m, double side_m) {
  return {at(east_m, north_m), at(east_m + side_m, north_m), at(east_m + side_m, north_m + side_m),
          at(east_m, north_m + side_m)};
}

air::AltitudeLimit msl(double metres) { return {air::AltitudeReference::Msl, metres, ""}; }
air::AltitudeLimit agl(double metres) { return {air::AltitudeReference::Agl, metres, ""}; }

air::Airspace airspace(const char* cls, const char* name, std::vector<geo::LatLon> ring,
                       air::AltitudeLimit floor = msl(500.0), air::AltitudeLimit ceiling = msl(2000.0)) {
  air::Airspace a;
  a.airspace_class = cls;
  a.name = name;
  a.boundary = std::move(ring);
  a.floor = floor;
  a.ceiling = ceiling;
  return a;
}

geo::LatLonBounds box(double east_m, double north_m, double side_m) {
  geo::LatLonBounds b;
  for (const geo::LatLon& p : square(east_m, north_m, side_m)) b.add(p.lat, p.lon);
  return b;
}

TEST(AirspaceVolumes, ColoursFollowTheClassesAsPilotsMapsDo) {
  const auto ctr = airspace_class_style("CTR").color_srgb;
  EXPECT_GT(ctr.r, 0.7f);
  EXPECT_LT(ctr.g, 0.3f);
  EXPECT_LT(ctr.b, 0.3f);
  const auto restricted = airspace_class_style("R").color_srgb;
  EXPECT_GT(restricted.r, 2.0f * restricted.b);
  EXPECT_EQ(airspace_class_style("P").color_srgb, restricted);
  const auto danger = airspace_class_style("Q").color_srgb;
  EXPECT_GT(danger.r, 0.9f);
  EXPECT_GT(danger.g, restricted.g + 0.15f);  // orange, apart from the red ones
  for (const char* controlled : {"C", "D"}) {
    const auto c = airspace_class_style(controlled).color_srgb;
    EXPECT_GT(c.b, 2.0f * c.r) << controlled;  // blue
  }
  const auto tmz = airspace_class_style("TMZ").color_srgb;
  EXPECT_NEAR(tmz.r, tmz.b, 0.1f);  // grey
  EXPECT_EQ(airspace_class_style("RMZ").color_srgb, tmz);
  // Spelled as files spell it: trailing blanks, lower case.
  EXPECT_EQ(airspace_class_style("c  ").color_srgb, airspace_class_style("C").color_srgb);
  EXPECT_NE(airspace_class_style("XYZ").color_srgb, ctr);
}

TEST(AirspaceVolumes, FlightLevelsAndFeetInMetresUnlimitedCapped) {
  const std::string text =
      "AC D\nAN HIGH\nAL FL 95\nAH UNL\nDP 46:00:00 N 013:00:00 E\nDP 46:00:00 N 013:05:00 E\n"
      "DP 46:05:00 N 013:05:00 E\n"
      "AC C\nAN LOW\nAL 3000 ft\nAH FL 125\nDP 46:00:00 N 013:00:00 E\nDP 46:00:00 N 013:05:00 E\n"
      "DP 46:05:00 N 013:05:00 E\n";
  const air::AirspaceReadResult read = air::read_openair(text, "fl.txt");
  ASSERT_TRUE(read.ok());
  AirspaceDrawOptions options;
  options.ceiling_cap_m = 5000.0;
  const AirspaceVolumes built = airspace_volumes(read.file, "fl.txt", options);
  ASSERT_EQ(built.volumes.size(), 2u);
  const Volume& high = built.volumes[0];
  // FL 95: 9500 ft of pressure altitude, drawn where the standard atmosphere puts it.
  EXPECT_NEAR(high.floor.metres, 9500.0 * kFootM, 0.01);
  EXPECT_EQ(high.floor.reference, VolumeHeightReference::Msl);
  EXPECT_TRUE(high.ceiling.unlimited);
  EXPECT_NEAR(high.ceiling.metres, 5000.0, 1e-9);  // at the cap
  EXPECT_EQ(high.category, "D");
  EXPECT_EQ(high.source, "fl.txt");
  EXPECT_GT(high.line, 0);
  const Volume& low = built.volumes[1];
  EXPECT_NEAR(low.floor.metres, 3000.0 * kFootM, 0.01);
  EXPECT_FALSE(low.floor.unlimited);
  // FL 125 (3810 m) is under the cap: drawn as it is.
  EXPECT_NEAR(low.ceiling.metres, 12500.0 * kFootM, 0.01);
  EXPECT_FALSE(low.ceiling.unlimited);
  EXPECT_FALSE(low.floor_text.empty());
  EXPECT_FALSE(low.ceiling_text.empty());

  options.ceiling_cap_m = 3000.0;  // now FL 125 is over it: capped and faded
  const AirspaceVolumes capped = airspace_volumes(read.file, "fl.txt", options);
  EXPECT_TRUE(capped.volumes[1].ceiling.unlimited);
  EXPECT_NEAR(capped.volumes[1].ceiling.metres, 3000.0, 1e-9);
  // A floor above the cap: the ceiling at least 1000 m over it.
  EXPECT_NEAR(capped.volumes[0].ceiling.metres, 9500.0 * kFootM + 1000.0, 0.01);
}

TEST(AirspaceVolumes, FloorAboveTheGroundFollowsTheSampledTerrain) {
  // Terrain rising 0.1 m per metre east: 500 m at kLon, 1500 m 10 km east.
  test::EastProfileSource slope("slope", kLat, kLon, [](double east) { return 500.0 + 0.1 * east; });
  air::AirspaceFile file;
  file.airspaces.push_back(airspace("E", "AGL", square(0.0, 0.0, 10000.0), agl(1000.0 * kFootM), msl(4000.0)));
  const AirspaceVolumes built = airspace_volumes(file, "agl.txt", {});
  ASSERT_EQ(built.volumes.size(), 1u);
  VolumeSet set;
  set.volumes = built.volumes;
  const Volume& v = set.volumes[0];
  // Densified so the floor follows the terrain between the file's corners: 10 km edges, a point
  // at least every 400 m.
  EXPECT_GE(v.boundary.size(), 4u * 25u);
  place_volumes_on_ground(set, &slope);
  ASSERT_EQ(set.volumes[0].ground_m.size(), set.volumes[0].boundary.size());
  const std::vector<VolumeShape> shapes = volume_shapes(set, 0.0);
  ASSERT_EQ(shapes.size(), 1u);
  double lowest = 1e9, highest = -1e9;
  for (std::size_t i = 0; i < shapes[0].columns.size(); ++i) {
    const geo::LatLon& p = set.volumes[0].boundary[i];
    const double east = (p.lon - kLon) * kMetresPerDegLon;
    const double ground = 500.0 + 0.1 * east;
    EXPECT_NEAR(shapes[0].columns[i].bottom_m, ground + 1000.0 * kFootM, 2.0) << i;
    EXPECT_NEAR(geo::geodetic_from_ecef(shapes[0].columns[i].bottom_ecef).height_m, shapes[0].columns[i].bottom_m,
                0.01);
    EXPECT_NEAR(shapes[0].columns[i].top_m, 4000.0, 1e-6);
    lowest = std::min(lowest, shapes[0].columns[i].bottom_m);
    highest = std::max(highest, shapes[0].columns[i].bottom_m);
  }
  EXPECT_NEAR(highest - lowest, 1000.0, 5.0);  // the floor climbs with the slope
  EXPECT_TRUE(shapes[0].floor_outline);
}

TEST(AirspaceVolumes, FloorOnTheGroundIsBuriedAndHasNoOutline) {
  test::EastProfileSource flat("flat", kLat, kLon, [](double) { return 800.0; });
  air::AirspaceFile file;
  file.airspaces.push_back(airspace("CTR", "GND", square(0.0, 0.0, 2000.0), agl(0.0), msl(1500.0)));
  VolumeSet set;
  set.volumes = airspace_volumes(file, "gnd.txt", {}).volumes;
  place_volumes_on_ground(set, &flat);
  const std::vector<VolumeShape> shapes = volume_shapes(set, 0.0);
  ASSERT_EQ(shapes.size(), 1u);
  EXPECT_FALSE(shapes[0].floor_outline);
  for (const VolumeColumn& c : shapes[0].columns) EXPECT_NEAR(c.bottom_m, 800.0 - kBuriedFloorM, 0.5);
  // Without terrain: on the neutral ground the renderer passes.
  VolumeSet bare;
  bare.volumes = airspace_volumes(file, "gnd.txt", {}).volumes;
  place_volumes_on_ground(bare, nullptr);
  const std::vector<VolumeShape> bare_shapes = volume_shapes(bare, 300.0);
  ASSERT_EQ(bare_shapes.size(), 1u);
  for (const VolumeColumn& c : bare_shapes[0].columns) EXPECT_NEAR(c.bottom_m, 300.0 - kBuriedFloorM, 1e-6);
}

TEST(AirspaceVolumes, CulledAroundTheTracksLevelledAndCapped) {
  air::AirspaceFile file;
  file.airspaces.push_back(airspace("D", "FAR", square(200000.0, 0.0, 5000.0)));         // 200 km east
  file.airspaces.push_back(airspace("D", "NEAR", square(8000.0, 0.0, 3000.0)));          // 8 km east
  file.airspaces.push_back(airspace("CTR", "UNDER", square(-1000.0, -1000.0, 4000.0)));  // under the track
  file.airspaces.push_back(airspace("C", "HIGH", square(0.0, 0.0, 5000.0), msl(7000.0), msl(9000.0)));
  AirspaceDrawOptions options;
  options.region = box(0.0, 0.0, 2000.0);  // the tracks
  options.margin_m = 15000.0;
  options.max_floor_m = 4000.0;
  const AirspaceVolumes built = airspace_volumes(file, "c.txt", options);
  ASSERT_EQ(built.volumes.size(), 2u);
  EXPECT_EQ(built.volumes[0].name, "UNDER");  // the nearest first
  EXPECT_EQ(built.volumes[1].name, "NEAR");
  EXPECT_EQ(built.outside_region, 1u);
  EXPECT_EQ(built.above_floor, 1u);
  EXPECT_EQ(built.over_cap, 0u);

  options.max_volumes = 1;
  const AirspaceVolumes one = airspace_volumes(file, "c.txt", options);
  ASSERT_EQ(one.volumes.size(), 1u);
  EXPECT_EQ(one.volumes[0].name, "UNDER");
  EXPECT_EQ(one.over_cap, 1u);

  options.max_volumes = 400;
  options.region.reset();  // no region: everything under the floor limit
  EXPECT_EQ(airspace_volumes(file, "c.txt", options).volumes.size(), 3u);
}

// An airspace across the antimeridian (its ring past 180 degrees) is drawn for tracks on
// either side of the line, and not for tracks half a world away.
TEST(AirspaceVolumes, AcrossTheAntimeridianKeptForTracksOnEitherSide) {
  air::AirspaceFile file;
  file.airspaces.push_back(airspace("D", "DATELINE", {{-40.0, 179.5}, {-40.0, 180.5}, {-41.0, 180.5}, {-41.0, 179.5}}));
  AirspaceDrawOptions options;
  options.margin_m = 1000.0;
  for (const double lon : {179.8, -179.8}) {
    geo::LatLonBounds tracks;
    tracks.add(-40.6, lon - 0.01);
    tracks.add(-40.4, lon + 0.01);
    options.region = tracks;
    const AirspaceVolumes built = airspace_volumes(file, "d.txt", options);
    EXPECT_EQ(built.volumes.size(), 1u) << lon;
  }
  geo::LatLonBounds far;
  far.add(-40.6, 0.0);
  far.add(-40.4, 0.1);
  options.region = far;
  EXPECT_TRUE(airspace_volumes(file, "d.txt", options).volumes.empty());
}

TEST(AirspaceVolumes, RingsSimplifiedWithinTheTolerance) {
  // A square whose edges carry 50 points each, a few metres off the straight line.
  std::vector<geo::LatLon> ring;
  for (int edge = 0; edge < 4; ++edge)
    for (int k = 0; k < 50; ++k) {
      const double t = 5000.0 * k / 50.0, wiggle = (k % 2) * 3.0;
      const double e[4] = {t, 5000.0 + wiggle, 5000.0 - t, -wiggle};
      const double n[4] = {-wiggle, t, 5000.0 + wiggle, 5000.0 - t};
      ring.push_back(at(e[edge], n[edge]));
    }
  air::AirspaceFile file;
  file.airspaces.push_back(airspace("D", "WIGGLY", ring));
  AirspaceDrawOptions options;
  options.simplify_m = 10.0;
  const AirspaceVolumes built = airspace_volumes(file, "s.txt", options);
  ASSERT_EQ(built.volumes.size(), 1u);
  EXPECT_EQ(built.points_before, 200u);
  EXPECT_LE(built.volumes[0].boundary.size(), 8u);
  EXPECT_GE(built.volumes[0].boundary.size(), 4u);  // the corners stay
  options.simplify_m = 1.0;                         // finer than the wiggle: kept
  EXPECT_GT(airspace_volumes(file, "s.txt", options).volumes[0].boundary.size(), 100u);
}

TEST(AirspaceVolumes, CableIsOneWallAtLeastAFewMetresTall) {
  air::AirspaceFile file;
  file.airspaces.push_back(airspace("Q", "KABEL", {at(0, 0), at(800, 300)}, msl(1500.0), msl(1500.0)));
  VolumeSet set;
  set.volumes = airspace_volumes(file, "k.txt", {}).volumes;
  ASSERT_EQ(set.volumes.size(), 1u);
  EXPECT_FALSE(set.volumes[0].closed);
  const std::vector<VolumeShape> shapes = volume_shapes(set, 0.0);
  ASSERT_EQ(shapes[0].columns.size(), 2u);
  EXPECT_FALSE(shapes[0].closed);
  EXPECT_NEAR(shapes[0].columns[0].top_m - shapes[0].columns[0].bottom_m, kMinWallM, 1e-9);
}

TEST(AirspaceVolumes, LegendListsTheClassesShownInTableOrder) {
  air::AirspaceFile file;
  file.airspaces.push_back(airspace("D", "a", square(0, 0, 1000)));
  file.airspaces.push_back(airspace("CTR", "b", square(0, 0, 1000)));
  file.airspaces.push_back(airspace("Q", "c", square(0, 0, 1000)));
  file.airspaces.push_back(airspace("D", "d", square(0, 0, 1000)));
  VolumeSet set;
  set.volumes = airspace_volumes(file, "l.txt", {}).volumes;
  std::vector<std::string> labels;
  for (const AirspaceClassShown& c : airspace_classes_shown(set)) labels.push_back(c.label);
  EXPECT_EQ(labels, (std::vector<std::string>{"CTR control zone", "Q danger", "class D"}));
  for (Volume& v : set.volumes) v.visible = v.category != "Q";
  EXPECT_EQ(airspace_classes_shown(set).size(), 2u);
}

TEST(AirspaceVolumes, PickFindsTheNearestWallInFrontOfTheTerrain) {
  air::AirspaceFile file;
  file.airspaces.push_back(airspace("D", "OUTER", square(-5000.0, -5000.0, 10000.0), msl(0.0), msl(3000.0)));
  file.airspaces.push_back(airspace("R", "INNER", square(-1000.0, -1000.0, 2000.0), msl(0.0), msl(3000.0)));
  VolumeSet set;
  set.volumes = airspace_volumes(file, "p.txt", {}).volumes;
  const std::vector<VolumeShape> shapes = volume_shapes(set, 0.0);
  // From 10 km south at 1000 m, looking north: the outer wall first (5 km away), then the inner.
  const glm::dvec3 from = ecef_from({at(0, -10000).lat, at(0, -10000).lon, 1000.0});
  const glm::dvec3 towards = ecef_from({at(0, 0).lat, at(0, 0).lon, 1000.0});
  const Ray ray{from, glm::normalize(towards - from)};
  const auto hit = pick_volume(shapes, ray, std::numeric_limits<double>::infinity());
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(set.volumes[hit->volume].name, "OUTER");
  EXPECT_NEAR(hit->distance_m, 5000.0, 20.0);
  // Terrain 3 km away hides every wall.
  EXPECT_FALSE(pick_volume(shapes, ray, 3000.0).has_value());
  // The outer one hidden: the inner is next.
  set.volumes[0].visible = false;
  const auto inner = pick_volume(volume_shapes(set, 0.0), ray, std::numeric_limits<double>::infinity());
  ASSERT_TRUE(inner.has_value());
  EXPECT_EQ(set.volumes[inner->volume].name, "INNER");
  EXPECT_NEAR(inner->distance_m, 9000.0, 20.0);
  // Above the ceiling: nothing.
  const glm::dvec3 high = ecef_from({at(0, -10000).lat, at(0, -10000).lon, 5000.0});
  const glm::dvec3 high_to = ecef_from({at(0, 0).lat, at(0, 0).lon, 5000.0});
  EXPECT_FALSE(pick_volume(shapes, Ray{high, glm::normalize(high_to - high)}, 1e9).has_value());
}

TEST(AirspaceVolumes, DescriptionShowsTheLimitsAsWritten) {
  Volume v;
  v.category = "CTR";
  v.name = "MEIRINGEN";
  v.floor_text = "GND";
  v.ceiling_text = "12959 ft";
  EXPECT_EQ(volume_description(v), "CTR MEIRINGEN · GND – 12959 ft");
  v.floor_text.clear();
  v.floor = {VolumeHeightReference::Ground, 300.0, false};
  EXPECT_EQ(volume_description(v), "CTR MEIRINGEN · 300 m AGL – 12959 ft");
  v.name = "CTR Meiringen";  // the class already in the name: not twice
  EXPECT_EQ(volume_description(v), "CTR Meiringen · 300 m AGL – 12959 ft");
  v.name = "MEIRINGEN";
  EXPECT_EQ(volume_tooltip_lines(v),
            (std::vector<std::string>{"MEIRINGEN", "class: CTR", "floor: 300 m AGL", "ceiling: 12959 ft"}));
}

TEST(AirspaceVolumes, NamesAreLabelledHalfwayUpOverTheMiddle) {
  air::AirspaceFile file;
  file.airspaces.push_back(airspace("CTR", "MIDDLE", square(-1000.0, -1000.0, 2000.0), msl(1000.0), msl(3000.0)));
  file.airspaces.push_back(airspace("D", "", square(0, 0, 1000)));  // no name: no label
  VolumeSet set;
  set.volumes = airspace_volumes(file, "n.txt", {}).volumes;
  Scene scene;
  scene.volumes = &set;
  const std::vector<LabelCandidate> labels = label_candidates(scene);
  ASSERT_EQ(labels.size(), 1u);
  EXPECT_EQ(labels[0].text, "CTR MIDDLE");
  const geo::Geodetic g = geo::geodetic_from_ecef(labels[0].anchor_ecef);
  EXPECT_NEAR(g.height_m, 2000.0, 1.0);
  EXPECT_NEAR(g.lat_deg, kLat, 1e-4);
  EXPECT_NEAR(g.lon_deg, kLon, 1e-4);
  EXPECT_GT(labels[0].color.r, labels[0].color.b);  // the class's red
  set.volumes[0].visible = false;
  EXPECT_TRUE(label_candidates(scene).empty());
}

TEST(AirspaceVolumes, TheLegendStacksTheClassesAboveTheColourBar) {
  air::AirspaceFile file;
  file.airspaces.push_back(airspace("CTR", "a", square(0, 0, 1000)));
  file.airspaces.push_back(airspace("Q", "b", square(0, 0, 1000)));
  VolumeSet set;
  set.volumes = airspace_volumes(file, "l.txt", {}).volumes;
  Scene scene;
  scene.volumes = &set;
  const std::vector<TrackKeyEntry> key = airspace_key_for(scene);
  ASSERT_EQ(key.size(), 2u);
  EXPECT_EQ(key[0].name, "CTR control zone");
  EXPECT_EQ(key[0].color_srgb, airspace_class_style("CTR").color_srgb);
  const PixelRect alone = scene_legend_panel(640, 360, scene);
  EXPECT_FALSE(alone.empty());
  // With a colour bar as well: one panel over both, the bar's below.
  scene.style.tracks.color_by = track::ColorMetric::altitude;
  scene.color_range = track::ValueRange{500.0, 1500.0};
  const PixelRect both = scene_legend_panel(640, 360, scene);
  scene.volumes = nullptr;
  const PixelRect bar = scene_legend_panel(640, 360, scene);
  EXPECT_TRUE(both.contains(bar));
  EXPECT_GT(both.height, bar.height + alone.height / 2);
  EXPECT_EQ(both.bottom(), bar.bottom());
  RgbaImage image;
  image.width = 640, image.height = 360;
  image.rgba.assign(640u * 360u * 4u, 0);
  scene.volumes = &set;
  draw_scene_legend(image, scene);
  std::size_t painted_above_bar = 0;
  for (int y = both.y; y < bar.y; ++y)
    for (int x = both.x; x < both.right(); ++x)
      painted_above_bar += image.pixel(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y))[3] > 0;
  EXPECT_GT(painted_above_bar, 100u);
}

TEST(AirspaceVolumes, ShownAndHiddenByKind) {
  VolumeSet set;
  set.volumes.resize(2);
  set.volumes[1].kind = VolumeKind::TaskCylinder;
  set_volumes_visible(set, VolumeKind::Airspace, false);
  EXPECT_FALSE(set.volumes[0].visible);
  EXPECT_TRUE(set.volumes[1].visible);
  EXPECT_EQ(set.revision, 1u);
}

TEST(AirspaceVolumes, SwissFileAroundInterlaken) {
  const auto path = test::shared_data() / "airspace" / "openairrs_Switzerland.txt";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared data absent: " << path;
  const air::AirspaceReadResult read = air::load_openair_file(path.string());
  ASSERT_TRUE(read.ok());
  AirspaceDrawOptions options;
  geo::LatLonBounds interlaken;
  interlaken.add(46.68, 7.81);
  interlaken.add(46.74, 7.93);
  options.region = interlaken;
  options.max_floor_m = 4500.0;
  const AirspaceVolumes built = airspace_volumes(read.file, path.string(), options);
  EXPECT_LT(built.volumes.size(), read.file.airspaces.size() / 3);
  EXPECT_GT(built.outside_region, read.file.airspaces.size() / 2);
  bool heliport = false, meiringen = false;
  for (const Volume& v : built.volumes) {
    heliport = heliport || v.name.find("INTERLAKEN HP") != std::string::npos;
    meiringen = meiringen || v.name.find("MEIRINGEN") != std::string::npos;
    EXPECT_LE(v.floor.metres, 4500.0) << v.name;
  }
  EXPECT_TRUE(heliport);
  EXPECT_TRUE(meiringen);
  EXPECT_LE(built.points_after, built.points_before + 2000);  // simplified, then densified where AGL
}

}  // namespace
}  // namespace trailray::scene
