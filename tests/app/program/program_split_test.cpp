// The three programs behind `trailray` (app/program/program_router): which one runs a command line, that
// the track commands load none of the heavy libraries, that render loads no film encoder, window
// or HTTP server, and a clear error when a program is missing.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "app/program/program_router.hpp"
#include "app/run_command.hpp"
#include "test_support.hpp"

using trailray::app::Program;
using trailray::app::program_for;
using trailray::test::run_command;
using trailray::test::shell_quote;

namespace {

Program route(std::vector<const char*> args) {
  args.insert(args.begin(), "trailray");
  return program_for(static_cast<int>(args.size()), args.data());
}

// The shared libraries the dynamic loader opened for a command line (LD_DEBUG=libs).
std::string loaded_libraries(const std::string& arguments) {
  return run_command("LD_DEBUG=libs " + shell_quote(TRAILRAY_BINARY) + " " + arguments + " 2>&1 >/dev/null").out;
}

const char* kHeavy[] = {"libgdal", "libEGL", "libGLESv2", "libavcodec", "libglfw", "libmicrohttpd", "libcurl"};

}  // namespace

TEST(ProgramRouter, TrackCommandsRunInTrailrayItself) {
  for (const char* c : {"stats", "convert", "score", "flight", "task", "check"})
    EXPECT_EQ(route({c, "x.gpx"}), Program::Tracks) << c;
  EXPECT_EQ(route({"--version"}), Program::Tracks);
  EXPECT_EQ(route({"stats", "--help"}), Program::Tracks);  // the same options in every program
  EXPECT_EQ(route({"check", "--airspace", "a.txt", "--", "--terrain.gpx"}), Program::Tracks);
}

TEST(ProgramRouter, TerrainAndPicturesGoToTrailrayRender) {
  for (const char* c : {"render", "elevation", "heatmap", "bench"}) EXPECT_EQ(route({c, "x.gpx"}), Program::Pictures) << c;
  EXPECT_EQ(route({"check", "--airspace", "a.txt", "--terrain", "dem.tif", "x.igc"}), Program::Pictures);
  EXPECT_EQ(route({"check", "--terrain=dem.tif", "x.igc"}), Program::Pictures);
  EXPECT_EQ(route({"check", "--offline", "x.igc"}), Program::Pictures);
  EXPECT_EQ(route({"check", "--help"}), Program::Pictures);  // its help lists the terrain options
}

TEST(ProgramRouter, TheRestGoesToTrailrayFull) {
  for (const char* c : {"view", "video", "serve", "nonsense"}) EXPECT_EQ(route({c}), Program::Full) << c;
  EXPECT_EQ(route({}), Program::Full);
  EXPECT_EQ(route({"--help"}), Program::Full);
}

TEST(ProgramSplit, StatsLoadsNoneOfTheHeavyLibraries) {
  TRAILRAY_REQUIRE_DATA(gpx, "gpx/gpxstudio_with_hr.gpx");
  const std::string libs = loaded_libraries("stats " + shell_quote(gpx.string()));
  ASSERT_NE(libs.find("libfmt"), std::string::npos) << libs;  // LD_DEBUG did report
  for (const char* heavy : kHeavy) EXPECT_EQ(libs.find(heavy), std::string::npos) << heavy << " loaded by stats";
}

TEST(ProgramSplit, RenderLoadsNoEncoderWindowOrServer) {
  const std::string libs = loaded_libraries("render --help");
  ASSERT_NE(libs.find("libgdal"), std::string::npos) << libs;
  for (const char* heavy : {"libavcodec", "libglfw", "libmicrohttpd"})
    EXPECT_EQ(libs.find(heavy), std::string::npos) << heavy << " loaded by render";
}

TEST(ProgramSplit, EveryCommandIsStillThere) {
  const auto help = run_command(shell_quote(TRAILRAY_BINARY) + " --help");
  EXPECT_EQ(help.status, 0);
  for (const char* c : {"stats", "elevation", "convert", "check", "render", "view", "video", "score", "flight",
                        "task", "serve", "bench", "heatmap"})
    EXPECT_NE(help.out.find(std::string("  ") + c), std::string::npos) << c;
  const auto check = run_command(shell_quote(TRAILRAY_BINARY) + " check --help");
  EXPECT_NE(check.out.find("--terrain"), std::string::npos);
}

TEST(ProgramSplit, AMissingProgramIsNamed) {
  trailray::test::TempFile lonely("trailray");
  std::filesystem::copy_file(TRAILRAY_BINARY, lonely.path(), std::filesystem::copy_options::overwrite_existing);
  std::filesystem::permissions(lonely.path(), std::filesystem::perms::owner_all);
  const auto r = run_command(shell_quote(lonely.str()) + " render --help 2>&1");
  EXPECT_EQ(r.status, 127);
  EXPECT_NE(r.out.find("trailray-render"), std::string::npos) << r.out;
  // The track commands need nothing beside it.
  EXPECT_EQ(run_command(shell_quote(lonely.str()) + " --version").status, 0);
}
