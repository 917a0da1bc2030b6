// `trailray stats` on KML and KMZ files as a user runs it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "app/run_command.hpp"
#include "test_support.hpp"

using nlohmann::json;
using trailray::test::run_command;
using trailray::test::shell_quote;
using trailray::test::TempFile;

namespace {

std::string binary() { return shell_quote(TRAILRAY_BINARY); }

// A 2-point gx:Track with absolute altitudes and a 2-point LineString without an altitudeMode.
const char* kTwoPlacemarks = R"(<?xml version="1.0" encoding="UTF-8"?>
<kml xmlns="http://www.opengis.net/kml/2.2" xmlns:gx="http://www.google.com/kml/ext/2.2"><Document>
<Placemark><name>Climb</name><gx:Track><altitudeMode>absolute</altitudeMode>
<when>2024-06-01T10:00:00Z</when><when>2024-06-01T12:01:00+02:00</when>
<gx:coord>7.0 46.0 1000</gx:coord><gx:coord>7.0 46.0009 1010</gx:coord>
</gx:Track></Placemark>
<Placemark><name>Walk</name><LineString><coordinates>7.1,46.1,500 7.1,46.1009,900</coordinates></LineString></Placemark>
<Placemark><name>Hut</name><Point><coordinates>7.05,46.05</coordinates></Point></Placemark>
</Document></kml>)";

}  // namespace

TEST(StatsKmlCli, TracksFiguresAndClampedAltitudes) {
  TempFile f("day.kml", kTwoPlacemarks);
  auto r = run_command(binary() + " stats --json " + shell_quote(f.str()));
  ASSERT_EQ(r.status, 0) << r.out;
  const json file = json::parse(r.out)["files"][0];
  EXPECT_EQ(file["format"], "kml");
  EXPECT_EQ(file["waypoints"], 1);
  ASSERT_EQ(file["tracks"].size(), 2u);
  const json climb = file["tracks"][0]["raw"];
  EXPECT_EQ(file["tracks"][0]["name"], "Climb");
  EXPECT_EQ(climb["points"], 2);
  EXPECT_EQ(climb["duration_s"], 60.0);  // the +02:00 offset applied
  EXPECT_EQ(climb["max_elevation_m"], 1010.0);
  EXPECT_NEAR(climb["distance_2d_m"].get<double>(), 100.07, 0.5);
  // No altitudeMode is clampToGround: the 500 and 900 are not elevations.
  const json walk = file["tracks"][1]["raw"];
  EXPECT_EQ(walk["points"], 2);
  EXPECT_TRUE(walk["elevation_gain_m"].is_null());
  EXPECT_TRUE(walk["max_elevation_m"].is_null());
}

TEST(StatsKmlCli, RealKmlAndKmzFiles) {
  TRAILRAY_REQUIRE_DATA(skydrop, "kml/gpsbabel_skydrop.kml");
  TRAILRAY_REQUIRE_DATA(kmz, "kml/geotag_kmz1.kmz");
  auto r = run_command(binary() + " stats --json " + shell_quote(skydrop.string()) + " " + shell_quote(kmz.string()));
  ASSERT_EQ(r.status, 0) << r.out;
  const json doc = json::parse(r.out);
  const json flight = doc["files"][0];
  EXPECT_EQ(flight["format"], "kml");
  ASSERT_EQ(flight["tracks"].size(), 1u);
  EXPECT_EQ(flight["tracks"][0]["raw"]["points"], 1329);
  EXPECT_GT(flight["tracks"][0]["raw"]["elevation_gain_m"].get<double>(), 0.0);  // altitudeMode absolute
  const json archive = doc["files"][1];
  EXPECT_EQ(archive["format"], "kmz");
  EXPECT_EQ(archive["tracks"].size(), 8u);
  EXPECT_EQ(archive["waypoints"], 6);
}

TEST(StatsKmlCli, KmzWithoutKmlFailsNamingTheFile) {
  TRAILRAY_REQUIRE_DATA(empty, "kml/furkot_no-kml-inside.kmz");
  TempFile err("stderr.txt");
  auto r = run_command(binary() + " stats " + shell_quote(empty.string()) + " 2>" + shell_quote(err.str()));
  EXPECT_NE(r.status, 0);
  auto text = run_command("cat " + shell_quote(err.str()));
  EXPECT_NE(text.out.find(empty.string() + ": no KML document inside the KMZ archive"), std::string::npos) << text.out;
}
