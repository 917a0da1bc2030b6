// The KML and KMZ readers on the real files in ../shared/data/kml (MANIFEST.md there gives the
// counts), and on cut and damaged copies of them.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "test_support.hpp"
#include "track/io/byte_source.hpp"
#include "track/io/load.hpp"
#include "track/io/readers.hpp"

using namespace trailray::track;

namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t track_points(const TrackFile& f) {
  std::size_t n = 0;
  for (const Track& t : f.tracks) n += t.point_count();
  return n;
}

bool all_points_valid(const TrackFile& f) {
  for (const Track& t : f.tracks)
    for (const Segment& s : t.segments)
      for (const TrackPoint& p : s.points)
        if (!valid_coordinates(p.lat, p.lon)) return false;
  for (const Waypoint& w : f.waypoints)
    if (!valid_coordinates(w.point.lat, w.point.lon)) return false;
  return true;
}

ReadResult read_bytes(const std::string& bytes, const std::string& name) {
  auto src = ByteSource::from_memory(bytes, name);
  return name.ends_with(".kmz") ? read_kmz(*src, {}) : read_kml(*src, {});
}

}  // namespace

TEST(KmlReaderData, SkydropLineStringWithAbsoluteAltitudes) {
  TRAILRAY_REQUIRE_DATA(path, "kml/gpsbabel_skydrop.kml");
  ReadResult r = load_track_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(r.file.format, Format::Kml);
  EXPECT_EQ(r.file.metadata.name, "Flight log from 21.08.2017 @ 17:00");
  ASSERT_EQ(r.file.tracks.size(), 1u);
  const Track& t = r.file.tracks[0];
  EXPECT_EQ(t.name, "Flight");
  ASSERT_EQ(t.segments.size(), 1u);
  const auto& p = t.segments[0].points;
  ASSERT_EQ(p.size(), 1329u);  // MANIFEST: 1329 tuples, the comments between them skipped
  EXPECT_DOUBLE_EQ(p[0].lon, 8.5155383);
  EXPECT_DOUBLE_EQ(p[0].lat, 48.2662716);
  EXPECT_DOUBLE_EQ(p[0].ele, 768.0);  // altitudeMode absolute
  EXPECT_DOUBLE_EQ(p.back().lon, 8.514155);
  EXPECT_FALSE(p[0].has_time());
}

TEST(KmlReaderData, GxMultiTrackTwoSegmentsOf13AndTwoTimedPoints) {
  TRAILRAY_REQUIRE_DATA(path, "kml/togeojson_gxmultitrack.kml");
  ReadResult r = load_track_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(r.file.metadata.name, "12/04/2014 11:24 AM");
  ASSERT_EQ(r.file.tracks.size(), 1u);
  const Track& t = r.file.tracks[0];
  EXPECT_EQ(t.type, "course à pied");
  ASSERT_EQ(t.segments.size(), 2u);
  EXPECT_EQ(t.segments[0].points.size(), 13u);
  EXPECT_EQ(t.segments[1].points.size(), 13u);
  const TrackPoint& first = t.segments[0].points[0];
  EXPECT_DOUBLE_EQ(first.lon, -71.324739);
  EXPECT_DOUBLE_EQ(first.ele, 791.5999755859375);  // the MultiTrack's altitudeMode absolute
  EXPECT_DOUBLE_EQ(first.time, 1397312776.702);    // 2014-04-12T14:26:16.702Z
  EXPECT_DOUBLE_EQ(t.segments[1].points[12].time, 1397312844.638);
  ASSERT_EQ(r.file.waypoints.size(), 2u);
  EXPECT_EQ(r.file.waypoints[0].name, "12/04/2014 11:24 AM (départ)");
  EXPECT_DOUBLE_EQ(r.file.waypoints[0].point.time, 1397312776.702);
  EXPECT_FALSE(r.file.waypoints[0].point.has_ele());  // no altitudeMode: clampToGround
  EXPECT_DOUBLE_EQ(r.file.waypoints[1].point.lat, -40.157777);
}

TEST(KmlReaderData, GxTrackSevenTimedPointsClampedToGround) {
  TRAILRAY_REQUIRE_DATA(path, "kml/togeojson_gxtrack.kml");
  ReadResult r = load_track_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  ASSERT_EQ(r.file.tracks.size(), 1u);
  const auto& p = r.file.tracks[0].segments.at(0).points;
  ASSERT_EQ(p.size(), 7u);
  EXPECT_DOUBLE_EQ(p[6].lon, -122.203207);
  EXPECT_DOUBLE_EQ(p[6].time, 1275012176.0);                // 2010-05-28T02:02:56Z
  for (const TrackPoint& q : p) EXPECT_FALSE(q.has_ele());  // no altitudeMode: the spec's clampToGround
}

