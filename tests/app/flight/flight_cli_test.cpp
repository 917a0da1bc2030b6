// `trailray flight` as a user runs it: the report and the JSON of a simulated flight whose
// thermals and wind are known, two flights in one file, tracks without times, bad input.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "app/run_command.hpp"
#include "test_support.hpp"
#include "track/flight/synthetic_flight.hpp"

using nlohmann::json;
using trailray::test::run_command;
using trailray::test::shell_quote;
using trailray::test::TempFile;
using trailray::track::test::SyntheticFlight;

namespace {

std::string binary() { return shell_quote(TRAILRAY_BINARY); }

// The simulated fixes as an IGC log (GNSS and pressure altitude alike, or pressure 0), every
// `every`th fix.
std::string igc_of(const SyntheticFlight& sim, bool with_pressure = true, std::size_t every = 1) {
  std::string s = "AXXX001\r\nHFDTE150619\r\n";
  for (std::size_t i = 0; i < sim.points().size(); i += every) {
    const auto& p = sim.points()[i];
    const auto secs = static_cast<long>(p.time) % 86400;
    const long latm = std::lround(std::fabs(p.lat) * 60000), lonm = std::lround(std::fabs(p.lon) * 60000);
    const long alt = std::lround(p.ele);
    char buf[80];
    std::snprintf(buf, sizeof buf, "B%02ld%02ld%02ld%02ld%05ld%c%03ld%05ld%cA%05ld%05ld\r\n", secs / 3600,
                  secs / 60 % 60, secs % 60, latm / 60000, latm % 60000, p.lat < 0 ? 'S' : 'N', lonm / 60000,
                  lonm % 60000, p.lon < 0 ? 'W' : 'E', with_pressure ? alt : 0L, alt);
    s += buf;
  }
  return s;
}

// Ground, a glide, a right thermal (+2 m/s), a glide, a left thermal (+1.5 m/s), a glide,
// ground; wind 5 m/s from 300 degrees.
SyntheticFlight two_thermals() {
  SyntheticFlight sim(5.0, 300.0);
  sim.ground(120);
  sim.glide(150, 0.0);
  sim.circle(200, true, 2.0);
  sim.glide(400, 120.0, 10.0, 1.2);
  sim.circle(160, false, 1.5);
  sim.glide(200, 100.0);
  sim.ground(120);
  return sim;
}

double angle_diff(double a, double b) {
  const double d = std::fmod(std::fabs(a - b), 360.0);
  return d > 180.0 ? 360.0 - d : d;
}

}  // namespace

