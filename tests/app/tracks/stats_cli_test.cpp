// `trailray stats` as a user runs it: exit codes, JSON shape, stdin, several files, errors.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <vector>

#include "app/run_command.hpp"
#include "test_support.hpp"

using nlohmann::json;
using trailray::test::run_command;
using trailray::test::shell_quote;
using trailray::test::TempFile;

namespace {

std::string binary() { return shell_quote(TRAILRAY_BINARY); }

const char* kTwoSegments = R"(<gpx version="1.1"><trk><name>Loop</name>
<trkseg>
<trkpt lat="46.00000" lon="7.0"><ele>1000</ele><time>2024-06-01T10:00:00Z</time></trkpt>
<trkpt lat="46.00090" lon="7.0"><ele>1010</ele><time>2024-06-01T10:01:00Z</time></trkpt>
<trkpt lat="46.00180" lon="7.0"><ele>1020</ele><time>2024-06-01T10:02:00Z</time></trkpt>
</trkseg>
<trkseg>
<trkpt lat="46.10000" lon="7.0"><ele>900</ele><time>2024-06-01T12:00:00Z</time></trkpt>
<trkpt lat="46.10090" lon="7.0"><ele>900</ele><time>2024-06-01T12:01:00Z</time></trkpt>
</trkseg></trk><wpt lat="46" lon="7"><name>start</name></wpt></gpx>)";

}  // namespace

TEST(StatsCli, JsonHasTheDocumentedShape) {
  TempFile f("loop.gpx", kTwoSegments);
  auto r = run_command(binary() + " stats --json " + shell_quote(f.str()));
  ASSERT_EQ(r.status, 0) << r.out;
  json doc = json::parse(r.out);
  ASSERT_EQ(doc["files"].size(), 1u);
  const json& file = doc["files"][0];
  EXPECT_EQ(file["path"], f.str());
  EXPECT_EQ(file["format"], "gpx");
  EXPECT_EQ(file["routes"], 0);
  EXPECT_EQ(file["waypoints"], 1);
  EXPECT_TRUE(file["warnings"].is_array());
  ASSERT_EQ(file["tracks"].size(), 1u);
  const json& t = file["tracks"][0];
  EXPECT_EQ(t["name"], "Loop");
  for (const char* which : {"raw", "clean"}) {
    const json& s = t[which];
    for (const char* key : {"points", "segments", "distance_2d_m", "distance_3d_m", "duration_s", "elapsed_s",
                            "moving_time_s", "elevation_gain_m", "elevation_loss_m", "min_elevation_m",
                            "max_elevation_m", "max_speed_kmh", "avg_speed_kmh", "max_climb_ms", "max_sink_ms", "bbox"})
      EXPECT_TRUE(s.contains(key)) << which << "." << key;
  }
  const json& raw = t["raw"];
  EXPECT_EQ(raw["points"], 5);
  EXPECT_EQ(raw["segments"], 2);
  // 3 steps of 0.0009 degrees of latitude (about 100 m each); nothing across the 11 km gap.
  EXPECT_NEAR(raw["distance_2d_m"].get<double>(), 3 * 100.07, 0.5);
  EXPECT_EQ(raw["duration_s"], 180.0);  // 120 s + 60 s, not the 2 hours between segments
  EXPECT_EQ(raw["elapsed_s"], 7260.0);
  EXPECT_EQ(raw["min_elevation_m"], 900.0);
  EXPECT_EQ(raw["max_elevation_m"], 1020.0);
  ASSERT_EQ(raw["bbox"].size(), 4u);
  EXPECT_EQ(raw["bbox"][0], 46.0);
  EXPECT_EQ(raw["bbox"][2], 46.1009);
  ASSERT_EQ(t["segments"].size(), 2u);
  EXPECT_EQ(t["segments"][1]["raw"]["points"], 2);
  EXPECT_EQ(t["segments"][1]["raw"]["duration_s"], 60.0);
}