TEST(KmlReaderData, GeotagKmzReadsBothEntries) {
  TRAILRAY_REQUIRE_DATA(path, "kml/geotag_kmz1.kmz");
  ReadResult r = load_track_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(r.file.format, Format::Kmz);
  EXPECT_EQ(r.file.metadata.name, "Susdal");  // track1.kml's
  // Each entry: 3 positions, a 3-point path and 3 accuracy circles of 16 points; 108 in all.
  ASSERT_EQ(r.file.waypoints.size(), 6u);
  ASSERT_EQ(r.file.tracks.size(), 8u);
  EXPECT_EQ(track_points(r.file) + r.file.waypoints.size(), 108u);
  EXPECT_EQ(r.file.tracks[0].name, "Path");
  EXPECT_EQ(r.file.tracks[4].name, "Path");
  EXPECT_EQ(r.file.waypoints[1].name, "fused2");
  EXPECT_DOUBLE_EQ(r.file.waypoints[1].point.time, 1438016916.0);  // 20:08:36+03:00
  EXPECT_DOUBLE_EQ(r.file.waypoints[0].point.time, 1438016887.0);  // 17:08:07Z
  EXPECT_DOUBLE_EQ(r.file.waypoints[3].point.lon, 40.9483229);     // track2.kml's first
}

TEST(KmlReaderData, FurkotKmzStopsMatchTheImportersExpectation) {
  TRAILRAY_REQUIRE_DATA(path, "kml/furkot_usa.kmz");
  TRAILRAY_REQUIRE_DATA(expected_path, "kml/furkot_usa.expected.json");
  ReadResult r = load_track_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  const nlohmann::json expected = nlohmann::json::parse(slurp(expected_path));
  EXPECT_EQ(r.file.metadata.name, expected["destination"].get<std::string>());
  EXPECT_EQ(r.file.metadata.description, expected["notes"].get<std::string>());
  const auto& stops = expected["stops"];
  ASSERT_EQ(stops.size(), 12u);
  ASSERT_EQ(r.file.waypoints.size(), stops.size());
  EXPECT_TRUE(r.file.tracks.empty());
  for (std::size_t i = 0; i < stops.size(); ++i) {
    const Waypoint& w = r.file.waypoints[i];
    EXPECT_EQ(w.name, stops[i]["name"].get<std::string>()) << i;
    EXPECT_NEAR(w.point.lon, stops[i]["coordinates"]["lon"].get<double>(), 1e-9) << i;
    EXPECT_NEAR(w.point.lat, stops[i]["coordinates"]["lat"].get<double>(), 1e-9) << i;
    EXPECT_FALSE(w.point.has_ele()) << i;  // ",0" under the default clampToGround
  }
}

TEST(KmlReaderData, KmzWithoutKmlIsAnErrorNamingTheFile) {
  TRAILRAY_REQUIRE_DATA(path, "kml/furkot_no-kml-inside.kmz");
  ReadResult r = load_track_file(path.string());
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->file, path.string());
  EXPECT_NE(r.error->message.find("no KML document"), std::string::npos) << r.error->message;
  EXPECT_NE(r.error->message.find("PL-TollGate.csv"), std::string::npos) << r.error->message;
}

// Every real file cut at many offsets, and with bytes changed: never a crash, never an invalid
// point, at most the complete file's points, and a cut KML keeps what came before the cut.
TEST(KmlReaderData, CutAndDamagedCopiesNeverCrash) {
  TRAILRAY_REQUIRE_DATA(dir, "kml");
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (ext != ".kml" && ext != ".kmz") continue;
    ++files;
    const std::string name = e.path().filename().string();
    const std::string bytes = slurp(e.path());
    const ReadResult whole = read_bytes(bytes, name);
    const std::size_t whole_points = track_points(whole.file) + whole.file.waypoints.size();
    std::size_t previous = 0;
    const std::size_t step = std::max<std::size_t>(1, bytes.size() / 300);
    for (std::size_t cut = 0; cut < bytes.size(); cut += step) {
      ReadResult r = read_bytes(bytes.substr(0, cut), name);
      const std::size_t points = track_points(r.file) + r.file.waypoints.size();
      EXPECT_TRUE(all_points_valid(r.file)) << name << " cut at " << cut;
      EXPECT_LE(points, whole_points) << name << " cut at " << cut;
      if (ext == ".kml" && r.ok()) {
        EXPECT_GE(points, previous) << name << " cut at " << cut << ": a longer prefix keeps fewer points";
        previous = points;
      }
      if (r.error) {
        EXPECT_FALSE(r.error->message.empty());
      }
    }
    for (std::size_t at = 0; at < bytes.size(); at += step) {
      std::string bent = bytes;
      bent[at] = static_cast<char>(bent[at] ^ 0x5A);
      ReadResult r = read_bytes(bent, name);
      EXPECT_TRUE(all_points_valid(r.file)) << name << " changed at " << at;
    }
  }
  EXPECT_GE(files, 6);
}
