// The GeoJSON reader on synthetic documents: every construct it reads, what it skips, and how
// it reports broken input (JSON paths, line:column).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "track/io/byte_source.hpp"
#include "track/io/readers.hpp"

using namespace trailray::track;

namespace {

ReadResult read(const std::string& text, ReadOptions options = {}) {
  auto src = ByteSource::from_memory(text, "test.geojson");
  return read_geojson(*src, options);
}

std::string warnings_of(const ReadResult& r) {
  std::string s;
  for (const auto& w : r.warnings) s += w.to_string() + "\n";
  return s;
}

bool any_warning_contains(const ReadResult& r, const std::string& needle) {
  return warnings_of(r).find(needle) != std::string::npos;
}

std::string feature(const std::string& geometry, const std::string& properties = "{}") {
  return R"({"type":"Feature","properties":)" + properties + R"(,"geometry":)" + geometry + "}";
}

std::string collection(const std::string& features) {
  return R"({"type":"FeatureCollection","features":[)" + features + "]}";
}

}  // namespace

TEST(GeoJsonReader, LineStringFeatureWithTogeojsonTimesAndHeartRates) {
  auto r =
      read(collection(feature(R"({"type":"LineString","coordinates":[[7.1,46.1,1000],[7.2,46.2,1010.5],[7.3,46.3]]})",
                              R"({"name":" Loop ","desc":"d","type":"running",
                                       "coordTimes":["2024-06-01T10:00:00Z","2024-06-01T10:00:01.250Z",null],
                                       "heartRates":[100,101,102]})")));
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_EQ(r.file.format, Format::GeoJson);
  ASSERT_EQ(r.file.tracks.size(), 1u);
  const Track& t = r.file.tracks[0];
  EXPECT_EQ(t.name, "Loop");
  EXPECT_EQ(t.description, "d");
  EXPECT_EQ(t.type, "running");
  ASSERT_EQ(t.segments.size(), 1u);
  const auto& p = t.segments[0].points;
  ASSERT_EQ(p.size(), 3u);
  EXPECT_DOUBLE_EQ(p[0].lon, 7.1);
  EXPECT_DOUBLE_EQ(p[0].lat, 46.1);
  EXPECT_DOUBLE_EQ(p[1].ele, 1010.5);
  EXPECT_FALSE(p[2].has_ele());
  EXPECT_DOUBLE_EQ(p[0].time, 1717236000.0);
  EXPECT_DOUBLE_EQ(p[1].time, 1717236001.25);
  EXPECT_FALSE(p[2].has_time());
  EXPECT_FLOAT_EQ(p[2].heart_rate, 102.0f);
  EXPECT_TRUE(r.warnings.empty()) << warnings_of(r);
}

TEST(GeoJsonReader, CoordinatePropertiesChannelsInAnyKeyOrder) {
  // gpsbabel writes geometry first and "type" last; coordinateProperties is togeojson's newer form.
  auto r = read(R"({"features":[{"geometry":{"coordinates":[[1,2],[3,4]],"type":"LineString"},
      "properties":{"coordinateProperties":{"times":["2020-01-01T00:00:00Z","2020-01-01T00:00:02Z"],
        "heart":[90,null],"cads":[80,81],"powers":[200,210.5],"atemps":[21.5,22],"speeds":[3.25,"4"]}},
      "type":"Feature"}],"type":"FeatureCollection"})");
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.tracks.size(), 1u);
  const auto& p = r.file.tracks[0].segments[0].points;
  ASSERT_EQ(p.size(), 2u);
  EXPECT_DOUBLE_EQ(p[1].time - p[0].time, 2.0);
  EXPECT_FLOAT_EQ(p[0].heart_rate, 90.0f);
  EXPECT_TRUE(std::isnan(p[1].heart_rate));
  EXPECT_FLOAT_EQ(p[1].cadence, 81.0f);
  EXPECT_FLOAT_EQ(p[1].power, 210.5f);
  EXPECT_FLOAT_EQ(p[0].temperature, 21.5f);
  EXPECT_FLOAT_EQ(p[1].speed, 4.0f);
}

TEST(GeoJsonReader, MultiLineStringIsOneTrackWithASegmentPerLine) {
  auto r = read(feature(R"({"type":"MultiLineString","coordinates":[[[1,2],[1.1,2.1]],[[5,6],[5.1,6.1],[5.2,6.2]]]})",
                        R"({"name":"two","coordTimes":[["2020-01-01T00:00:00Z","2020-01-01T00:00:01Z"],
                            ["2020-01-01T01:00:00Z","2020-01-01T01:00:01Z","2020-01-01T01:00:02Z"]]})"));
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.tracks.size(), 1u);
  const Track& t = r.file.tracks[0];
  ASSERT_EQ(t.segments.size(), 2u);
  EXPECT_EQ(t.segments[0].points.size(), 2u);
  ASSERT_EQ(t.segments[1].points.size(), 3u);
  EXPECT_DOUBLE_EQ(t.segments[1].points[2].time - t.segments[0].points[0].time, 3602.0);
  EXPECT_DOUBLE_EQ(t.segments[1].points[0].lon, 5.0);
}

