// `trailray score` as a user runs it: JSON shape, table, rule sets, errors naming the file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "app/run_command.hpp"
#include "test_support.hpp"

using nlohmann::json;
using trailray::test::run_command;
using trailray::test::shell_quote;
using trailray::test::TempFile;

namespace {

std::string binary() { return shell_quote(TRAILRAY_BINARY); }

std::string b_record(int seconds, double lat, double lon, char validity = 'A') {
  const int latm = static_cast<int>(std::lround(std::fabs(lat) * 60000));
  const int lonm = static_cast<int>(std::lround(std::fabs(lon) * 60000));
  char buf[64];
  std::snprintf(buf, sizeof buf, "B%02d%02d%02d%02d%05d%c%03d%05d%c%c%05d%05d\r\n", seconds / 3600 % 24,
                seconds / 60 % 60, seconds % 60, latm / 60000, latm % 60000, lat < 0 ? 'S' : 'N', lonm / 60000,
                lonm % 60000, lon < 0 ? 'W' : 'E', validity, 1000, 1000);
  return buf;
}

// A closed triangle of about 30 km flown at 1 Hz (no launch or landing: scored with --no-trim).
std::string triangle_igc() {
  std::string s = "AXXX001\r\nHFDTE150619\r\n";
  const double c[4][2] = {{46.0, 7.0}, {46.0, 7.13}, {46.078, 7.065}, {46.0, 7.0}};
  int t = 10 * 3600;
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 200; ++i) {
      const double f = i / 200.0;
      s += b_record(t++, c[k][0] + (c[k + 1][0] - c[k][0]) * f, c[k][1] + (c[k + 1][1] - c[k][1]) * f);
    }
  s += b_record(t, c[3][0], c[3][1]);
  return s;
}

}  // namespace

TEST(ScoreCli, JsonHasTheDocumentedShape) {
  TempFile f("tri.igc", triangle_igc());
  auto r = run_command(binary() + " score --no-trim --json " + shell_quote(f.str()));
  ASSERT_EQ(r.status, 0) << r.out;
  const json doc = json::parse(r.out);
  EXPECT_EQ(doc["rules"], "xcontest");
  EXPECT_EQ(doc["type"], "Closed FAI Triangle");
  EXPECT_EQ(doc["code"], "fai");
  for (const char* key : {"distance_km", "closing_km", "penalty_km", "multiplier", "score"})
    EXPECT_TRUE(doc[key].is_number()) << key;
  EXPECT_DOUBLE_EQ(doc["multiplier"].get<double>(), 1.6);
  ASSERT_EQ(doc["legs_km"].size(), 3u);
  double sum = 0;
  for (const auto& l : doc["legs_km"]) sum += l.get<double>();
  EXPECT_NEAR(sum, doc["distance_km"].get<double>(), 1e-6);
  EXPECT_NEAR(doc["score"].get<double>(),
              std::round((doc["distance_km"].get<double>() - doc["penalty_km"].get<double>()) * 1.6 * 100) / 100, 1e-6);
  ASSERT_EQ(doc["turnpoints"].size(), 3u);
  for (const auto& tp : doc["turnpoints"]) {
    EXPECT_TRUE(tp["lat"].is_number());
    EXPECT_TRUE(tp["lon"].is_number());
    EXPECT_TRUE(tp["fix"].is_number_integer());
    EXPECT_EQ(tp["time"].get<std::string>().substr(0, 11), "2019-06-15T");
  }
  ASSERT_EQ(doc["by_type"].size(), 5u);
  for (const auto& t : doc["by_type"]) {
    EXPECT_TRUE(t["type"].is_string());
    EXPECT_TRUE(t["code"].is_string());
    EXPECT_TRUE(t["score"].is_number());
    EXPECT_TRUE(t["exact"].is_boolean());
  }
  EXPECT_EQ(doc["by_type"][0]["code"], "od");
  ASSERT_EQ(doc["by_type"][0]["turnpoints"].size(), 5u);  // start, three turnpoints, finish
  EXPECT_EQ(doc["by_type"][0]["legs_km"].size(), 4u);
}

