// `trailray bench tracks` as a user runs it: the JSON document's fields and plausible figures
// (times positive, the capsules' memory per point within the issue's 20 bytes and under an eighth
// of the tube's), real tracks read from a data folder (an unreadable file skipped with its
// reason), the table, and bad --points values refused with a message naming the option. Small
// pictures and few frames: the figures are checked for sense, never for speed.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "app/run_command.hpp"
#include "test_support.hpp"

using nlohmann::json;
using trailray::test::run_command;
using trailray::test::shell_quote;

namespace {

std::string bench() { return shell_quote(TRAILRAY_BINARY) + " bench tracks "; }

bool positive_finite(const json& v) { return v.is_number() && std::isfinite(v.get<double>()) && v.get<double>() > 0.0; }

// A folder removed at scope end.
class ScratchDir {
 public:
  ScratchDir() {
    path_ = trailray::test::make_unique_temp_dir("trailray-bench-test-");
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  void write(const std::string& relative, const std::string& content) const {
    std::filesystem::create_directories((path_ / relative).parent_path());
    std::ofstream(path_ / relative, std::ios::binary) << content;
  }

 private:
  std::filesystem::path path_;
};

// Six points 100 m apart going north and climbing: nothing for the cleaning to drop.
std::string six_point_gpx() {
  std::string gpx = R"(<gpx version="1.1"><trk><name>Climb</name><trkseg>)";
  for (int i = 0; i < 6; ++i)
    gpx += "<trkpt lat=\"" + std::to_string(47.0 + 0.0009 * i) + "\" lon=\"11.0\"><ele>" +
           std::to_string(1000 + 10 * i) + "</ele><time>2024-06-01T10:0" + std::to_string(i) + ":00Z</time></trkpt>";
  return gpx + "</trkseg></trk></gpx>";
}

}  // namespace

TEST(BenchCli, JsonHasEveryFigureAndTheCapsulesSpendAnEighthOfTheTubesMemory) {
  const auto r = run_command(bench() + "--points 1000 --size 320x180 --frames 3 --data none --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const json doc = json::parse(r.out);
  EXPECT_FALSE(doc["renderer"].get<std::string>().empty());
  EXPECT_TRUE(doc["timing"] == "gpu" || doc["timing"] == "cpu") << doc["timing"];
  EXPECT_EQ(doc["size"]["width"], 320);
  EXPECT_EQ(doc["size"]["height"], 180);
  EXPECT_EQ(doc["frames"], 3);
  ASSERT_EQ(doc["datasets"].size(), 1u) << doc.dump(2);
  const json& walk = doc["datasets"][0];
  EXPECT_EQ(walk["name"], "walk-1000");
  EXPECT_EQ(walk["kind"], "random_walk");
  EXPECT_EQ(walk["points"], 1000);
  for (const char* field : {"capsule_ms", "capsule_overlay_ms", "capsule_total_ms", "ribbon_ms", "tube_ms",
                            "capsule_over_ribbon", "capsule_over_tube", "tube_radius_m", "view_distance_m"})
    EXPECT_TRUE(positive_finite(walk[field])) << field << " = " << walk[field];
  EXPECT_GE(walk["capsule_total_ms"].get<double>(), walk["capsule_ms"].get<double>());
  // The ratios are of the capsules' total: the visible pass and the overlay every frame draws.
  EXPECT_NEAR(walk["capsule_total_ms"].get<double>(),
              walk["capsule_ms"].get<double>() + walk["capsule_overlay_ms"].get<double>(), 1e-9);
  EXPECT_NEAR(walk["capsule_over_ribbon"].get<double>(),
              walk["capsule_total_ms"].get<double>() / walk["ribbon_ms"].get<double>(), 1e-9);
  EXPECT_NEAR(walk["capsule_over_tube"].get<double>(),
              walk["capsule_total_ms"].get<double>() / walk["tube_ms"].get<double>(), 1e-9);
  EXPECT_NEAR(walk["capsule_visible_over_ribbon"].get<double>(),
              walk["capsule_ms"].get<double>() / walk["ribbon_ms"].get<double>(), 1e-9);

  const double capsule = walk["capsule_bytes_per_point"].get<double>();
  const double tube = walk["tube_bytes_per_point"].get<double>();
  EXPECT_GT(capsule, 0.0);
  EXPECT_LE(capsule, 20.0) << "the issue allows at most 20 bytes per point";
  EXPECT_LT(capsule, tube / 8.0);
  // The tube's own layout: 8 vertices of 24 bytes per point, 48 four-byte indices per segment.
  EXPECT_NEAR(tube, 8 * 24 + 48 * 4 * 999.0 / 1000.0, 1e-6);
  EXPECT_NEAR(walk["ribbon_bytes_per_point"].get<double>(), 2 * 28, 1e-6);
  EXPECT_NEAR(walk["capsule_over_tube_bytes"].get<double>(), capsule / tube, 1e-9);

  ASSERT_TRUE(doc.contains("targets"));
  EXPECT_EQ(doc["targets"]["dataset"], "walk-1000");
  EXPECT_EQ(doc["targets"]["capsule_over_tube_bytes"]["met"], capsule / tube <= 0.125);
}

TEST(BenchCli, RealTracksComeFromTheDataFolderAndUnreadableOnesAreSkippedWithTheReason) {
  ScratchDir data;
  data.write("gpx/climb.gpx", six_point_gpx());
  data.write("gpx/broken.gpx", "this is not XML");
  data.write("gpx/notes.txt", "not a track file");
  const auto r =
      run_command(bench() + "--points 2 --size 64x36 --frames 1 --json --data " + shell_quote(data.path().string()));
  ASSERT_EQ(r.status, 0) << r.out;
  const json doc = json::parse(r.out);
  ASSERT_EQ(doc["datasets"].size(), 2u) << doc.dump(2);
  EXPECT_EQ(doc["datasets"][0]["name"], "walk-2");
  const json& climb = doc["datasets"][1];
  EXPECT_EQ(climb["name"], "climb.gpx");
  EXPECT_EQ(climb["kind"], "track");
  EXPECT_EQ(climb["points"], 6);
  EXPECT_TRUE(positive_finite(climb["tube_ms"])) << climb.dump(2);
  ASSERT_EQ(doc["skipped"].size(), 1u) << doc.dump(2);
  EXPECT_EQ(doc["skipped"][0].get<std::string>().rfind("broken.gpx: ", 0), 0u) << doc["skipped"][0];
}

TEST(BenchCli, PrintsATableWithTheTargetsWithoutJson) {
  const auto r = run_command(bench() + "--points 2,3 --size 64x36 --frames 1 --data none");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("capsule"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("walk-2 "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("walk-3 "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("targets at walk-3:"), std::string::npos) << r.out;
}

TEST(BenchCli, BadPointCountsFailNamingTheOption) {
  for (const std::string bad : {"0", "abc", "20000000", "1000,,2000", "-5", ""}) {
    const auto r = run_command(bench() + "--points " + shell_quote(bad) + " --data none 2>&1");
    EXPECT_EQ(r.status, 2) << bad << ": " << r.out;
    EXPECT_NE(r.out.find("--points"), std::string::npos) << bad << ": " << r.out;
    EXPECT_NE(r.out.find("is not a point count"), std::string::npos) << bad << ": " << r.out;
  }
}

// `--many`: the many-track scenario is one more row, its tracks as segments of one buffer.
TEST(BenchCli, ManyTracksAreOneMoreRowWithATrackPerSegment) {
  const auto r = run_command(bench() + "--points 2 --many 7x40 --size 64x36 --frames 1 --data none --json");
  ASSERT_EQ(r.status, 0);
  const json doc = json::parse(r.out);
  ASSERT_EQ(doc["datasets"].size(), 2u);
  const json& many = doc["datasets"][1];
  EXPECT_EQ(many["name"], "walks-7x40");
  EXPECT_EQ(many["kind"], "many_walks");
  EXPECT_EQ(many["points"], 280);
  EXPECT_EQ(many["segments"], 7);
  EXPECT_TRUE(positive_finite(many["capsule_total_ms"]));
  EXPECT_TRUE(positive_finite(many["tube_ms"]));
  for (const std::string bad : {"7", "7x", "x40", "0x40", "7x1", "20000x20000"}) {
    const auto e = run_command(bench() + "--many " + shell_quote(bad) + " --data none 2>&1");
    EXPECT_EQ(e.status, 2) << bad << ": " << e.out;
    EXPECT_NE(e.out.find("is not TRACKSxPOINTS"), std::string::npos) << bad << ": " << e.out;
  }
}

// `--lod on|off`: with the level of detail, a walk of many points a pixel draws far fewer
// capsules; without it, one per pair of points.
TEST(BenchCli, LevelOfDetailMergesCapsulesAndOffDrawsEveryOne) {
  std::size_t drawn_on = 0;
  for (const std::string mode : {"on", "off"}) {
    const auto r = run_command(bench() + "--points 20000 --size 160x90 --frames 1 --data none --json --lod " + mode);
    ASSERT_EQ(r.status, 0) << r.out;
    const json doc = json::parse(r.out);
    EXPECT_EQ(doc["lod"], mode);
    const json& walk = doc["datasets"][0];
    if (mode == "on") {
      drawn_on = walk["capsules_drawn"].get<std::size_t>();
      EXPECT_GT(drawn_on, 0u);
      EXPECT_LT(drawn_on, 19999u / 4) << "a 20000-point walk in 160x90 pixels has many points a pixel";
    } else {
      EXPECT_EQ(walk["capsules_drawn"], 19999);
    }
  }
  const auto bad = run_command(bench() + "--lod maybe --data none 2>&1");
  EXPECT_EQ(bad.status, 2) << bad.out;
  EXPECT_NE(bad.out.find("--lod"), std::string::npos) << bad.out;
}
