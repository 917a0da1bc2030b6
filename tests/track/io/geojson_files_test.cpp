// The GeoJSON reader on the real files in shared/data/geojson: every coordinate and time checked
// against an independent parse of the same file (nlohmann's DOM), and against the GPX files
// togeojson made them from.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "test_support.hpp"
#include "track/io/load.hpp"
#include "track/io/parse_util.hpp"

using namespace trailray::track;
using nlohmann::json;

namespace {

std::vector<TrackPoint> all_track_points(const TrackFile& f) {
  std::vector<TrackPoint> out;
  for (const auto& t : f.tracks)
    for (const auto& s : t.segments) out.insert(out.end(), s.points.begin(), s.points.end());
  return out;
}

// Lines of a geometry as the DOM has them, with their coordTimes (nested like the lines).
void dom_lines(const json& g, std::vector<json>& lines) {
  const std::string type = g["type"];
  if (type == "LineString") lines.push_back(g["coordinates"]);
  if (type == "MultiLineString")
    for (const auto& l : g["coordinates"]) lines.push_back(l);
  if (type == "GeometryCollection")
    for (const auto& m : g["geometries"]) dom_lines(m, lines);
}

}  // namespace

TEST(GeoJsonFiles, EveryCoordinateAndTimeMatchesAnIndependentParse) {
  TRAILRAY_REQUIRE_DATA(dir, "geojson");
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string path = e.path().string();
    SCOPED_TRACE(path);
    ReadResult r = load_track_file(path);
    ASSERT_TRUE(r.ok()) << r.error->to_string();
    EXPECT_EQ(r.file.format, Format::GeoJson);
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front().to_string();
    std::ifstream in(path);
    const json doc = json::parse(in);
    std::vector<TrackPoint> read = all_track_points(r.file);
    std::size_t k = 0, waypoints = 0, tracks = 0;
    for (const auto& f : doc["features"]) {
      const json& g = f["geometry"];
      if (g["type"] == "Point") {
        ASSERT_LT(waypoints, r.file.waypoints.size());
        const Waypoint& w = r.file.waypoints[waypoints++];
        EXPECT_DOUBLE_EQ(w.point.lon, g["coordinates"][0].get<double>());
        EXPECT_DOUBLE_EQ(w.point.lat, g["coordinates"][1].get<double>());
        if (f["properties"].contains("name")) {
          EXPECT_EQ(w.name, std::string(trim(f["properties"]["name"].get<std::string>())));
        }
        continue;
      }
      std::vector<json> lines;
      dom_lines(g, lines);
      if (lines.empty()) continue;
      ASSERT_LT(tracks, r.file.tracks.size());
      const Track& t = r.file.tracks[tracks++];
      EXPECT_EQ(t.name, std::string(trim(f["properties"].value("name", ""))));
      ASSERT_EQ(t.segments.size(), lines.size());
      const json times = f["properties"].value("coordTimes", json::array());
      for (std::size_t l = 0; l < lines.size(); ++l) {
        ASSERT_EQ(t.segments[l].points.size(), lines[l].size());
        for (std::size_t i = 0; i < lines[l].size(); ++i, ++k) {
          const json& c = lines[l][i];
          ASSERT_LT(k, read.size());
          EXPECT_DOUBLE_EQ(read[k].lon, c[0].get<double>());
          EXPECT_DOUBLE_EQ(read[k].lat, c[1].get<double>());
          if (c.size() > 2) {
            EXPECT_DOUBLE_EQ(read[k].ele, c[2].get<double>());
          }
          if (!times.empty()) {
            const json& tv = times[0].is_array() ? times[l][i] : times[i];
            EXPECT_DOUBLE_EQ(read[k].time, *parse_iso8601(tv.get<std::string>()));
          } else {
            EXPECT_FALSE(read[k].has_time());
          }
        }
      }
    }
    EXPECT_EQ(k, read.size());
    EXPECT_EQ(waypoints, r.file.waypoints.size());
    ++files;
  }
  EXPECT_EQ(files, 4);
}

TEST(GeoJsonFiles, TheManifestsFigures) {
  TRAILRAY_REQUIRE_DATA(dir, "geojson");
  struct Expected {
    const char* file;
    std::size_t tracks, segments, points, waypoints;
  };
  for (const Expected& x : {Expected{"togeojson_run_gpxtpx.gpx.geojson", 1, 1, 1118, 0},
                            Expected{"togeojson_blue_hills.gpx.geojson", 3, 13, 1242, 46},
                            Expected{"togeojson_gxmultitrack.kml.geojson", 1, 2, 26, 2},
                            Expected{"gpsbabel_segmented_tracks.geojson", 2, 2, 46, 0}}) {
    ReadResult r = load_track_file((dir / x.file).string());
    ASSERT_TRUE(r.ok()) << x.file;
    std::size_t segments = 0, points = 0;
    for (const auto& t : r.file.tracks) segments += t.segments.size(), points += t.point_count();
    EXPECT_EQ(r.file.tracks.size(), x.tracks) << x.file;
    EXPECT_EQ(segments, x.segments) << x.file;
    EXPECT_EQ(points, x.points) << x.file;
    EXPECT_EQ(r.file.waypoints.size(), x.waypoints) << x.file;
  }
}