TEST(GeoJsonReader, GeometryCollectionOfLinesIsOneTrackAsTogeojsonWritesGxMultiTrack) {
  auto r = read(feature(R"({"type":"GeometryCollection","geometries":[
                             {"type":"LineString","coordinates":[[1,2,3],[1.1,2.1,4]]},
                             {"type":"LineString","coordinates":[[5,6],[5.1,6.1]]},
                             {"type":"Point","coordinates":[9,9]},
                             {"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}]})",
                        R"({"name":"multi","coordTimes":[["2020-01-01T00:00:00.5Z","2020-01-01T00:00:01Z"],
                            ["2020-01-01T00:00:02Z","2020-01-01T00:00:03Z"]]})"));
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.tracks.size(), 1u);
  ASSERT_EQ(r.file.tracks[0].segments.size(), 2u);
  EXPECT_DOUBLE_EQ(r.file.tracks[0].segments[0].points[0].time, 1577836800.5);
  ASSERT_EQ(r.file.waypoints.size(), 1u);
  EXPECT_EQ(r.file.waypoints[0].name, "multi");
  EXPECT_TRUE(any_warning_contains(r, "Polygon geometry skipped")) << warnings_of(r);
}

TEST(GeoJsonReader, BareGeometryAtTheTopLevel) {
  auto r = read(R"({"type":"LineString","coordinates":[[10,20],[10.5,20.5]]})");
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.tracks.size(), 1u);
  EXPECT_EQ(r.file.tracks[0].point_count(), 2u);
}

TEST(GeoJsonReader, PointsAndMultiPointsAreWaypoints) {
  auto r = read(collection(feature(R"({"type":"Point","coordinates":[7.5,46.5,1234.5]})",
                                   R"({"name":"Hut","desc":"food","sym":"Lodge","time":"2021-07-01T12:00:00Z"})") +
                           "," +
                           feature(R"({"type":"MultiPoint","coordinates":[[1,2],[3,4]]})",
                                   R"({"name":"pair","timestamp":"2021-07-01T12:00:00Z"})")));
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.waypoints.size(), 3u);
  const Waypoint& w = r.file.waypoints[0];
  EXPECT_EQ(w.name, "Hut");
  EXPECT_EQ(w.description, "food");
  EXPECT_EQ(w.symbol, "Lodge");
  EXPECT_DOUBLE_EQ(w.point.ele, 1234.5);
  EXPECT_DOUBLE_EQ(w.point.time, 1625140800.0);
  EXPECT_EQ(r.file.waypoints[2].name, "pair");
  EXPECT_DOUBLE_EQ(r.file.waypoints[2].point.lon, 3.0);
  EXPECT_DOUBLE_EQ(r.file.waypoints[2].point.time, 1625140800.0);
  EXPECT_TRUE(r.file.tracks.empty());
}

TEST(GeoJsonReader, GpxTypeRteMakesRoutes) {
  auto r = read(collection(
      feature(R"({"type":"LineString","coordinates":[[1,2],[3,4],[5,6]]})", R"({"_gpxType":"rte","name":"plan"})")));
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.file.tracks.empty());
  ASSERT_EQ(r.file.routes.size(), 1u);
  EXPECT_EQ(r.file.routes[0].name, "plan");
  EXPECT_EQ(r.file.routes[0].points.size(), 3u);
}

TEST(GeoJsonReader, PolygonsUnknownTypesAndMissingGeometriesAreSkippedWithCountedWarnings) {
  std::string features;
  for (int i = 0; i < 3; ++i)
    features += feature(R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]})") + ",";
  features += feature(R"({"type":"Curve","coordinates":[[0,0],[1,1]]})") + ",";
  features += feature("null") + ",";
  features += feature(R"({"type":"LineString","coordinates":[[0,0],[1,1]]})");
  auto r = read(collection(features));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.file.tracks.size(), 1u);
  const std::string w = warnings_of(r);
  EXPECT_NE(w.find("features[0].geometry: a Polygon geometry skipped"), std::string::npos) << w;
  EXPECT_NE(w.find("(3 times"), std::string::npos) << w;  // counted, not repeated
  EXPECT_NE(w.find("a Curve geometry skipped"), std::string::npos) << w;
  EXPECT_NE(w.find("features[4]: a feature without a geometry skipped"), std::string::npos) << w;
}

