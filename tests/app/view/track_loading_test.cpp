// The viewer's loading: a folder (given or dropped) stands for its track files, read on all
// cores in name order; a file that cannot be read, or a folder without track files, is an error
// line and the others still load.
#include "app/view/track_loading.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "app/track_cli_support.hpp"

namespace trailray::app::view {
namespace {

using trailray::test::east_line;

constexpr double kLat = 46.70, kLon = 7.85, kT0 = 1718704800.0;

TrackLoadInputs inputs() {
  TrackLoadInputs in;
  in.neutral_ground_m = std::numeric_limits<double>::quiet_NaN();
  return in;
}

TEST(ViewerTrackLoading, FolderLoadsLikeItsFilesInNameOrder) {
  trailray::test::RenderEnv env;
  const std::string folder = env.file("season");
  std::filesystem::create_directories(folder + "/empty");
  std::vector<std::string> files;
  for (const char* name : {"c", "a", "b"})
    files.push_back(env.write_gpx(std::string("season/") + name + ".gpx",
                                  {{name, {east_line(kLat, kLon, 0.0, 20, 15.0, kT0, 3.0, 700.0)}}}));
  std::ofstream(folder + "/broken.gpx") << "<gpx><trk><trkseg><trkpt lat=\"1\" lon=\"2\"></trk>";

  const LoadedViewerTracks by_folder = load_viewer_tracks({folder, folder + "/empty"}, inputs());
  ASSERT_EQ(by_folder.tracks.size(), 3u);
  EXPECT_EQ(by_folder.tracks[0].name, "a");
  EXPECT_EQ(by_folder.tracks[1].name, "b");
  EXPECT_EQ(by_folder.tracks[2].name, "c");
  ASSERT_EQ(by_folder.errors.size(), 2u);
  EXPECT_NE(by_folder.errors[0].find(folder + "/empty: the folder holds no track file"), std::string::npos)
      << by_folder.errors[0];
  EXPECT_EQ(by_folder.errors[1].rfind(folder + "/broken.gpx:", 0), 0u) << by_folder.errors[1];

  // The same tracks, colours included, as the files named one by one (a, b, c).
  const LoadedViewerTracks by_name = load_viewer_tracks({files[1], files[2], files[0]}, inputs());
  ASSERT_EQ(by_name.tracks.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(by_name.tracks[i].source, by_folder.tracks[i].source);
    EXPECT_EQ(by_name.tracks[i].color_srgb, by_folder.tracks[i].color_srgb);
    EXPECT_EQ(by_name.tracks[i].distance_m, by_folder.tracks[i].distance_m);
  }
  EXPECT_NE(by_folder.tracks[0].color_srgb, by_folder.tracks[1].color_srgb);
}

}  // namespace
}  // namespace trailray::app::view