TEST(StatsCli, AbsentFiguresAreNullNotNaN) {
  TempFile f("route.gpx", R"(<gpx><trk><trkseg><trkpt lat="1" lon="2"/><trkpt lat="1" lon="2"/></trkseg></trk></gpx>)");
  auto r = run_command(binary() + " stats --json " + shell_quote(f.str()));
  ASSERT_EQ(r.status, 0);
  EXPECT_EQ(r.out.find("NaN"), std::string::npos);
  EXPECT_EQ(r.out.find("nan"), std::string::npos);
  EXPECT_EQ(r.out.find("inf"), std::string::npos);
  json s = json::parse(r.out)["files"][0]["tracks"][0]["raw"];
  EXPECT_TRUE(s["duration_s"].is_null());
  EXPECT_TRUE(s["max_speed_kmh"].is_null());
  EXPECT_TRUE(s["elevation_gain_m"].is_null());
  EXPECT_EQ(s["distance_2d_m"], 0.0);
}

TEST(StatsCli, ReadsStandardInput) {
  TempFile f("loop.gpx", kTwoSegments);
  auto r = run_command(binary() + " stats --json - < " + shell_quote(f.str()));
  ASSERT_EQ(r.status, 0);
  json file = json::parse(r.out)["files"][0];
  EXPECT_EQ(file["path"], "-");
  EXPECT_EQ(file["tracks"][0]["raw"]["points"], 5);
}

TEST(StatsCli, GzipCompressedInput) {
  TempFile f("loop.gpx", kTwoSegments);
  ASSERT_EQ(run_command("gzip -k " + shell_quote(f.str())).status, 0);
  auto r = run_command(binary() + " stats --json " + shell_quote(f.str() + ".gz"));
  ASSERT_EQ(r.status, 0);
  EXPECT_EQ(json::parse(r.out)["files"][0]["tracks"][0]["raw"]["points"], 5);
}

TEST(StatsCli, ABadFileDoesNotStopTheOthers) {
  TempFile good("good.gpx", kTwoSegments);
  TempFile bad("bad.gpx", "<gpx><trk>\n<trkseg></trk></gpx>");
  auto r = run_command(binary() + " stats --json " + shell_quote(bad.str()) + " " + shell_quote(good.str()) + " 2>" +
                       shell_quote(bad.str() + ".err"));
  EXPECT_EQ(r.status, 1);
  json doc = json::parse(r.out);
  ASSERT_EQ(doc["files"].size(), 2u);
  EXPECT_TRUE(doc["files"][0].contains("error"));
  EXPECT_EQ(doc["files"][1]["tracks"][0]["raw"]["points"], 5);
  auto err = run_command("cat " + shell_quote(bad.str() + ".err"));
  EXPECT_NE(err.out.find("trailray: error: " + bad.str() + ":2:"), std::string::npos) << err.out;
  EXPECT_NE(err.out.find("mismatched tag"), std::string::npos) << err.out;
}

// Many files are read on all cores; the tables and the JSON come in the order of the files, the
// same as each file alone.
TEST(StatsCli, ManyFilesComeOutInTheirOrder) {
  std::vector<std::unique_ptr<TempFile>> files;
  std::string args;
  for (int i = 0; i < 40; ++i) {
    std::string gpx = kTwoSegments;
    // Each file another track name and length, so that an order mix-up shows.
    gpx.replace(gpx.find("Loop"), 4, "Loop " + std::to_string(i));
    for (int k = 0; k < i % 3; ++k) gpx.replace(gpx.find("</trkseg></trk>"), 0, "<trkpt lat=\"46.2\" lon=\"7.0\"/>");
    files.push_back(std::make_unique<TempFile>("many" + std::to_string(i) + ".gpx", gpx));
    args += " " + shell_quote(files.back()->str());
  }
  auto r = run_command(binary() + " stats --json" + args);
  ASSERT_EQ(r.status, 0);
  const json doc = json::parse(r.out);
  ASSERT_EQ(doc["files"].size(), 40u);
  for (int i = 0; i < 40; ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(doc["files"][i]["path"], files[i]->str());
    EXPECT_EQ(doc["files"][i]["tracks"][0]["name"], "Loop " + std::to_string(i));
    EXPECT_EQ(doc["files"][i]["tracks"][0]["raw"]["points"], 5 + i % 3);
  }
  auto table = run_command(binary() + " stats" + args);
  ASSERT_EQ(table.status, 0);
  std::size_t at = 0;
  for (int i = 0; i < 40; ++i) {
    at = table.out.find(files[i]->str(), at);
    ASSERT_NE(at, std::string::npos) << i;
  }
}