TEST(GeoJsonFiles, SameCoordinatesTimesAndHeartRatesAsTheGpxTogeojsonReadForRun) {
  TRAILRAY_REQUIRE_DATA(gj, "geojson/togeojson_run_gpxtpx.gpx.geojson");
  TRAILRAY_REQUIRE_DATA(gpx, "gpx/togeojson_run_gpxtpx.gpx");
  ReadResult a = load_track_file(gj.string()), b = load_track_file(gpx.string());
  ASSERT_TRUE(a.ok() && b.ok());
  const auto pa = all_track_points(a.file), pb = all_track_points(b.file);
  ASSERT_EQ(pa.size(), pb.size());
  ASSERT_EQ(pa.size(), 1118u);
  for (std::size_t i = 0; i < pa.size(); ++i) {
    EXPECT_DOUBLE_EQ(pa[i].lat, pb[i].lat) << i;
    EXPECT_DOUBLE_EQ(pa[i].lon, pb[i].lon) << i;
    EXPECT_DOUBLE_EQ(pa[i].ele, pb[i].ele) << i;
    EXPECT_DOUBLE_EQ(pa[i].time, pb[i].time) << i;
    EXPECT_FLOAT_EQ(pa[i].heart_rate, pb[i].heart_rate) << i;
  }
  EXPECT_EQ(a.file.tracks[0].name, b.file.tracks[0].name);
}

TEST(GeoJsonFiles, BlueHillsMatchesItsGpxExceptTheOnePointSegmentTogeojsonDropped) {
  TRAILRAY_REQUIRE_DATA(gj, "geojson/togeojson_blue_hills.gpx.geojson");
  TRAILRAY_REQUIRE_DATA(gpx, "gpx/togeojson_blue_hills.gpx");
  ReadResult a = load_track_file(gj.string()), b = load_track_file(gpx.string());
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(a.file.tracks.size(), b.file.tracks.size());
  std::size_t compared = 0, dropped = 0;
  for (std::size_t t = 0; t < a.file.tracks.size(); ++t) {
    EXPECT_EQ(a.file.tracks[t].name, b.file.tracks[t].name);
    std::vector<Segment> gpx_segments;
    for (const auto& s : b.file.tracks[t].segments) {
      if (s.points.size() < 2)
        dropped += s.points.size();  // togeojson keeps lines of 2+ points
      else
        gpx_segments.push_back(s);
    }
    const auto& segs = a.file.tracks[t].segments;
    ASSERT_EQ(segs.size(), gpx_segments.size());
    for (std::size_t s = 0; s < segs.size(); ++s) {
      ASSERT_EQ(segs[s].points.size(), gpx_segments[s].points.size());
      for (std::size_t i = 0; i < segs[s].points.size(); ++i, ++compared) {
        const auto &p = segs[s].points[i], &q = gpx_segments[s].points[i];
        EXPECT_DOUBLE_EQ(p.lat, q.lat);
        EXPECT_DOUBLE_EQ(p.lon, q.lon);
        EXPECT_DOUBLE_EQ(p.ele, q.ele);
        EXPECT_DOUBLE_EQ(p.time, q.time);
      }
    }
  }
  EXPECT_EQ(compared, 1242u);
  EXPECT_EQ(dropped, 1u);
  ASSERT_EQ(a.file.waypoints.size(), b.file.waypoints.size());
  for (std::size_t i = 0; i < a.file.waypoints.size(); ++i) {
    const Waypoint &w = a.file.waypoints[i], &v = b.file.waypoints[i];
    EXPECT_EQ(w.name, v.name);
    EXPECT_EQ(w.description, v.description);
    EXPECT_EQ(w.symbol, v.symbol);
    EXPECT_DOUBLE_EQ(w.point.lat, v.point.lat);
    EXPECT_DOUBLE_EQ(w.point.lon, v.point.lon);
    EXPECT_EQ(w.point.has_ele(), v.point.has_ele());
    if (v.point.has_ele()) {
      EXPECT_DOUBLE_EQ(w.point.ele, v.point.ele);
    }
    if (v.point.has_time()) {
      EXPECT_DOUBLE_EQ(w.point.time, v.point.time);
    }
  }
}
