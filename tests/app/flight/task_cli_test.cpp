// `trailray task` as a user runs it (JSON shape, table, errors naming the file and the place) and
// `render --task` (the optimised route drawn in its colour).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/run_command.hpp"
#include "terrain/codecs/image_codec.hpp"
#include "terrain/tile_fixtures.hpp"
#include "test_support.hpp"

using nlohmann::json;
using trailray::test::run_command;
using trailray::test::shell_quote;
using trailray::test::TempDir;
using trailray::test::TempFile;

namespace {

std::string binary() { return shell_quote(TRAILRAY_BINARY); }

// Pixels close to the task route's cyan (kTaskRouteColor) after shading.
std::size_t cyan_pixels(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  const std::string bytes = s.str();
  const auto image =
      trailray::terrain::decode_image(std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
  std::size_t n = 0;
  for (std::size_t i = 0; i + 2 < image.samples8.size(); i += image.channels) {
    const int r = image.samples8[i], g = image.samples8[i + 1], b = image.samples8[i + 2];
    n += (r < 80 && g > 140 && b > 170) ? 1 : 0;
  }
  return n;
}

}  // namespace

TEST(TaskCli, CompetitionFlightJson) {
  TRAILRAY_REQUIRE_DATA(task, "tasks/igclib_xctrack_1.xctsk");
  TRAILRAY_REQUIRE_DATA(flight, "tasks/igclib_race_0090.igc");
  const auto r =
      run_command(binary() + " task --json " + shell_quote(task.string()) + " " + shell_quote(flight.string()));
  ASSERT_EQ(r.status, 0) << r.out;
  const json doc = json::parse(r.out);
  ASSERT_EQ(doc["turnpoints"].size(), 9u);
  EXPECT_EQ(doc["turnpoints"][0]["role"], "takeoff");
  EXPECT_EQ(doc["turnpoints"][1]["role"], "SSS");
  EXPECT_EQ(doc["turnpoints"][7]["role"], "ESS");
  EXPECT_EQ(doc["turnpoints"][8]["role"], "goal");
  EXPECT_EQ(doc["goal"]["type"], "line");
  EXPECT_EQ(doc["earth_model_stated"], false);
  EXPECT_LT(doc["optimised_km"].get<double>(), doc["centre_km"].get<double>());
  EXPECT_DOUBLE_EQ(doc["turnpoints"][8]["optimised_km"].get<double>(), doc["optimised_km"].get<double>());
  EXPECT_TRUE(doc["stated_km"].is_null());
  ASSERT_EQ(doc["flights"].size(), 1u);
  const json& f = doc["flights"][0];
  EXPECT_EQ(f["reached_count"], 9);
  EXPECT_EQ(f["goal"], true);
  EXPECT_EQ(f["reached"][4]["by_exit"], true);  // out of the 15 km cylinder around R15
  ASSERT_EQ(f["notes"].size(), 1u);
  EXPECT_NE(f["notes"][0].get<std::string>().find("local time"), std::string::npos);
}

TEST(TaskCli, TableAndQrText) {
  TRAILRAY_REQUIRE_DATA(qr, "tasks/pyxctsk_task_gibe.qr.txt");
  const auto r = run_command(binary() + " task " + shell_quote(qr.string()));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("QR form"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Kleine Scheidegg"), std::string::npos);
  // XContest: 190.7 km through centres, 174.5 km optimised.
  EXPECT_NE(r.out.find("190.65 km through centres, 174.49 km optimised"), std::string::npos) << r.out;
}

TEST(TaskCli, ErrorsNameTheFileAndThePlace) {
  TempFile bad("bad.xctsk", R"({"version":1,"turnpoints":[{"radius":-5,"waypoint":{"lat":1,"lon":2}}]})");
  const auto r = run_command(binary() + " task " + shell_quote(bad.str()) + " 2>&1");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find(bad.str() + ": turnpoints[0].radius: out of range"), std::string::npos) << r.out;
  TempFile task("t.xctsk", R"({"version":1,"turnpoints":[{"radius":400,"waypoint":{"lat":1,"lon":2}}]})");
  const auto missing = run_command(binary() + " task " + shell_quote(task.str()) + " /nonexistent/flight.igc 2>&1");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.out.find("/nonexistent/flight.igc"), std::string::npos) << missing.out;
}

TEST(TaskRenderCli, DrawsTheOptimisedRoute) {
  TRAILRAY_REQUIRE_DATA(task, "tasks/igclib_xctrack_1.xctsk");
  TRAILRAY_REQUIRE_DATA(flight, "tasks/igclib_race_0090.igc");
  TempDir home;
  const std::string with = (home.path() / "with.png").string(), without = (home.path() / "without.png").string();
  const std::string render = "XDG_CONFIG_HOME=" + shell_quote((home.path() / "config").string()) +
                             " XDG_CACHE_HOME=" + shell_quote((home.path() / "cache").string()) +
                             " TRAILRAY_CONFIG= " + binary() +
                             " render --imagery none --terrain none --size 480x270 --legend off ";
  const auto a = run_command(render + shell_quote(flight.string()) + " -o " + shell_quote(without) + " 2>&1");
  ASSERT_EQ(a.status, 0) << a.out;
  const auto b = run_command(render + "--task " + shell_quote(task.string()) + " " + shell_quote(flight.string()) +
                             " -o " + shell_quote(with) + " 2>&1");
  ASSERT_EQ(b.status, 0) << b.out;
  EXPECT_LT(cyan_pixels(without), 20u);
  EXPECT_GT(cyan_pixels(with), 200u);
  const auto bad = run_command(render + "--task /nonexistent.xctsk " + shell_quote(flight.string()) + " -o " +
                               shell_quote(with) + " 2>&1");
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.out.find("/nonexistent.xctsk"), std::string::npos) << bad.out;
}
