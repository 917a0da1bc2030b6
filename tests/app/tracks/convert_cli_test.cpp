// `trailray convert` as a user runs it: round trips through every output format, merging,
// --cleaned, and the safety of the output file (atomic, --force, never over an input).
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/run_command.hpp"
#include "test_support.hpp"

using trailray::test::run_command;
using trailray::test::shell_quote;
using trailray::test::TempFile;

namespace {

std::string binary() { return shell_quote(TRAILRAY_BINARY); }

std::string convert(const std::string& args) { return binary() + " convert " + args; }

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every point of a file as trailray reads it, one CSV row each (all channels included).
std::string as_csv(const std::string& path) {
  auto r = run_command(convert(shell_quote(path) + " --format csv -o - 2>/dev/null"));
  EXPECT_EQ(r.status, 0) << path;
  return r.out;
}

std::size_t lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

// Files left in a folder besides `keep` (a temporary file that was not cleaned up, say).
std::vector<std::string> others_in(const std::filesystem::path& dir, const std::vector<std::string>& keep) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (std::find(keep.begin(), keep.end(), n) == keep.end()) out.push_back(n);
  }
  return out;
}

const char* kGpx = R"(<gpx version="1.1" xmlns:gpxtpx="http://www.garmin.com/xmlschemas/TrackPointExtension/v1">
<wpt lat="46.5" lon="7.5"><ele>2000</ele><name>Hut</name><desc>beds</desc><sym>Lodge</sym></wpt>
<rte><name>plan</name><rtept lat="46.0" lon="7.0"/><rtept lat="46.1" lon="7.1"/></rte>
<trk><name>Ride</name><type>cycling</type><trkseg>
<trkpt lat="46.0000001" lon="7.0000001"><ele>1000.5</ele><time>2024-06-01T10:00:00.250Z</time><extensions><power>250</power>
<gpxtpx:TrackPointExtension><gpxtpx:atemp>21.5</gpxtpx:atemp><gpxtpx:hr>120</gpxtpx:hr><gpxtpx:cad>80</gpxtpx:cad></gpxtpx:TrackPointExtension></extensions></trkpt>
<trkpt lat="46.0009" lon="7.0"><ele>1001</ele><time>2024-06-01T10:00:10Z</time><extensions><power>260</power>
<gpxtpx:TrackPointExtension><gpxtpx:atemp>21.25</gpxtpx:atemp><gpxtpx:hr>121</gpxtpx:hr><gpxtpx:cad>81</gpxtpx:cad></gpxtpx:TrackPointExtension></extensions></trkpt>
</trkseg><trkseg>
<trkpt lat="46.1" lon="7.1"><ele>900</ele><time>2024-06-01T11:00:00Z</time></trkpt>
<trkpt lat="46.1009" lon="7.1"><time>2024-06-01T11:00:10Z</time></trkpt>
</trkseg></trk></gpx>)";

}  // namespace

TEST(ConvertCli, GpxToGeoJsonToGpxKeepsPointsTimesAndChannels) {
  TempFile in("in.gpx", kGpx);
  const auto dir = in.path().parent_path();
  const std::string geojson = (dir / "out.geojson").string(), back = (dir / "back.gpx").string();
  ASSERT_EQ(run_command(convert(shell_quote(in.str()) + " -o " + shell_quote(geojson))).status, 0);
  ASSERT_EQ(run_command(convert(shell_quote(geojson) + " -o " + shell_quote(back))).status, 0);
  const std::string original = as_csv(in.str());
  EXPECT_EQ(lines(original), 1u + 4 + 2 + 1);
  EXPECT_EQ(as_csv(geojson), original);
  EXPECT_EQ(as_csv(back), original);
  EXPECT_NE(original.find("track,1,1,Ride,46.0000001,7.0000001,1000.5,2024-06-01T10:00:00.250Z,120,80,250,21.5,"),
            std::string::npos)
      << original;
  EXPECT_NE(original.find("waypoint,1,,Hut,46.5,7.5,2000,"), std::string::npos);
  const std::string gpx = slurp(back);
  EXPECT_NE(gpx.find("<desc>beds</desc><sym>Lodge</sym>"), std::string::npos) << gpx;
  EXPECT_NE(gpx.find("<type>cycling</type>"), std::string::npos);
}