TEST(FlightCli, ReportListsThermalsGlidesAndWind) {
  TempFile f("flight.igc", igc_of(two_thermals()));
  auto r = run_command(binary() + " flight " + shell_quote(f.str()));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("1 flight\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("flight 1 of 1: 2019-06-15"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("thermals   2, mean climb +1."), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  right  "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  left  "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("best glide L/D"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("wind by altitude"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("m/s from 30"), std::string::npos) << r.out;  // from about 300 degrees
}

TEST(FlightCli, JsonHasTheDocumentedShapeAndTheSimulatedFigures) {
  TempFile f("flight.igc", igc_of(two_thermals()));
  auto r = run_command(binary() + " flight --json " + shell_quote(f.str()));
  ASSERT_EQ(r.status, 0) << r.out;
  const json doc = json::parse(r.out);
  ASSERT_EQ(doc["files"].size(), 1u);
  const json& file = doc["files"][0];
  EXPECT_EQ(file["path"], f.str());
  EXPECT_EQ(file["format"], "igc");
  ASSERT_EQ(file["tracks"].size(), 1u);
  const json& track = file["tracks"][0];
  EXPECT_TRUE(track["note"].is_null());
  EXPECT_TRUE(track["has_altitude"].get<bool>());
  ASSERT_EQ(track["flights"].size(), 1u);
  const json& flight = track["flights"][0];
  for (const char* key : {"duration_s", "distance_m", "max_alt_m", "min_alt_m", "circling_share", "circling_s",
                          "gliding_s", "unknown_s", "mean_thermal_climb_ms", "best_climb_ms"})
    EXPECT_TRUE(flight[key].is_number()) << key;
  for (const char* key : {"time", "lat", "lon", "alt_m", "point"})
    EXPECT_FALSE(flight["takeoff"][key].is_null()) << key;
  EXPECT_EQ(flight["takeoff"]["time"].get<std::string>().substr(0, 11), "2019-06-15T");
  EXPECT_NEAR(flight["duration_s"].get<double>(), 150 + 200 + 400 + 160 + 200, 12.0);
  ASSERT_EQ(flight["thermals"].size(), 2u);
  EXPECT_EQ(flight["thermals"][0]["direction"], "right");
  EXPECT_EQ(flight["thermals"][1]["direction"], "left");
  EXPECT_NEAR(flight["thermals"][0]["mean_climb_ms"].get<double>(), 2.0, 0.2);
  EXPECT_NEAR(flight["thermals"][1]["mean_climb_ms"].get<double>(), 1.5, 0.2);
  // IGC positions are rounded to 0.001 minute (about 2 m): the wind still comes out within
  // 0.3 m/s and 4 degrees.
  for (const json& t : flight["thermals"]) {
    EXPECT_TRUE(t["wind_from_centres"].get<bool>());
    EXPECT_NEAR(t["wind_speed_ms"].get<double>(), 5.0, 0.3);
    EXPECT_LT(angle_diff(t["wind_from_deg"].get<double>(), 300.0), 4.0);
    EXPECT_LT(angle_diff(t["drift_to_deg"].get<double>(), 120.0), 4.0);
    EXPECT_NEAR(t["gain_m"].get<double>(), t["exit_alt_m"].get<double>() - t["entry_alt_m"].get<double>(), 0.2);
    EXPECT_TRUE(t["phase"].is_number_integer());
  }
  ASSERT_EQ(flight["glides"].size(), 3u);
  for (const json& g : flight["glides"]) {
    for (const char* key : {"duration_s", "distance_m", "height_lost_m", "glide_ratio", "mean_speed_ms"})
      EXPECT_TRUE(g[key].is_number()) << key;
    EXPECT_NEAR(g["glide_ratio"].get<double>(), g["distance_m"].get<double>() / g["height_lost_m"].get<double>(), 0.1);
  }
  // Best glide: the best ratio among glides of 2 km or more that lost 100 m or more.
  int best = -1;
  for (std::size_t i = 0; i < flight["glides"].size(); ++i) {
    const json& g = flight["glides"][i];
    if (g["distance_m"].get<double>() >= 2000 && g["height_lost_m"].get<double>() >= 100 &&
        (best < 0 || g["glide_ratio"].get<double>() >
                         flight["glides"][static_cast<std::size_t>(best)]["glide_ratio"].get<double>()))
      best = static_cast<int>(i);
  }
  EXPECT_GE(best, 1);  // the first glide (1.5 km) is too short
  EXPECT_EQ(flight["best_glide"], best);
  ASSERT_FALSE(flight["wind"].empty());
  for (const json& w : flight["wind"]) EXPECT_NEAR(w["speed_ms"].get<double>(), 5.0, 0.3);
  // Phases tile the flight.
  double sum = 0;
  for (const json& p : flight["phases"]) sum += p["duration_s"].get<double>();
  EXPECT_NEAR(sum, flight["duration_s"].get<double>(), 1e-6);
  EXPECT_EQ(doc["settings"]["best_climb_window_s"], 20.0);
}

TEST(FlightCli, TwoFlightsInOneFile) {
  SyntheticFlight sim(2.0, 200.0);
  sim.ground(200);
  sim.glide(120, 0.0);
  sim.circle(120, true, 2.0);
  sim.glide(120, 90.0);
  sim.ground(900);
  sim.glide(120, 180.0, 10.0, 1.5);
  sim.circle(120, false, 1.0);
  sim.glide(120, 270.0);
  sim.ground(200);
  TempFile f("two.igc", igc_of(sim));
  auto r = run_command(binary() + " flight --json " + shell_quote(f.str()));
  ASSERT_EQ(r.status, 0) << r.out;
  const json flights = json::parse(r.out)["files"][0]["tracks"][0]["flights"];
  ASSERT_EQ(flights.size(), 2u);
  EXPECT_GT(flights[1]["takeoff"]["point"].get<int>() - flights[0]["landing"]["point"].get<int>(), 800);
  auto text = run_command(binary() + " flight " + shell_quote(f.str()));
  EXPECT_NE(text.out.find("2 flights"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("flight 2 of 2"), std::string::npos) << text.out;
}

TEST(FlightCli, TrackWithoutTimesGetsAMessage) {
  TempFile f("route.gpx", R"(<gpx version="1.1"><trk><name>No clock</name><trkseg>
<trkpt lat="46.0" lon="7.0"><ele>1000</ele></trkpt>
<trkpt lat="46.01" lon="7.0"><ele>900</ele></trkpt>
</trkseg></trk></gpx>)");
  auto r = run_command(binary() + " flight " + shell_quote(f.str()));
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("track 1 \"No clock\": no times: flight analysis needs timed points"), std::string::npos)
      << r.out;
  auto j = run_command(binary() + " flight --json " + shell_quote(f.str()));
  ASSERT_EQ(j.status, 0) << j.out;
  const json track = json::parse(j.out)["files"][0]["tracks"][0];
  EXPECT_TRUE(track["flights"].empty());
  EXPECT_EQ(track["points_used"], 0);
  EXPECT_NE(track["note"].get<std::string>().find("no times"), std::string::npos);
}

TEST(FlightCli, IgcAltitudeOptionIsUsed) {
  // No barometer: with --igc-altitude pressure the points have no elevation, so no flight.
  TempFile f("gnss-only.igc", igc_of(two_thermals(), false));
  auto gnss = run_command(binary() + " flight --json " + shell_quote(f.str()));
  ASSERT_EQ(gnss.status, 0) << gnss.out;
  EXPECT_EQ(json::parse(gnss.out)["files"][0]["tracks"][0]["flights"].size(), 1u);
  auto pressure = run_command(binary() + " flight --json --igc-altitude pressure " + shell_quote(f.str()) + " 2>&1");
  ASSERT_EQ(pressure.status, 0) << pressure.out;
  const std::string out = pressure.out.substr(pressure.out.find('{'));
  const json track = json::parse(out)["files"][0]["tracks"][0];
  EXPECT_TRUE(track["flights"].empty());
  EXPECT_FALSE(track["has_altitude"].get<bool>());
  EXPECT_NE(track["note"].get<std::string>().find("no elevation"), std::string::npos);
}

TEST(FlightCli, CoarseFixesAreNoted) {
  TempFile f("coarse.igc", igc_of(two_thermals(), true, 10));
  auto r = run_command(binary() + " flight " + shell_quote(f.str()));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("note: fixes 10 s apart"), std::string::npos) << r.out;
  auto j = run_command(binary() + " flight --json " + shell_quote(f.str()));
  EXPECT_EQ(json::parse(j.out)["files"][0]["tracks"][0]["fix_interval_s"], 10.0);
  TempFile fine("fine.igc", igc_of(two_thermals()));
  EXPECT_EQ(run_command(binary() + " flight " + shell_quote(fine.str())).out.find("note:"), std::string::npos);
}

