// Conformance with gpxpy (Debian python3-gpxpy), computed in the same test run: for every GPX
// in shared/data that gpxpy reads, trailray's raw figures must agree with gpxpy's.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

#include "app/run_command.hpp"
#include "test_support.hpp"

using nlohmann::json;
using trailray::test::run_command;
using trailray::test::shell_quote;

TEST(ConformanceGpxpy, RawFiguresMatchGpxpyOnEveryGpxFile) {
  TRAILRAY_REQUIRE_DATA(dir, "gpx");
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".gpx") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 30u);

  std::string cmd =
      "/usr/bin/python3 " + shell_quote(std::string(TRAILRAY_SOURCE_DIR) + "/tests/conformance/gpxpy_figures.py");
  for (const auto& f : files) cmd += " " + shell_quote(f);
  auto py = run_command(cmd);
  ASSERT_EQ(py.status, 0) << "gpxpy script failed (is python3-gpxpy installed? run scripts/setup.sh)";
  std::map<std::string, json> gpxpy;
  std::istringstream lines(py.out);
  for (std::string line; std::getline(lines, line);) {
    json j = json::parse(line);
    gpxpy[j["path"]] = j;
  }

  int compared = 0, blind_segments = 0;
  for (const auto& f : files) {
    const json& g = gpxpy.at(f);
    if (!g["ok"]) continue;  // gpxpy cannot read it (trailray's own tests cover these files)
    auto tr = run_command(shell_quote(TRAILRAY_BINARY) + " stats --json " + shell_quote(f) + " 2>/dev/null");
    ASSERT_EQ(tr.status, 0) << f;
    json doc = json::parse(tr.out);
    const json& file = doc["files"][0];
    std::size_t points = 0;
    double duration = 0.0, distance = 0.0;
    for (const auto& t : file["tracks"]) {
      points += t["raw"]["points"].get<std::size_t>();
      if (!t["raw"]["duration_s"].is_null()) duration += t["raw"]["duration_s"].get<double>();
      distance += t["raw"]["distance_2d_m"].get<double>();
    }
    EXPECT_EQ(points, g["points"].get<std::size_t>()) << f;
    EXPECT_NEAR(duration, g["duration_s"].get<double>(), 1e-3)
        << f << " (" << g["gpxpy_blind_segments"] << " segments where gpxpy's duration sees no time"
        << " and the first/last timed point of gpxpy's parse is used instead)";
    blind_segments += g["gpxpy_blind_segments"].get<int>();
    const double expected = g["length_2d_m"].get<double>();
    EXPECT_NEAR(distance, expected, std::max(0.005 * expected, 1e-6)) << f << " (within 0.5%)";
    ++compared;
  }
  EXPECT_GE(compared, 30) << "gpxpy read fewer files than expected";
  std::cout << "[ INFO ] compared " << compared << " files with gpxpy; " << blind_segments
            << " segment(s) timed only away from their first/last two points (gpxpy says unknown there)\n";
}