TEST(GeoJsonReader, MismatchedPerPointArraysAreIgnoredWithAWarning) {
  // togeojson leaves out the times of points that have none: they cannot be placed then.
  auto r = read(feature(R"({"type":"LineString","coordinates":[[1,2],[3,4],[5,6]]})",
                        R"({"coordTimes":["2020-01-01T00:00:00Z","2020-01-01T00:00:01Z"],"heartRates":[1,2,3]})"));
  ASSERT_TRUE(r.ok());
  const auto& p = r.file.tracks.at(0).segments.at(0).points;
  ASSERT_EQ(p.size(), 3u);
  EXPECT_FALSE(p[0].has_time());
  EXPECT_FLOAT_EQ(p[2].heart_rate, 3.0f);
  EXPECT_TRUE(any_warning_contains(r, "properties.coordTimes: 2 values for the 3 points of line 1")) << warnings_of(r);
}

TEST(GeoJsonReader, BadCoordinatesAreDroppedNamingTheirJsonPathAndPosition) {
  const std::string text = "{\"type\":\"FeatureCollection\",\"features\":[\n" +
                           feature(R"({"type":"LineString","coordinates":[[1,2],[3,4]]})") + ",\n" +
                           feature(R"({"type":"LineString","coordinates":[[1,2],["3",4],[5,6],[7],[500,1]]})",
                                   R"({"coordTimes":["2020-01-01T00:00:00Z","2020-01-01T00:00:01Z",
                                      "2020-01-01T00:00:02Z","2020-01-01T00:00:03Z","2020-01-01T00:00:04Z"]})") +
                           "]}";
  auto r = read(text);
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.tracks.size(), 2u);
  const auto& p = r.file.tracks[1].segments.at(0).points;
  ASSERT_EQ(p.size(), 2u);  // [1,2] and [5,6], each with its own time
  EXPECT_DOUBLE_EQ(p[1].lon, 5.0);
  EXPECT_DOUBLE_EQ(p[1].time - p[0].time, 2.0);
  const std::string w = warnings_of(r);
  EXPECT_NE(w.find("test.geojson:4:"), std::string::npos) << w;
  EXPECT_NE(w.find("features[1].geometry.coordinates[1]: a coordinate that is not a number"), std::string::npos) << w;
  EXPECT_NE(w.find("features[1].geometry.coordinates[3]: a position with fewer than 2 numbers"), std::string::npos)
      << w;
  EXPECT_NE(w.find("features[1].geometry.coordinates[4]: a position out of range"), std::string::npos) << w;
  auto strict = read(text, ReadOptions{.strict = true});
  ASSERT_FALSE(strict.ok());
  EXPECT_NE(strict.error->message.find("not a number"), std::string::npos);
}

TEST(GeoJsonReader, SyntaxErrorsNameLineAndColumn) {
  auto r = read("{\n  \"type\": \"FeatureCollection\",\n  \"features\": [ x ]\n}");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->position.line, 3);
  EXPECT_EQ(r.error->position.column, 17);
  EXPECT_EQ(r.error->position.byte_offset, 49);
  EXPECT_NE(r.error->to_string().find("test.geojson:3:17: invalid JSON: syntax error"), std::string::npos)
      << r.error->to_string();
}

TEST(GeoJsonReader, LineAndColumnAreRightFarIntoABigFile) {
  // Far past the reader's 64 KiB chunks: the line count carries over from chunk to chunk.
  std::string text = "{\"type\":\"FeatureCollection\",\"features\":[\n";
  for (int i = 0; i < 20000; ++i) text += feature(R"({"type":"Point","coordinates":[1,2]})") + ",\n";
  text += "  {\"type\": tru }]}";
  auto r = read(text);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->position.line, 20002);
  EXPECT_EQ(r.error->position.column, 15);
  EXPECT_EQ(r.error->position.byte_offset, static_cast<std::int64_t>(text.size()) - 4);
}

TEST(GeoJsonReader, NotGeoJsonIsAnError) {
  for (const char* text : {"[1,2,3]", "{}", R"({"type":"Topology","objects":{}})", "{\"type\":"}) {
    auto r = read(text);
    if (std::string(text) == "{\"type\":") {
      EXPECT_TRUE(r.ok()) << text;  // cut: nothing read, a warning
      EXPECT_TRUE(r.file.tracks.empty());
      continue;
    }
    ASSERT_FALSE(r.ok()) << text;
    EXPECT_NE(r.error->message.find("not GeoJSON"), std::string::npos) << r.error->message;
  }
  auto invalid_utf8 = read("{\"type\":\"Feature\",\"properties\":{\"name\":\"\xE9t\xE9\"},\"geometry\":null}");
  ASSERT_FALSE(invalid_utf8.ok());
  EXPECT_NE(invalid_utf8.error->message.find("invalid JSON"), std::string::npos);
}

