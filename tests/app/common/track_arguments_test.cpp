// expand_track_arguments: folders and patterns become the track files they name, sorted by name;
// files (even with pattern characters in their names) and `-` are taken as they are.
#include "app/common/track_arguments.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "terrain/tile_fixtures.hpp"

namespace trailray::app {
namespace {

namespace fs = std::filesystem;
using Paths = std::vector<std::string>;

// A folder of files (the content does not matter: nothing is read).
struct Folder {
  trailray::test::TempDir dir;  // holds a hidden ".anchor" file: never listed
  std::string root = dir.path().string();
  std::string add(const std::string& relative) const {
    const fs::path path = dir.path() / relative;
    fs::create_directories(path.parent_path());
    std::ofstream(path) << "x";
    return path.string();
  }
  std::string at(const std::string& relative) const { return (dir.path() / relative).string(); }
};

std::string error_of(const Paths& arguments) {
  try {
    expand_track_arguments(arguments);
  } catch (const TrackArgumentError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(TrackArguments, FolderGivesItsTrackFilesSortedByNameSkippingOthers) {
  Folder f;
  f.add("b.gpx");
  f.add("a.IGC");
  f.add("c.tcx.gz");
  f.add("B.kmz");
  f.add("notes.txt");
  f.add("gpx");  // no extension at all
  f.add(".hidden.gpx");
  f.add("sub/d.gpx");  // subfolders are not entered
  f.add("e.geojson");
  f.add("f.json");
  f.add("g.fit");
  f.add("h.kml");
  EXPECT_EQ(expand_track_arguments({f.root}), (Paths{f.at("B.kmz"), f.at("a.IGC"), f.at("b.gpx"), f.at("c.tcx.gz"),
                                                     f.at("e.geojson"), f.at("f.json"), f.at("g.fit"), f.at("h.kml")}));
  // With a trailing slash the names are joined without a double one.
  EXPECT_EQ(expand_track_arguments({f.root + "/"}).front(), f.root + "/B.kmz");
}

TEST(TrackArguments, ByteOrderNotNaturalOrder) {
  Folder f;
  f.add("flight10.igc");
  f.add("flight2.igc");
  f.add("flight1.igc");
  EXPECT_EQ(expand_track_arguments({f.root}), (Paths{f.at("flight1.igc"), f.at("flight10.igc"), f.at("flight2.igc")}));
}

TEST(TrackArguments, PatternMatchesFilesAndFoldersSorted) {
  Folder f;
  f.add("2024/b.igc");
  f.add("2024/a.igc");
  f.add("2024/a.gpx");
  f.add("2024/readme.md");
  f.add("2023/z.igc");
  f.add("2023/deep/y.igc");
  EXPECT_EQ(expand_track_arguments({f.root + "/2024/*.igc"}), (Paths{f.at("2024/a.igc"), f.at("2024/b.igc")}));
  // A pattern that matches folders: their track files (one level), folder by folder.
  EXPECT_EQ(expand_track_arguments({f.root + "/20*"}),
            (Paths{f.at("2023/z.igc"), f.at("2024/a.gpx"), f.at("2024/a.igc"), f.at("2024/b.igc")}));
  // Patterns in several components; `?` and sets.
  EXPECT_EQ(expand_track_arguments({f.root + "/202[3-4]/?.igc"}),
            (Paths{f.at("2023/z.igc"), f.at("2024/a.igc"), f.at("2024/b.igc")}));
  // Non-track files a pattern matches are left out.
  EXPECT_EQ(expand_track_arguments({f.root + "/2024/*"}),
            (Paths{f.at("2024/a.gpx"), f.at("2024/a.igc"), f.at("2024/b.igc")}));
}

TEST(TrackArguments, DoubleStarReachesEveryFolderBelow) {
  Folder f;
  f.add("a.igc");
  f.add("2024/b.igc");
  f.add("2024/alps/c.igc");
  f.add("2024/alps/c.gpx");
  f.add("2024/.cache/d.igc");  // hidden folders are not entered
  f.add(".e.igc");
  EXPECT_EQ(expand_track_arguments({f.root + "/**/*.igc"}),
            (Paths{f.at("2024/alps/c.igc"), f.at("2024/b.igc"), f.at("a.igc")}));
  // As the last component: the track files of every folder it reaches.
  EXPECT_EQ(expand_track_arguments({f.root + "/**"}),
            (Paths{f.at("a.igc"), f.at("2024/b.igc"), f.at("2024/alps/c.gpx"), f.at("2024/alps/c.igc")}));
  EXPECT_EQ(expand_track_arguments({f.root + "/2024/**/c.*"}), (Paths{f.at("2024/alps/c.gpx"), f.at("2024/alps/c.igc")}));
  // Twice: each file once.
  EXPECT_EQ(expand_track_arguments({f.root + "/**/**/b.igc"}), (Paths{f.at("2024/b.igc")}));
}

TEST(TrackArguments, ABackslashMakesAPatternCharacterLiteral) {
  Folder f;
  f.add("a*b.gpx");
  f.add("aXb.gpx");
  EXPECT_EQ(expand_track_arguments({f.root + "/a\\*b.gp?"}), (Paths{f.at("a*b.gpx")}));
  EXPECT_EQ(expand_track_arguments({f.root + "/a*b.gp?"}), (Paths{f.at("a*b.gpx"), f.at("aXb.gpx")}));
  EXPECT_TRUE(glob_name_matches("a\\*b", "a*b"));
  EXPECT_FALSE(glob_name_matches("a\\*b", "aXb"));
  EXPECT_TRUE(glob_name_matches("\\[x]", "[x]"));
  EXPECT_FALSE(glob_name_matches("\\[x]", "x"));
}

TEST(TrackArguments, ArgumentsKeepTheirOrder) {
  Folder f;
  const std::string z = f.add("z.gpx");
  f.add("d/b.gpx");
  f.add("d/a.gpx");
  EXPECT_EQ(expand_track_arguments({z, f.at("d"), "-", z}), (Paths{z, f.at("d/a.gpx"), f.at("d/b.gpx"), "-", z}));
}

TEST(TrackArguments, PatternWithoutMatchIsAnErrorNamingIt) {
  Folder f;
  f.add("a.gpx");
  const std::string pattern = f.root + "/*.igc";
  const std::string message = error_of({pattern});
  EXPECT_NE(message.find(pattern), std::string::npos) << message;
  EXPECT_NE(message.find("no file matches"), std::string::npos) << message;
  // A pattern under a folder that does not exist.
  EXPECT_NE(error_of({f.root + "/none/*.gpx"}).find("no file matches"), std::string::npos);
}

TEST(TrackArguments, PatternMatchingOnlyOtherFilesIsAnError) {
  Folder f;
  f.add("a.txt");
  f.add("b.csv");
  const std::string pattern = f.root + "/*";
  const std::string message = error_of({pattern});
  EXPECT_NE(message.find(pattern + ": the pattern matches no track file"), std::string::npos) << message;
}

TEST(TrackArguments, FolderWithoutTrackFilesIsAnErrorNamingIt) {
  Folder f;
  f.add("notes.txt");
  f.add("sub/a.gpx");
  const std::string message = error_of({f.root});
  EXPECT_NE(message.find(f.root + ": the folder holds no track file"), std::string::npos) << message;
}

TEST(TrackArguments, ExistingNameWithPatternCharactersIsTakenAsIs) {
  Folder f;
  const std::string odd = f.add("flight [1] *best?.igc");
  f.add("flight 1 xbestx.igc");  // what the name would match as a pattern
  EXPECT_EQ(expand_track_arguments({odd}), (Paths{odd}));
}

TEST(TrackArguments, PlainNamesThatDoNotExistAndStandardInputPassThrough) {
  EXPECT_EQ(expand_track_arguments({"-", "/no/such/file.gpx"}), (Paths{"-", "/no/such/file.gpx"}));
  EXPECT_EQ(expand_track_arguments({}), Paths{});
}

TEST(TrackArguments, TrackExtensions) {
  for (const char* name : {"a.gpx", "a.GPX", "a.igc", "a.tcx", "a.fit", "a.kml", "a.kmz", "a.geojson", "a.json",
                           "a.gpx.gz", "a.IGC.GZ", "x.y.kml"})
    EXPECT_TRUE(has_track_extension(name)) << name;
  for (const char* name : {"a.txt", "a.gz", "gpx", ".gpx", "a.gpx.zip", "a.igc~", "a.jsonl", "a"})
    EXPECT_FALSE(has_track_extension(name)) << name;
}

TEST(TrackArguments, GlobNameMatching) {
  EXPECT_TRUE(glob_name_matches("*.igc", "a.igc"));
  EXPECT_FALSE(glob_name_matches("*.igc", ".igc.igc"));  // a leading dot needs a dot
  EXPECT_TRUE(glob_name_matches(".*", ".hidden"));
  EXPECT_FALSE(glob_name_matches("*.igc", "a.igc.gz"));
  EXPECT_TRUE(glob_name_matches("*", "anything"));
  EXPECT_TRUE(glob_name_matches("a*b*c", "aXXbYYbc"));
  EXPECT_FALSE(glob_name_matches("a*b*c", "aXXbYYbd"));
  EXPECT_FALSE(glob_name_matches("f?ght", "flight"));
  EXPECT_TRUE(glob_name_matches("fl?ght", "flight"));
  EXPECT_TRUE(glob_name_matches("day[0-9].gpx", "day7.gpx"));
  EXPECT_FALSE(glob_name_matches("day[0-9].gpx", "dayx.gpx"));
  EXPECT_TRUE(glob_name_matches("day[!0-9].gpx", "dayx.gpx"));
  EXPECT_TRUE(glob_name_matches("day[^0-9].gpx", "dayx.gpx"));
  EXPECT_FALSE(glob_name_matches("day[!0-9].gpx", "day3.gpx"));
  EXPECT_TRUE(glob_name_matches("[]]x", "]x"));
  EXPECT_TRUE(glob_name_matches("a[bc", "a[bc"));  // an unclosed '[' is itself
  EXPECT_FALSE(glob_name_matches("a[bc", "ab"));
  EXPECT_TRUE(glob_name_matches("**", ""));
  EXPECT_FALSE(glob_name_matches("?", ""));
}

}  // namespace
}  // namespace trailray::app