TEST(FlightCli, UnreadableFileIsNamed) {
  TempFile bad("broken.igc", "this is not a flight log\n");
  auto r = run_command(binary() + " flight " + shell_quote(bad.str()) + " /nonexistent/x.igc 2>&1");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find(bad.str()), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("/nonexistent/x.igc"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2 of 2 files could not be read"), std::string::npos) << r.out;
}

TEST(FlightCli, HelpDocumentsTheJson) {
  auto r = run_command(binary() + " flight --help");
  ASSERT_EQ(r.status, 0);
  for (const char* s : {"--json", "--igc-altitude", "--strict", "\"thermals\"", "\"wind_from_deg\"", "glide_ratio",
                        "FROM that direction"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s;
}

TEST(FlightCli, RealFlightWithAMiddleLanding) {
  TRAILRAY_REQUIRE_DATA(path, "igc/igclib_flight_with_middle_landing.igc");
  auto r = run_command(binary() + " flight --json " + shell_quote(path.string()));
  ASSERT_EQ(r.status, 0);
  const json flights = json::parse(r.out)["files"][0]["tracks"][0]["flights"];
  ASSERT_EQ(flights.size(), 2u);
  EXPECT_LT(flights[0]["landing"]["time"].get<std::string>(), flights[1]["takeoff"]["time"].get<std::string>());
  for (const json& fl : flights) EXPECT_GT(fl["thermal_count"].get<int>(), 3);
}

// --task: the flight's result against a task follows its report. A task made around the
// simulated flight: the take-off where it starts, a cylinder around its middle (reached), one
// 50 km away (not reached).
TEST(FlightCli, TaskResultFollowsTheReport) {
  const SyntheticFlight sim = two_thermals();
  const auto& start = sim.points().front();
  const auto& middle = sim.points()[sim.points().size() / 2];
  const std::string tp = R"({{"radius":{},"waypoint":{{"name":"{}","lat":{:.6f},"lon":{:.6f}}}{}}})";
  const std::string task_json =
      R"({"version":1,"taskType":"CLASSIC","turnpoints":[)" +
      fmt::format(fmt::runtime(tp), 400, "LAUNCH", start.lat, start.lon, R"(,"type":"TAKEOFF")") + "," +
      fmt::format(fmt::runtime(tp), 500, "MIDDLE", middle.lat, middle.lon, "") + "," +
      fmt::format(fmt::runtime(tp), 400, "FAR", middle.lat + 0.45, middle.lon, "") + "]}";
  TempFile task("t.xctsk", task_json);
  TempFile f("flight.igc", igc_of(sim));
  const auto text = run_command(binary() + " flight --task " + shell_quote(task.str()) + " " + shell_quote(f.str()));
  ASSERT_EQ(text.status, 0) << text.out;
  EXPECT_NE(text.out.find("thermals   2"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("2 of 3 turnpoints, no goal"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("FAR"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("not reached"), std::string::npos) << text.out;

  const auto r =
      run_command(binary() + " flight --json --task " + shell_quote(task.str()) + " " + shell_quote(f.str()));
  ASSERT_EQ(r.status, 0) << r.out;
  const json doc = json::parse(r.out);
  ASSERT_EQ(doc["task"]["turnpoints"].size(), 3u);
  const json& result = doc["files"][0]["task"];
  EXPECT_EQ(result["reached_count"], 2);
  ASSERT_EQ(result["reached"].size(), 2u);
  EXPECT_EQ(result["reached"][1]["name"], "MIDDLE");
  // Reached after the take-off (the log's first fix), within the simulated flight's duration.
  const double launched = result["reached"][0]["time"].get<double>();
  const double reached = result["reached"][1]["time"].get<double>();
  EXPECT_GT(reached, launched);
  EXPECT_LT(reached - launched, sim.points().back().time - start.time);

  TempFile bad("bad.xctsk", R"({"version":1,"turnpoints":[]})");
  const auto broken =
      run_command(binary() + " flight --task " + shell_quote(bad.str()) + " " + shell_quote(f.str()) + " 2>&1");
  EXPECT_EQ(broken.status, 1);
  EXPECT_NE(broken.out.find(bad.str()), std::string::npos) << broken.out;
}