TEST(StatsCli, TableShowsCleanFiguresPerTrack) {
  TempFile f("loop.gpx", kTwoSegments);
  auto r = run_command(binary() + " stats " + shell_quote(f.str()));
  ASSERT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("(gpx, 1 track, 0 routes, 1 waypoint)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Loop"), std::string::npos);
  EXPECT_NE(r.out.find("0:03:00"), std::string::npos) << r.out;  // duration of both segments
}

TEST(StatsCli, StrictTurnsATruncationIntoAnError) {
  TempFile f("cut.gpx", "<gpx><trk><trkseg><trkpt lat=\"1\" lon=\"2\"/><trkpt lat=\"1\" lon=\"2.001\"/><trkpt lat=");
  auto lenient = run_command(binary() + " stats --json " + shell_quote(f.str()) + " 2>/dev/null");
  EXPECT_EQ(lenient.status, 0);
  EXPECT_EQ(json::parse(lenient.out)["files"][0]["tracks"][0]["raw"]["points"], 2);
  EXPECT_EQ(json::parse(lenient.out)["files"][0]["warnings"].size(), 1u);
  auto strict = run_command(binary() + " stats --strict " + shell_quote(f.str()) + " 2>&1");
  EXPECT_EQ(strict.status, 1);
  EXPECT_NE(strict.out.find("--strict"), std::string::npos) << strict.out;
}

TEST(StatsCli, UsageErrorsExitWithTwoAndListValidValues) {
  TempFile f("loop.gpx", kTwoSegments);
  auto r = run_command(binary() + " stats --igc-altitude sideways " + shell_quote(f.str()) + " 2>&1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("gnss"), std::string::npos) << r.out;
  EXPECT_EQ(run_command(binary() + " stats 2>/dev/null").status, 2);
  EXPECT_EQ(run_command(binary() + " frobnicate 2>/dev/null").status, 2);
  auto help = run_command(binary() + " stats --help");
  EXPECT_EQ(help.status, 0);
  for (const char* opt :
       {"--json", "--strict", "--igc-altitude", "--min-distance", "--no-smooth", "--smooth-width", "--smooth-sigma"})
    EXPECT_NE(help.out.find(opt), std::string::npos) << opt;
}

TEST(StatsCli, CleaningOptionsChangeTheCleanFigures) {
  std::string doc = "<gpx><trk><trkseg>";
  for (int i = 0; i < 50; ++i)
    doc += "<trkpt lat=\"" + std::to_string(46.0 + 0.00001 * i) +
           "\" lon=\"7\"><time>2024-06-01T10:00:" + (i < 10 ? "0" : "") + std::to_string(i) + "Z</time></trkpt>";
  doc += "</trkseg></trk></gpx>";
  TempFile f("dense.gpx", doc);
  auto points = [&](const std::string& opts) {
    auto r = run_command(binary() + " stats --json " + opts + " " + shell_quote(f.str()));
    return json::parse(r.out)["files"][0]["tracks"][0]["clean"]["points"].get<int>();
  };
  // Points 1.1 m apart: the default 3 m minimum distance keeps about a third of them.
  EXPECT_LT(points(""), 25);
  EXPECT_EQ(points("--min-distance 0"), 50);
}
