// Folders and patterns on the command line: `trailray stats` lists a quoted pattern's files in
// name order, a pattern without a match or a folder without track files fails naming it, and
// `trailray render` of a folder draws the picture of its files named one by one.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "app/run_command.hpp"
#include "app/track_cli_support.hpp"

namespace trailray::test {
namespace {

constexpr double kLat = 46.70, kLon = 7.85, kT0 = 1718704800.0;
const std::string kPicture = " --terrain none --no-ssao --no-atmosphere --size 320x180 --time 2024-06-18T10:00:00Z";

std::string stats(const std::string& args) { return shell_quote(TRAILRAY_BINARY) + " stats " + args + " 2>&1"; }

TEST(TrackArgumentsCli, QuotedPatternListsItsFilesInNameOrder) {
  RenderEnv env;
  env.write_gpx("b.gpx", {{"B", {east_line(kLat, kLon, 0.0, 10, 20.0, kT0, 2.0, 500.0)}}});
  env.write_gpx("a.gpx", {{"A", {east_line(kLat, kLon, 0.0, 10, 20.0, kT0, 2.0, 500.0)}}});
  env.write_gpx("c.kml.txt", {{"C", {east_line(kLat, kLon, 0.0, 10, 20.0, kT0, 2.0, 500.0)}}});
  const auto r = run_command(stats(shell_quote(env.file("*"))));
  ASSERT_EQ(r.status, 0) << r.out;
  const std::size_t a = r.out.find(env.file("a.gpx")), b = r.out.find(env.file("b.gpx"));
  ASSERT_NE(a, std::string::npos) << r.out;
  ASSERT_NE(b, std::string::npos) << r.out;
  EXPECT_LT(a, b);
  EXPECT_EQ(r.out.find("c.kml.txt"), std::string::npos) << r.out;
  // The folder itself: the same files.
  const auto folder = run_command(stats(shell_quote(env.home.path().string())));
  EXPECT_EQ(folder.status, 0);
  EXPECT_EQ(folder.out, r.out);
}

TEST(TrackArgumentsCli, NothingToReadFailsNamingTheArgument) {
  RenderEnv env;
  env.write_gpx("a.gpx", {{"A", {east_line(kLat, kLon, 0.0, 10, 20.0, kT0, 2.0, 500.0)}}});
  const std::string pattern = env.file("*.igc");
  const auto r = run_command(stats(shell_quote(pattern)));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("trailray: error: " + pattern + ": no file matches this pattern"), std::string::npos) << r.out;
  const std::string empty = env.file("empty");
  std::filesystem::create_directories(empty);
  const auto e = run_command(stats(shell_quote(empty)));
  EXPECT_EQ(e.status, 1);
  EXPECT_NE(e.out.find(empty + ": the folder holds no track file"), std::string::npos) << e.out;
}

TEST(TrackArgumentsCli, RenderOfAFolderIsRenderOfItsFiles) {
  RenderEnv env;
  const std::string folder = env.file("season");
  std::filesystem::create_directories(folder);
  std::vector<std::string> files;
  for (int i = 0; i < 6; ++i) {
    const std::string name = "season/day" + std::to_string(i) + ".gpx";
    files.push_back(
        env.write_gpx(name, {{"", {east_line(kLat, kLon, 0.0, 30, 40.0, kT0, 5.0, 600.0 + 20.0 * i, 200.0 * i)}}}));
  }
  std::string listed;
  for (const std::string& f : files) listed += " " + shell_quote(f);
  const auto by_folder = run_command(env.prefix() + shell_quote(folder) + kPicture + " -o " +
                                     shell_quote(env.file("folder.png")) + " 2>&1");
  ASSERT_EQ(by_folder.status, 0) << by_folder.out;
  const auto by_files =
      run_command(env.prefix() + listed + kPicture + " -o " + shell_quote(env.file("files.png")) + " 2>&1");
  ASSERT_EQ(by_files.status, 0) << by_files.out;
  const Picture a = read_picture(env.file("folder.png")), b = read_picture(env.file("files.png"));
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  EXPECT_TRUE(a.rgba == b.rgba) << "the folder's picture differs from its files'";
  // Six tracks, six palette colours: the picture is not just the ground.
  std::size_t coloured = 0;
  for (std::uint32_t y = 0; y < a.height; ++y)
    for (std::uint32_t x = 0; x < a.width; ++x) {
      const Picture::Rgb p = a.at(x, y);
      coloured += std::max({p.r, p.g, p.b}) - std::min({p.r, p.g, p.b}) > 80 ? 1 : 0;
    }
  EXPECT_GT(coloured, 100u);
}

}  // namespace
}  // namespace trailray::test