TEST(ScoreCli, RuleSetsAndTable) {
  TempFile f("tri.igc", triangle_igc());
  auto ffvl = run_command(binary() + " score --no-trim --rules ffvl --json " + shell_quote(f.str()));
  ASSERT_EQ(ffvl.status, 0) << ffvl.out;
  EXPECT_EQ(json::parse(ffvl.out)["type"], "Triangle FAI");
  auto fai = run_command(binary() + " score --no-trim --rules fai --distance geodesic --json " + shell_quote(f.str()));
  ASSERT_EQ(fai.status, 0) << fai.out;
  const json d = json::parse(fai.out);
  EXPECT_EQ(d["distance_model"], "geodesic");
  const double tenth = d["score"].get<double>() * 10;
  EXPECT_NEAR(tenth, std::round(tenth), 1e-6);  // FAI rounds to 0.1
  auto table = run_command(binary() + " score --no-trim " + shell_quote(f.str()));
  ASSERT_EQ(table.status, 0);
  EXPECT_NE(table.out.find("Closed FAI Triangle"), std::string::npos);
  EXPECT_NE(table.out.find("best: Closed FAI Triangle"), std::string::npos);
  EXPECT_NE(table.out.find("TP1"), std::string::npos);
}

TEST(ScoreCli, ErrorsNameTheFile) {
  auto missing = run_command(binary() + " score /nonexistent/flight.igc 2>&1");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.out.find("/nonexistent/flight.igc"), std::string::npos) << missing.out;

  TempFile bad("bad.igc",
               "AXXX\r\nHFDTE150619\r\n" + b_record(36000, 46, 7) + "B1000xx4600000N00700000EA0100001000\r\n");
  auto r = run_command(binary() + " score " + shell_quote(bad.str()) + " 2>&1");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find(bad.str() + ":4"), std::string::npos) << r.out;

  TempFile empty("none.igc", "AXXX\r\nHFDTE150619\r\n");
  auto e = run_command(binary() + " score " + shell_quote(empty.str()) + " 2>&1");
  EXPECT_EQ(e.status, 1);
  EXPECT_NE(e.out.find(empty.str()), std::string::npos) << e.out;

  TempFile few("few.igc", "HFDTE150619\r\n" + b_record(36000, 46, 7) + b_record(36001, 46, 7.001) +
                              b_record(36002, 46, 7.002, 'V'));
  auto f = run_command(binary() + " score " + shell_quote(few.str()) + " 2>&1");
  EXPECT_EQ(f.status, 1);
  EXPECT_NE(f.out.find("at least 5"), std::string::npos) << f.out;

  TempFile tri("tri.igc", triangle_igc());
  auto rules = run_command(binary() + " score --rules olc " + shell_quote(tri.str()) + " 2>&1");
  EXPECT_EQ(rules.status, 2);
  EXPECT_NE(rules.out.find("unknown rule set 'olc'"), std::string::npos) << rules.out;
  auto dist = run_command(binary() + " score --distance sphere " + shell_quote(tri.str()) + " 2>&1");
  EXPECT_EQ(dist.status, 2);
}

TEST(ScoreCli, HelpNamesRuleSetsAndDistances) {
  auto r = run_command(binary() + " score --help");
  EXPECT_EQ(r.status, 0);
  for (const char* s : {"--rules", "xcontest", "ffvl", "fai-oar", "fai-cylinders", "xcleague", "--distance", "fcc",
                        "geodesic", "--json", "--no-trim", "--all-types"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s;
}

TEST(ScoreCli, AFlightInAnotherFormatScoresAsItsIgc) {
  // The same triangle as GPX (written by convert): the track's timed points are its fixes.
  TempFile igc("tri.igc", triangle_igc());
  const std::string gpx = (igc.path().parent_path() / "tri.gpx").string();
  ASSERT_EQ(run_command(binary() + " convert " + shell_quote(igc.str()) + " -o " + shell_quote(gpx) + " 2>&1").status, 0);
  const auto a = run_command(binary() + " score --no-trim --json " + shell_quote(igc.str()));
  const auto b = run_command(binary() + " score --no-trim --json " + shell_quote(gpx) + " 2>&1");
  ASSERT_EQ(a.status, 0) << a.out;
  ASSERT_EQ(b.status, 0) << b.out;
  const json ja = json::parse(a.out), jb = json::parse(b.out);
  EXPECT_EQ(jb["type"], ja["type"]);
  EXPECT_NEAR(jb["distance_km"].get<double>(), ja["distance_km"].get<double>(), 1e-3);
  EXPECT_NEAR(jb["score"].get<double>(), ja["score"].get<double>(), 1e-3);
}