TEST(GeoJsonReader, ACutFileKeepsThePointsCompleteBeforeTheCut) {
  std::string text = R"({"type":"FeatureCollection","features":[)" +
                     feature(R"({"type":"LineString","coordinates":[[1,1],[2,2]]})") + "," +
                     feature(R"({"type":"LineString","coordinates":[[3,3],[4,4],[5,5],[6,6]]})",
                             R"({"coordTimes":["2020-01-01T00:00:00Z","2020-01-01T00:00:01Z",
                                 "2020-01-01T00:00:02Z","2020-01-01T00:00:03Z"]})") +
                     "]}";
  const std::size_t cut_at = text.find("[5,5]") + 3;  // inside the third position
  auto r = read(text.substr(0, cut_at));
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  ASSERT_EQ(r.file.tracks.size(), 2u);
  const auto& p = r.file.tracks[1].segments.at(0).points;
  ASSERT_EQ(p.size(), 2u);
  EXPECT_DOUBLE_EQ(p[1].lon, 4.0);
  EXPECT_DOUBLE_EQ(p[1].time - p[0].time, 1.0);  // times before the cut are placed
  EXPECT_TRUE(any_warning_contains(r, "cut off")) << warnings_of(r);
  EXPECT_TRUE(any_warning_contains(r, "kept the 4 complete points")) << warnings_of(r);
  EXPECT_FALSE(read(text.substr(0, cut_at), ReadOptions{.strict = true}).ok());
}

TEST(GeoJsonReader, EveryCutOfADocumentReadsWithoutError) {
  const std::string text =
      collection(feature(R"({"type":"MultiLineString","coordinates":[[[1,2,3],[1.1,2.1,3]],[[5,6],[5.1,6.1]]]})",
                         R"({"name":"n","coordinateProperties":{"times":[["2020-01-01T00:00:00Z",null],
                            [null,"2020-01-01T00:00:03Z"]],"heart":[[1,2],[3,4]]}})") +
                 "," + feature(R"({"type":"Point","coordinates":[1,2]})", R"({"name":"w"})"));
  std::size_t previous = 0;
  for (std::size_t n = 1; n < text.size(); ++n) {
    auto r = read(text.substr(0, n));
    ASSERT_TRUE(r.ok()) << n << ": " << r.error->to_string();
    std::size_t points = r.file.waypoints.size();
    for (const auto& t : r.file.tracks) points += t.point_count();
    EXPECT_GE(points, previous) << "a longer prefix lost points at " << n;
    previous = points;
  }
  EXPECT_EQ(previous, 5u);
}

TEST(GeoJsonReader, CorruptedBytesNeverCrashAndKeepOnlyValidPoints) {
  const std::string text =
      collection(feature(R"({"type":"LineString","coordinates":[[1,2,3],[1.1,2.1,3],[1.2,2.2]]})",
                         R"({"coordTimes":["2020-01-01T00:00:00Z","2020-01-01T00:00:01Z","2020-01-01T00:00:02Z"]})") +
                 "," + feature(R"({"type":"Point","coordinates":[1,2]})", R"({"name":"w"})"));
  unsigned seed = 12345;
  auto next = [&seed] { return seed = seed * 1103515245u + 12345u, (seed >> 16) & 0x7fff; };
  const char replacements[] = {'[', ']', '{', '}', ',', ':', '"', '9', '-', 'e', '.', 'n', '\0', '\xff'};
  int errors = 0, read_ok = 0;
  for (int i = 0; i < 500; ++i) {
    std::string t = text;
    for (int k = 0; k < 3; ++k) t[next() % t.size()] = replacements[next() % sizeof replacements];
    auto r = read(t);
    if (!r.ok()) {
      ++errors;
      EXPECT_FALSE(r.error->message.empty());
      continue;
    }
    ++read_ok;
    for (const auto& tr : r.file.tracks)
      for (const auto& s : tr.segments)
        for (const auto& p : s.points) EXPECT_TRUE(valid_coordinates(p.lat, p.lon));
  }
  EXPECT_GT(errors, 0);
  EXPECT_GT(read_ok, 0);
}

TEST(GeoJsonReader, DeepNestingIsNotAProblem) {
  std::string deep(100000, '[');
  auto r = read(R"({"type":"Feature","properties":{"x":)" + deep + "}");
  EXPECT_FALSE(r.ok());  // cut after the nesting: a syntax error or a cut, never a crash
  auto r2 = read(R"({"type":"LineString","coordinates":)" + deep + std::string(100000, ']') + "}");
  EXPECT_TRUE(r2.ok());
  EXPECT_TRUE(r2.file.tracks.empty());
}
