// `trailray stats` on FIT files: the distances agree with the device's own session totals
// (which leave out timer pauses, as the segments do), and damage shows as warnings.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "app/run_command.hpp"
#include "test_support.hpp"

using nlohmann::json;
using trailray::test::run_command;
using trailray::test::shell_quote;

namespace {

std::string binary() { return shell_quote(TRAILRAY_BINARY); }

struct DeviceTotals {
  const char* file;
  double total_distance_m;  // the session message's total_distance
  int segments;             // stretches between timer pauses
};

TEST(StatsFitCli, DistancesMatchTheDevicesSessionTotals) {
  const DeviceTotals cases[] = {{"gpsbabel_garmin-edge-800.fit", 25196.98, 8},
                                {"fitparse_garmin-fenix-5-bike.fit", 459.52, 1},
                                {"fitparse_developer-types-sample.fit", 6753.99, 1}};
  for (const DeviceTotals& c : cases) {
    SCOPED_TRACE(c.file);
    TRAILRAY_REQUIRE_DATA(path, std::string("fit/") + c.file);
    auto r = run_command(binary() + " stats --json " + shell_quote(path.string()) + " 2>/dev/null");
    ASSERT_EQ(r.status, 0) << r.out;
    const json file = json::parse(r.out)["files"][0];
    EXPECT_EQ(file["format"], "fit");
    ASSERT_EQ(file["tracks"].size(), 1u);
    const json& raw = file["tracks"][0]["raw"];
    EXPECT_EQ(raw["segments"], c.segments);
    EXPECT_NEAR(raw["distance_2d_m"].get<double>(), c.total_distance_m, 0.01 * c.total_distance_m);
    EXPECT_LE(raw["duration_s"].get<double>(), raw["elapsed_s"].get<double>());
    EXPECT_GT(raw["max_speed_kmh"].get<double>(), raw["avg_speed_kmh"].get<double>());
  }
}

TEST(StatsFitCli, ADamagedFileWarnsAndStrictRefusesIt) {
  TRAILRAY_REQUIRE_DATA(path, "fit/gpsbabel_lezyne_super_gps-bad-endian.fit");
  auto lenient = run_command(binary() + " stats --json " + shell_quote(path.string()) + " 2>/dev/null");
  ASSERT_EQ(lenient.status, 0);
  const json file = json::parse(lenient.out)["files"][0];
  EXPECT_EQ(file["tracks"][0]["raw"]["points"], 804);
  ASSERT_GE(file["warnings"].size(), 2u);
  EXPECT_NE(file["warnings"].dump().find("architecture byte 0xE5"), std::string::npos) << file["warnings"].dump();
  EXPECT_NE(file["warnings"].dump().find("byte 22227"), std::string::npos);
  auto strict = run_command(binary() + " stats --strict " + shell_quote(path.string()) + " 2>&1");
  EXPECT_EQ(strict.status, 1);
  EXPECT_NE(strict.out.find("--strict"), std::string::npos) << strict.out;
}

}  // namespace