TEST(ConvertCli, RealGpxFilesRoundTripThroughGeoJsonWithEveryExtension) {
  // power (gpsbabel, from a TCX), heart rate (togeojson's run), temperature (gpx.studio).
  for (const char* name : {"gpx/gpsbabel_gtrnctr_power.gpx", "gpx/togeojson_run_gpxtpx.gpx",
                           "gpx/gpxstudio_with_temp.gpx", "gpx/togeojson_blue_hills.gpx"}) {
    TRAILRAY_REQUIRE_DATA(src, name);
    TempFile out("out.geojson");
    std::filesystem::remove(out.path());
    auto r = run_command(convert(shell_quote(src.string()) + " -o " + shell_quote(out.str()) + " 2>&1"));
    ASSERT_EQ(r.status, 0) << r.out;
    const std::string original = as_csv(src.string());
    EXPECT_GT(lines(original), 50u) << name;
    EXPECT_EQ(as_csv(out.str()), original) << name;
  }
}

TEST(ConvertCli, CsvHasAHeaderAndARowPerPoint) {
  TempFile in("in.gpx", kGpx);
  const auto out = in.path().parent_path() / "points.csv";
  ASSERT_EQ(run_command(convert(shell_quote(in.str()) + " -o " + shell_quote(out.string()))).status, 0);
  std::istringstream s(slurp(out));
  std::vector<std::string> rows;
  for (std::string line; std::getline(s, line);) rows.push_back(line);
  ASSERT_EQ(rows.size(), 8u);
  EXPECT_EQ(rows[0], "kind,track,segment,name,lat,lon,ele,time,hr,cad,power,temp,speed");
  EXPECT_EQ(rows[1], "track,1,1,Ride,46.0000001,7.0000001,1000.5,2024-06-01T10:00:00.250Z,120,80,250,21.5,");
  EXPECT_EQ(rows[4], "track,1,2,Ride,46.1009,7.1,,2024-06-01T11:00:10Z,,,,,");
  EXPECT_EQ(rows[5], "route,1,,plan,46,7,,,,,,,");
  EXPECT_EQ(rows[7], "waypoint,1,,Hut,46.5,7.5,2000,,,,,,");
}

TEST(ConvertCli, KmlIsReadByGdalWithTheSameCoordinates) {
  TempFile in("in.gpx", kGpx);
  const auto out = in.path().parent_path() / "out.kml";
  ASSERT_EQ(run_command(convert(shell_quote(in.str()) + " -o " + shell_quote(out.string()))).status, 0);
  const std::string kml = slurp(out);
  EXPECT_NE(kml.find("<gx:MultiTrack>"), std::string::npos);
  EXPECT_NE(kml.find("<when>2024-06-01T10:00:00.250Z</when>"), std::string::npos);
  EXPECT_NE(kml.find("<gx:SimpleArrayData name=\"heartrate\"><gx:value>120</gx:value><gx:value>121</gx:value>"),
            std::string::npos);
  auto ogr = run_command("ogrinfo -ro -al -q -fields=NO " + shell_quote(out.string()) + " 2>&1");
  ASSERT_EQ(ogr.status, 0) << "ogrinfo (gdal-bin, scripts/setup.sh) failed: " << ogr.out;
  // The track (2 segments), the route, the waypoint: GDAL sees every coordinate we wrote.
  EXPECT_NE(ogr.out.find("7.0000001 46.0000001 1000.5,7.0 46.0009 1001"), std::string::npos) << ogr.out;
  EXPECT_NE(ogr.out.find("7.1 46.1 900,7.1 46.1009"), std::string::npos) << ogr.out;
  EXPECT_NE(ogr.out.find("LINESTRING (7 46,7.1 46.1)"), std::string::npos) << ogr.out;
  EXPECT_NE(ogr.out.find("POINT Z (7.5 46.5 2000)"), std::string::npos) << ogr.out;
}

