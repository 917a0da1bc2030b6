// `trailray check` as a user runs it: exit status (0 none, 1 found, 2 usage or unreadable file),
// the text and --json output, FL limits against an IGC file's pressure altitude.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/run_command.hpp"
#include "test_support.hpp"

using nlohmann::json;
using trailray::test::run_command;
using trailray::test::shell_quote;
using trailray::test::TempFile;

namespace {

// A 5 km circle around 47 N 8 E, and a polygon far away.
const char* kAirspace =
    "* test\r\nAC R\r\nAN Test Circle\r\nAL GND\r\nAH 2000 m\r\nV X=47:00:00 N 008:00:00 E\r\nDC 2.6998\r\n"
    "AC D\r\nAN Far Away\r\nAL FL 100\r\nAH FL 150\r\nDP 10:00:00 N 010:00:00 E\r\nDP 10:00:00 N 011:00:00 E\r\n"
    "DP 11:00:00 N 011:00:00 E\r\n";

// Due north through the circle's centre at `ele` metres, one fix every 10 s.
std::string gpx(double ele) {
  std::ostringstream s;
  s << "<?xml version=\"1.0\"?><gpx version=\"1.1\" creator=\"test\"><trk><trkseg>";
  for (int i = 0; i <= 200; ++i) {
    char time[32];
    std::snprintf(time, sizeof time, "2024-06-01T10:%02d:%02dZ", (i * 10) / 60, (i * 10) % 60);
    s << "<trkpt lat=\"" << 46.9 + 0.001 * i << "\" lon=\"8\"><ele>" << ele << "</ele><time>" << time
      << "</time></trkpt>";
  }
  s << "</trkseg></trk></gpx>";
  return s.str();
}

// An IGC flight through a FL 100..FL 150 circle: pressure altitude `pressure`, GNSS `gnss`.
std::string igc(int pressure, int gnss) {
  std::ostringstream s;
  s << "AXXX001\r\nHFDTE010624\r\n";
  for (int i = 0; i <= 120; ++i) {
    const double lat_min = 54.0 + 0.1 * i;  // 46:54.000 N .. 47:06.000 N
    char line[64];
    std::snprintf(line, sizeof line, "B10%02d%02d46%05dN00800000EA%05d%05d\r\n", i / 60, i % 60,
                  static_cast<int>(std::lround(lat_min * 1000)), pressure, gnss);
    s << line;
  }
  return s.str();
}

std::string cli(const std::string& args) { return shell_quote(TRAILRAY_BINARY) + " check " + args + " 2>&1"; }

}  // namespace

TEST(CheckCli, ExitOneWithTheInfringementZeroWithout) {
  TempFile air("air.txt", kAirspace);
  TempFile low("low.gpx", gpx(1000)), high("high.gpx", gpx(2500));
  auto r = run_command(cli("--airspace " + air.str() + " " + low.str()));
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("Test Circle [R] GND .. 2000 m"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ground unknown"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1 infringement in 1 track against 2 airspaces"), std::string::npos) << r.out;
  r = run_command(cli("--airspace " + air.str() + " " + high.str()));
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("0 infringements"), std::string::npos) << r.out;
  r = run_command(cli("--airspace " + air.str() + " " + high.str() + " " + low.str()));
  EXPECT_EQ(r.status, 1) << r.out;
}

TEST(CheckCli, JsonShape) {
  TempFile air("air.txt", kAirspace);
  TempFile low("low.gpx", gpx(1000));
  const auto r = run_command(shell_quote(TRAILRAY_BINARY) + " check --json --airspace " + air.str() + " " + low.str());
  ASSERT_EQ(r.status, 1) << r.out;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["airspaces"], 2);
  EXPECT_EQ(j["infringements"], 1);
  ASSERT_EQ(j["tracks"].size(), 1u);
  const json& t = j["tracks"][0];
  EXPECT_EQ(t["points"], 201);
  ASSERT_EQ(t["infringements"].size(), 1u);
  const json& f = t["infringements"][0];
  EXPECT_EQ(f["airspace"], "Test Circle");
  EXPECT_EQ(f["class"], "R");
  EXPECT_EQ(f["floor"]["reference"], "AGL");
  EXPECT_EQ(f["ceiling"]["reference"], "MSL");
  EXPECT_NEAR(f["ceiling"]["metres"].get<double>(), 2000, 1e-9);
  // Enters 5 km south of 47 N: (46.955 - 46.9) / 0.001 * 10 s = 550 s after 10:00:00, give or take
  // the ellipsoid's 5 km (0.0450 degrees there) and the 1 m chord error.
  const std::string entry = f["entry_time"];
  EXPECT_EQ(entry.substr(0, 16), "2024-06-01T10:09") << entry;
  EXPECT_NEAR(f["duration_s"].get<double>(), 2 * 5000 / (111195.0 * 0.001 / 10), 2.0);
  EXPECT_GT(f["max_horizontal_m"].get<double>(), 4900);
  EXPECT_NEAR(f["max_below_ceiling_m"].get<double>(), 1000, 1e-9);
  EXPECT_TRUE(f["max_above_floor_m"].is_null());
  EXPECT_EQ(f["ceiling_altitude"], "gnss");
  EXPECT_EQ(f["ground_assumed"], true);
  for (const char* key : {"line", "segment", "first_point", "last_point", "exit_time", "inside_at_start",
                          "inside_at_end", "max_vertical_m", "floor_altitude"})
    EXPECT_TRUE(f.contains(key)) << key;
}

