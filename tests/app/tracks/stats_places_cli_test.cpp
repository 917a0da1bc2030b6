// `trailray stats --places`: the summits a track reached and the huts it passed, from a real
// OpenStreetMap file (Liechtenstein 2013) and a hike written at test time over its real peaks.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "app/run_command.hpp"
#include "test_support.hpp"

using nlohmann::json;
using trailray::test::run_command;
using trailray::test::shell_quote;
using trailray::test::TempFile;

namespace {

std::string binary() { return shell_quote(TRAILRAY_BINARY); }

struct Fix {
  double lat, lon, ele;
};

// Liechtenstein 2013's nodes: Naafkopf (mapped twice, 2571 and 2570 m), Hinter Grauspitz 2574 m,
// Vorder Grauspitz 2599 m, the hut Guschg (no ele).
constexpr Fix kNaafkopf{47.0607725, 9.6070544, 2566.0};             // 5 m below the summit
constexpr Fix kHinterGrauspitz{47.0548251, 9.5874533, 2500.0};      // 74 m below: not reached
constexpr Fix kVorderGrauspitz{47.0527317 + 0.0002, 9.5812795, 2596.0};  // 22 m north of it
constexpr Fix kGuschg{47.1246839, 9.6039388, 1900.0};

// A hike from fix to fix, a point every 0.0005° (about 50 m) and 60 s from 08:00 UTC.
std::string hike_gpx(std::initializer_list<Fix> stops) {
  std::string gpx = "<gpx version=\"1.1\"><trk><name>Ridge</name><trkseg>\n";
  int second = 0;
  const Fix* previous = nullptr;
  const auto point = [&](double lat, double lon, double ele) {
    gpx += fmt::format("<trkpt lat=\"{:.7f}\" lon=\"{:.7f}\"><ele>{:.1f}</ele><time>2024-07-01T{:02}:{:02}:{:02}Z</time></trkpt>\n",
                       lat, lon, ele, 8 + second / 3600, second / 60 % 60, second % 60);
    second += 60;
  };
  for (const Fix& stop : stops) {
    if (previous != nullptr) {
      const int steps = static_cast<int>(std::ceil(std::max(std::fabs(stop.lat - previous->lat),
                                                            std::fabs(stop.lon - previous->lon)) / 0.0005));
      for (int i = 1; i < steps; ++i) {
        const double t = static_cast<double>(i) / steps;
        // Between stops the path dips 150 m: only the stops are high.
        point(previous->lat + (stop.lat - previous->lat) * t, previous->lon + (stop.lon - previous->lon) * t,
              std::min(previous->ele, stop.ele) - 150.0);
      }
    }
    point(stop.lat, stop.lon, stop.ele);
    previous = &stop;
  }
  return gpx + "</trkseg></trk></gpx>\n";
}

}  // namespace

TEST(StatsPlacesCli, SummitsReachedAndHutsPassed) {
  TRAILRAY_REQUIRE_DATA(osm, "osm/osm2pgsql_liechtenstein-2013-08-03.osm.pbf");
  TempFile gpx("ridge.gpx", hike_gpx({kGuschg, kNaafkopf, kHinterGrauspitz, kVorderGrauspitz}));
  const auto r = run_command(binary() + " stats --json --places " + shell_quote(osm.string()) + " " +
                             shell_quote(gpx.str()) + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  const json doc = json::parse(r.out);
  const json& track = doc["files"][0]["tracks"][0];
  ASSERT_TRUE(track.contains("summits")) << track.dump();
  const json& summits = track["summits"];
  // Naafkopf once (its two nodes merged), Vorder Grauspitz; not Hinter Grauspitz (74 m below).
  ASSERT_EQ(summits.size(), 2u) << summits.dump(2);
  EXPECT_EQ(summits[0]["name"], "Naafkopf");
  EXPECT_EQ(summits[0]["ele"], 2571.0);
  EXPECT_NEAR(summits[0]["lat"].get<double>(), 47.0607725, 1e-7);
  EXPECT_EQ(summits[1]["name"], "Vorder Grauspitz");
  EXPECT_EQ(summits[1]["ele"], 2599.0);
  EXPECT_NEAR(summits[1]["distance_m"].get<double>(), 22.2, 0.5);
  // The times of the nearest approaches, in the order reached.
  ASSERT_TRUE(summits[0]["time"].is_string());
  EXPECT_LT(summits[0]["time"].get<std::string>(), summits[1]["time"].get<std::string>());
  EXPECT_EQ(summits[0]["time"].get<std::string>().substr(0, 11), "2024-07-01T");
  const json& huts = track["huts"];
  ASSERT_EQ(huts.size(), 1u);
  EXPECT_EQ(huts[0]["name"], "Guschg");
  EXPECT_TRUE(huts[0]["ele"].is_null());
  EXPECT_EQ(huts[0]["time"], "2024-07-01T08:00:00Z");

  // The table lists them under the track.
  const auto table = run_command(binary() + " stats --places " + shell_quote(osm.string()) + " " +
                                 shell_quote(gpx.str()) + " 2>&1");
  ASSERT_EQ(table.status, 0) << table.out;
  EXPECT_NE(table.out.find("Ridge: summits reached: Naafkopf 2571 m ("), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("Vorder Grauspitz 2599 m"), std::string::npos) << table.out;
  EXPECT_EQ(table.out.find("Hinter Grauspitz"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("Ridge: huts passed: Guschg (08:00:00 UTC)"), std::string::npos) << table.out;
}

TEST(StatsPlacesCli, WithoutPlacesNoKeysAndAnUnreadableFileIsAnError) {
  TempFile gpx("ridge.gpx", hike_gpx({kNaafkopf, kVorderGrauspitz}));
  const auto plain = run_command(binary() + " stats --json " + shell_quote(gpx.str()));
  ASSERT_EQ(plain.status, 0) << plain.out;
  EXPECT_FALSE(json::parse(plain.out)["files"][0]["tracks"][0].contains("summits"));

  TempFile bad("bad.osm.pbf", "this is no OpenStreetMap file");
  const auto r = run_command(binary() + " stats --places " + shell_quote(bad.str()) + " " + shell_quote(gpx.str()) +
                             " 2>&1");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("bad.osm.pbf: cannot read OpenStreetMap data"), std::string::npos) << r.out;
}