TEST(ConvertCli, SeveralInputsMergeInOrder) {
  TempFile a("a.gpx", kGpx);
  TempFile b("b.geojson", R"({"type":"Feature","properties":{"name":"second"},
      "geometry":{"type":"LineString","coordinates":[[8,47],[8.1,47.1]]}})");
  auto r = run_command(convert(shell_quote(a.str()) + " " + shell_quote(b.str()) + " --format csv -o -"));
  ASSERT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("track,1,1,Ride,"), std::string::npos);
  EXPECT_NE(r.out.find("track,2,1,second,47,8,"), std::string::npos);
  EXPECT_LT(r.out.find("track,1,"), r.out.find("track,2,"));
  EXPECT_EQ(lines(r.out), 1u + 4 + 2 + 2 + 1);
}

TEST(ConvertCli, CleanedWritesTheCleanedTracks) {
  TRAILRAY_REQUIRE_DATA(src, "gpx/gpsbabel_skytraq-miniHomer2_8.gpx");
  auto raw = run_command(convert(shell_quote(src.string()) + " --format csv -o - 2>/dev/null"));
  auto clean = run_command(convert(shell_quote(src.string()) + " --cleaned --format csv -o - 2>/dev/null"));
  ASSERT_EQ(raw.status, 0);
  ASSERT_EQ(clean.status, 0);
  EXPECT_LT(lines(clean.out), lines(raw.out));  // dropped by --min-distance, positions smoothed
  EXPECT_NE(clean.out, raw.out);
  auto unsmoothed = run_command(
      convert(shell_quote(src.string()) + " --cleaned --no-smooth --min-distance 0 --format csv -o - 2>/dev/null"));
  EXPECT_LE(lines(unsmoothed.out), lines(raw.out));
  EXPECT_GT(lines(unsmoothed.out), lines(clean.out));
}

TEST(ConvertCli, CleanedRoutesAreNeverSmoothed) {
  // A planned zig-zag (a route: every point a place someone chose) and the same points recorded
  // (a track): --cleaned smooths the track's corners and leaves the route's points where they are.
  std::string zig;
  for (int i = 0; i < 12; ++i)
    zig += "<rtept lat=\"" + std::to_string(46.0 + 0.001 * i) + "\" lon=\"" + std::to_string(7.0 + (i % 2) * 0.002) + "\"/>";
  std::string trk = zig;
  for (std::string::size_type at; (at = trk.find("rtept")) != std::string::npos;) trk.replace(at, 5, "trkpt");
  TempFile in("plan.gpx", "<gpx version=\"1.1\"><rte>" + zig + "</rte><trk><trkseg>" + trk + "</trkseg></trk></gpx>");
  auto raw = run_command(convert(shell_quote(in.str()) + " --format csv -o - 2>/dev/null"));
  auto clean = run_command(convert(shell_quote(in.str()) + " --cleaned --format csv -o - 2>/dev/null"));
  ASSERT_EQ(raw.status, 0);
  ASSERT_EQ(clean.status, 0);
  const auto rows_of = [](const std::string& csv, const std::string& kind) {
    std::vector<std::string> rows;
    std::istringstream text(csv);
    for (std::string line; std::getline(text, line);)
      if (line.rfind(kind + ",", 0) == 0) rows.push_back(line);
    return rows;
  };
  EXPECT_EQ(rows_of(clean.out, "route"), rows_of(raw.out, "route"));
  ASSERT_EQ(rows_of(raw.out, "route").size(), 12u);
  EXPECT_NE(rows_of(clean.out, "track"), rows_of(raw.out, "track"));  // the track's corners smoothed
}