TEST(CheckCli, FlightLevelsAgainstIgcPressureAltitude) {
  const std::string air_text = "AC D\nAN Level Box\nAL FL 100\nAH FL 150\nV X=47:00:00 N 008:00:00 E\nDC 2.6998\n";
  TempFile air("air.txt", air_text);
  TempFile flight("flight.igc", igc(3200, 2900));  // pressure above FL 100 (3048 m), GNSS below
  auto r = run_command(shell_quote(TRAILRAY_BINARY) + " check --json --airspace " + air.str() + " " + flight.str());
  ASSERT_EQ(r.status, 1) << r.out;
  const json j = json::parse(r.out);
  const json& f = j["tracks"][0]["infringements"][0];
  EXPECT_EQ(f["floor_altitude"], "pressure");
  EXPECT_NEAR(f["max_above_floor_m"].get<double>(), 3200 - 3048, 1e-6);
  EXPECT_NE(j["tracks"][0]["altitudes"].get<std::string>().find("1013.25"), std::string::npos);
  // GNSS for everything: below the floor.
  r = run_command(cli("--igc-altitude gnss --airspace " + air.str() + " " + flight.str()));
  EXPECT_EQ(r.status, 0) << r.out;
}

TEST(CheckCli, UsageAndUnreadableFilesExitTwo) {
  TempFile air("air.txt", kAirspace);
  TempFile low("low.gpx", gpx(1000));
  TempFile broken("broken.txt", "AC R\nAN X\nAL GND\nAH 1000 ft\nDP 95:00:00 N 008:00:00 E\n");
  EXPECT_EQ(run_command(cli(low.str())).status, 2);                           // no --airspace
  EXPECT_EQ(run_command(cli("--airspace " + air.str())).status, 2);           // no track
  auto r = run_command(cli("--airspace " + broken.str() + " " + low.str()));  // FILE:LINE
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find(broken.str() + ":5:"), std::string::npos) << r.out;
  TempFile flat("flat.gpx",
                "<?xml version=\"1.0\"?><gpx version=\"1.1\" creator=\"t\"><trk><trkseg><trkpt lat=\"47\" "
                "lon=\"8\"/><trkpt lat=\"47.001\" lon=\"8\"/></trkseg></trk></gpx>");
  r = run_command(cli("--airspace " + air.str() + " " + flat.str()));  // no altitude: said, not guessed
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("2 of 2 points have no altitude"), std::string::npos) << r.out;
  r = run_command(cli("--airspace " + air.str() + " /nonexistent/track.gpx"));
  EXPECT_EQ(r.status, 2) << r.out;
}

TEST(CheckCli, AglFloorWithTerrainUsesTheGround) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/interlaken_dhm25_wgs84.tif");
  TRAILRAY_REQUIRE_DATA(flight, "igc/goigc_0100_interlaken.igc");
  TempFile air("air.txt",
               "AC R\nAN Box\nAL 300 ft AGL\nAH 3000 m\nDP 46:40:00 N 007:48:00 E\nDP 46:40:00 N 007:56:00 E\n"
               "DP 46:45:00 N 007:56:00 E\nDP 46:45:00 N 007:48:00 E\n");
  const std::string base = shell_quote(TRAILRAY_BINARY) + " check -q --json --airspace " + air.str() + " ";
  auto with = run_command(base + "--terrain " + shell_quote(dem.string()) + " " + shell_quote(flight.string()));
  auto without = run_command(base + shell_quote(flight.string()));
  ASSERT_EQ(with.status, 1) << with.out;
  ASSERT_EQ(without.status, 1) << without.out;
  const json w = json::parse(with.out), wo = json::parse(without.out);
  EXPECT_EQ(w["terrain"], true);
  // Without the ground the floor sits at 91 m above sea level: the whole flight (launch at about
  // 1900 m, landing near Interlaken at about 570 m) is inside, in one piece.
  ASSERT_EQ(wo["tracks"][0]["infringements"].size(), 1u);
  EXPECT_EQ(wo["tracks"][0]["infringements"][0]["ground_assumed"], true);
  // With it, the parts within 300 ft of the ground are not: several shorter stretches.
  const json& list = w["tracks"][0]["infringements"];
  ASSERT_GE(list.size(), 2u);
  for (const auto& f : list) {
    EXPECT_EQ(f["floor_altitude"], "gnss-ground");
    EXPECT_EQ(f["ground_assumed"], false);
    EXPECT_GE(f["max_above_floor_m"].get<double>(), 0.0);
  }
}
