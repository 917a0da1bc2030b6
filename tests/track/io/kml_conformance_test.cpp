// Conformance with two peers, each read in the same test run.
//
// GDAL's OGR (Debian python3-gdal, the LIBKML driver): for every KML and KMZ in shared/data/kml
// that OGR reads, trailray's lines and points have the same positions, to 1e-7 degree. Lines are tracks' segments
// (LineString, gx:Track, each gx:Track of a gx:MultiTrack), points are waypoints; both sides are compared as sorted
// lists, since OGR orders features by its layers (folders) rather than by the document.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "app/run_command.hpp"
#include "test_support.hpp"
#include "track/io/load.hpp"
#include "track/io/parse_util.hpp"

using nlohmann::json;
using namespace trailray::track;

namespace {

using Position = std::array<double, 2>;  // lon, lat
using Line = std::vector<Position>;

using trailray::test::run_command;
using trailray::test::shell_quote;

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
      "/usr/bin/python3 " + shell_quote(std::string(TRAILRAY_SOURCE_DIR) + "/tests/conformance/ogr_kml_coordinates.py");
  for (const auto& f : files) command += " " + shell_quote(f);
  std::string out;
  ASSERT_TRUE(run_command(command + " 2>/dev/null", out)) << "the OGR script failed (is python3-gdal installed? run "
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

namespace {

// A GPX point as gpsbabel writes it: lat, lon and the time (NaN when it wrote none).
struct PeerPoint {
  double lat, lon, time;
};

// The <trkpt> (or <wpt>) elements of gpsbabel's GPX output, in order.
std::vector<PeerPoint> gpx_points(const std::string& gpx, const std::string& tag) {
  std::vector<PeerPoint> points;
  const std::string open = "<" + tag + " lat=\"", close = "</" + tag + ">";
  for (std::size_t at = gpx.find(open); at != std::string::npos; at = gpx.find(open, at + 1)) {
    const std::size_t lat = at + open.size();
    const std::size_t lon = gpx.find("lon=\"", lat) + 5;
    const std::size_t end = gpx.find(close, at);
    const std::size_t time = gpx.find("<time>", at);
    double t = kMissing;
    if (time < end) t = parse_iso8601(gpx.substr(time + 6, gpx.find("</time>", time) - time - 6)).value_or(kMissing);
    points.push_back({std::stod(gpx.substr(lat, 20)), std::stod(gpx.substr(lon, 20)), t});
  }
  return points;
}

}  // namespace

// gpsbabel's KML reader (Debian gpsbabel; it reads no KMZ): the same track points in the same
// order, to 1e-7 degree, with the same times to the millisecond where the file gives them, and
// the same waypoints. A LineString has no times in KML: gpsbabel spreads its placemark's
// TimeSpan over the points, which trailray does not invent, so those are not compared.
TEST(KmlConformanceGpsbabel, TrackPointsTimesAndWaypointsMatchOnEveryKml) {
  TRAILRAY_REQUIRE_DATA(dir, "kml");
  int compared = 0, timed = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".kml") continue;
    const std::string file = e.path().string();
    std::string gpx;
    ASSERT_TRUE(run_command("gpsbabel -t -w -i kml -f " + shell_quote(file) + " -o gpx -F - 2>/dev/null", gpx))
        << file << ": gpsbabel failed (is it installed? run scripts/setup.sh)";
    const ReadResult r = load_track_file(file);
    ASSERT_TRUE(r.ok()) << r.error->to_string();
    std::vector<TrackPoint> ours;
    for (const Track& t : r.file.tracks)
      for (const Segment& s : t.segments) ours.insert(ours.end(), s.points.begin(), s.points.end());
    const std::vector<PeerPoint> theirs = gpx_points(gpx, "trkpt");
    ASSERT_EQ(ours.size(), theirs.size()) << file;
    for (std::size_t i = 0; i < ours.size(); ++i) {
      EXPECT_NEAR(ours[i].lat, theirs[i].lat, 1e-7) << file << " point " << i;
      EXPECT_NEAR(ours[i].lon, theirs[i].lon, 1e-7) << file << " point " << i;
      if (ours[i].has_time()) {
        EXPECT_NEAR(ours[i].time, theirs[i].time, 1e-3) << file << " point " << i;
        ++timed;
      }
    }
    const std::vector<PeerPoint> their_waypoints = gpx_points(gpx, "wpt");
    ASSERT_EQ(r.file.waypoints.size(), their_waypoints.size()) << file;
    for (std::size_t i = 0; i < their_waypoints.size(); ++i) {
      EXPECT_NEAR(r.file.waypoints[i].point.lat, their_waypoints[i].lat, 1e-7) << file << " waypoint " << i;
      EXPECT_NEAR(r.file.waypoints[i].point.lon, their_waypoints[i].lon, 1e-7) << file << " waypoint " << i;
      if (!std::isnan(their_waypoints[i].time)) {
        EXPECT_NEAR(r.file.waypoints[i].point.time, their_waypoints[i].time, 1e-3) << file << " waypoint " << i;
      }
    }
    ++compared;
  }
  EXPECT_EQ(compared, 3);
  EXPECT_EQ(timed, 26 + 7);  // the gx:Track points of gxmultitrack and gxtrack
}