TEST(ConvertCli, ExistingOutputNeedsForceAndIsReplacedAtomically) {
  TempFile in("in.gpx", kGpx);
  const auto dir = in.path().parent_path();
  const auto out = dir / "out.geojson";
  std::ofstream(out) << "precious";
  auto r = run_command(convert(shell_quote(in.str()) + " -o " + shell_quote(out.string()) + " 2>&1"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("already exists (--force replaces it)"), std::string::npos) << r.out;
  EXPECT_EQ(slurp(out), "precious");
  r = run_command(convert(shell_quote(in.str()) + " -o " + shell_quote(out.string()) + " --force 2>&1"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(slurp(out).rfind("{\"type\":\"FeatureCollection\"", 0), 0u);
  // A word on success: what was written.
  EXPECT_NE(r.out.find("wrote " + out.string() + ": 1 track ("), std::string::npos) << r.out;
  EXPECT_EQ(others_in(dir, {"in.gpx", "out.geojson"}), std::vector<std::string>{});  // no temporary left
}

TEST(ConvertCli, NeverWritesOverAnInputEvenUnderAnotherName) {
  TempFile in("in.geojson", R"({"type":"LineString","coordinates":[[8,47],[8.1,47.1]]})");
  const auto dir = in.path().parent_path();
  const std::string before = slurp(in.path());
  std::filesystem::create_hard_link(in.path(), dir / "hard.geojson");
  std::filesystem::create_symlink(in.path(), dir / "soft.geojson");
  for (const std::string& out : {in.str(), (dir / "hard.geojson").string(), (dir / "soft.geojson").string(),
                                 (dir / "." / "in.geojson").string()}) {
    auto r = run_command(convert(shell_quote(in.str()) + " -o " + shell_quote(out) + " --force 2>&1"));
    EXPECT_EQ(r.status, 1) << out;
    EXPECT_NE(r.out.find("is the input file"), std::string::npos) << r.out;
    EXPECT_EQ(slurp(in.path()), before);
  }
}

TEST(ConvertCli, ErrorsNameTheFileAndWriteNothing) {
  TempFile in("in.gpx", kGpx);
  const auto dir = in.path().parent_path();
  TempFile broken("broken.geojson", "{\"type\":\"FeatureCollection\",\n\"features\":[ nope ]}");
  auto r = run_command(convert(shell_quote(in.str()) + " " + shell_quote(broken.str()) + " -o " +
                               shell_quote((dir / "out.gpx").string()) + " 2>&1"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find(broken.str() + ":2:15: invalid JSON"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.gpx"));
  r = run_command(convert(shell_quote(in.str()) + " -o " + shell_quote((dir / "out.txt").string()) + " 2>&1"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("cannot tell the format from the extension '.txt'"), std::string::npos) << r.out;
  r = run_command(convert(shell_quote(in.str()) + " -o - 2>&1"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("needs --format"), std::string::npos) << r.out;
  r = run_command(
      convert(shell_quote(in.str()) + " -o " + shell_quote((dir / "no" / "such" / "x.kml").string()) + " 2>&1"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("x.kml: cannot create a temporary file in its folder"), std::string::npos) << r.out;
}

TEST(ConvertCli, FitInputConvertsToGpxWithTheSamePoints) {
  TRAILRAY_REQUIRE_DATA(fit, "fit/fitparse_garmin-fenix-5-bike.fit");
  TempFile out("bike.gpx");
  std::filesystem::remove(out.path());
  auto r = run_command(convert(shell_quote(fit.string()) + " -o " + shell_quote(out.str()) + " 2>&1"));
  ASSERT_EQ(r.status, 0) << r.out;
  const std::string original = as_csv(fit.string());
  EXPECT_EQ(lines(original), 1u + 19);  // MANIFEST: 19 records with a position
  EXPECT_EQ(as_csv(out.str()), original);
}

TEST(ConvertCli, ADeviceIsWrittenIntoNotReplaced) {
  TempFile in("in.gpx", kGpx);
  auto r = run_command(convert(shell_quote(in.str()) + " -o /dev/null --format kml 2>&1"));
  EXPECT_EQ(r.status, 0) << r.out;
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));  // renaming a file over it would have made it a file
}

TEST(ConvertCli, StandardInputToStandardOutput) {
  TempFile in("in.gpx", kGpx);
  auto r = run_command("cat " + shell_quote(in.str()) + " | " + convert("- -o - --format geojson"));
  ASSERT_EQ(r.status, 0);
  EXPECT_EQ(r.out.rfind("{\"type\":\"FeatureCollection\"", 0), 0u);
  EXPECT_NE(r.out.find("\"name\":\"Ride\""), std::string::npos);
}
