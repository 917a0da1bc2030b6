// Conformance with GDAL's OGR (Debian python3-gdal, the LIBKML driver), read in the same test
// run: for every KML and KMZ in shared/data/kml that OGR reads, trailray's lines and points have
// the same positions, to 1e-7 degree. Lines are tracks' segments (LineString, gx:Track, each
// gx:Track of a gx:MultiTrack), points are waypoints; both sides are compared as sorted lists,
// since OGR orders features by its layers (folders) rather than by the document.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.hpp"
#include "track/io/load.hpp"

using nlohmann::json;
using namespace trailray::track;

namespace {

using Position = std::array<double, 2>;  // lon, lat
using Line = std::vector<Position>;

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

bool run(const std::string& command, std::string& out) {
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return false;
  char buf[65536];
  for (std::size_t n; (n = fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
  const int status = pclose(pipe);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

Position position(const json& j) { return {j[0].get<double>(), j[1].get<double>()}; }

void expect_same_lines(std::vector<Line> ours, std::vector<Line> theirs, const std::string& file) {
  std::sort(ours.begin(), ours.end());
  std::sort(theirs.begin(), theirs.end());
  ASSERT_EQ(ours.size(), theirs.size()) << file << ": lines";
  for (std::size_t i = 0; i < ours.size(); ++i) {
    ASSERT_EQ(ours[i].size(), theirs[i].size()) << file << ": line " << i;
    for (std::size_t k = 0; k < ours[i].size(); ++k) {
      EXPECT_NEAR(ours[i][k][0], theirs[i][k][0], 1e-7) << file << ": line " << i << " point " << k;
      EXPECT_NEAR(ours[i][k][1], theirs[i][k][1], 1e-7) << file << ": line " << i << " point " << k;
    }
  }
}

}  // namespace

TEST(KmlConformanceOgr, PositionsMatchGdalOnEveryKmlAndKmz) {
  TRAILRAY_REQUIRE_DATA(dir, "kml");
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".kml" || e.path().extension() == ".kmz") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 6u);

  std::string command =
      "/usr/bin/python3 " + quote(std::string(TRAILRAY_SOURCE_DIR) + "/tests/conformance/ogr_kml_coordinates.py");
  for (const auto& f : files) command += " " + quote(f);
  std::string out;
  ASSERT_TRUE(run(command + " 2>/dev/null", out)) << "the OGR script failed (is python3-gdal installed? run "
                                                     "scripts/setup.sh)";
  std::istringstream lines(out);
  int compared = 0;
  for (std::string text; std::getline(lines, text);) {
    const json peer = json::parse(text);
    const std::string file = peer["path"];
    const ReadResult r = load_track_file(file);
    if (!peer["ok"].get<bool>()) {
      // The one file OGR cannot open is the archive without KML; trailray refuses it too.
      EXPECT_FALSE(r.ok()) << file << ": OGR cannot read it, trailray did";
      continue;
    }
    ASSERT_TRUE(r.ok()) << r.error->to_string();
    std::vector<Line> ours, theirs;
    for (const Track& t : r.file.tracks)
      for (const Segment& s : t.segments) {
        Line& l = ours.emplace_back();
        for (const TrackPoint& p : s.points) l.push_back({p.lon, p.lat});
      }
    for (const json& l : peer["lines"]) {
      Line& line = theirs.emplace_back();
      for (const json& p : l) line.push_back(position(p));
    }
    expect_same_lines(ours, theirs, file);
    // Points: each a line of one, the same comparison.
    std::vector<Line> our_points, their_points;
    for (const Waypoint& w : r.file.waypoints) our_points.push_back({{w.point.lon, w.point.lat}});
    for (const json& p : peer["points"]) their_points.push_back({position(p)});
    expect_same_lines(our_points, their_points, file + " (points)");
    ++compared;
  }
  EXPECT_EQ(compared, static_cast<int>(files.size()) - 1) << "every file but the archive without KML compared";
}
