// The GeoJSON, CSV and KML writers and their shared text: what they write, and that GeoJSON
// reads back to the same model.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "track/io/byte_source.hpp"
#include "track/io/csv_writer.hpp"
#include "track/io/geojson_writer.hpp"
#include "track/io/kml_writer.hpp"
#include "track/io/readers.hpp"
#include "track/io/text_output.hpp"

using namespace trailray::track;

namespace {

TrackPoint point(double lat, double lon, double ele, double time) {
  TrackPoint p;
  p.lat = lat, p.lon = lon, p.ele = ele, p.time = time;
  return p;
}

// Two tracks (one with two segments and every channel, one without times or heights), a
// route and two waypoints; names that need escaping.
TrackFile sample() {
  TrackFile f;
  f.metadata.name = "Day \"out\"";
  f.metadata.time = 1717236000.0;
  Track t;
  t.name = "Ride, with \\ and \"quotes\"\nand a line";
  t.description = "desc <b>";
  t.type = "cycling";
  Segment a, b;
  for (int i = 0; i < 3; ++i) {
    TrackPoint p = point(46.1234567 + i * 1e-7, 7.7654321 - i * 1e-7, 1000.25 + i, 1717236000.0 + i + 0.125);
    p.heart_rate = 120.0f + static_cast<float>(i);
    p.cadence = 80.0f;
    p.power = 250.5f;
    p.temperature = 21.3f;
    p.speed = 5.25f;
    a.points.push_back(p);
  }
  a.points[1].heart_rate = kMissingF;  // a gap in one channel
  b.points.push_back(point(46.2, 7.8, kMissing, 1717239600.0));
  b.points.push_back(point(46.21, 7.81, 1100.0, kMissing));
  t.segments = {a, Segment{}, b};
  f.tracks.push_back(t);
  Track plain;
  plain.name = "plain \xE9";  // Latin-1 byte: not UTF-8
  plain.segments.push_back({{point(-33.9, 151.2, kMissing, kMissing), point(-33.91, 151.21, kMissing, kMissing)}});
  f.tracks.push_back(plain);
  Route r;
  r.name = "plan";
  r.points = {point(45, 6, kMissing, kMissing), point(45.1, 6.1, 500, kMissing)};
  f.routes.push_back(r);
  Waypoint w;
  w.point = point(46.5, 7.5, 2000, 1717236000.5);
  w.name = "Hut";
  w.description = "beds";
  w.symbol = "Lodge";
  f.waypoints.push_back(w);
  Waypoint v;
  v.point = point(0.5, -0.5, kMissing, kMissing);
  f.waypoints.push_back(v);
  return f;
}

void expect_same_point(const TrackPoint& a, const TrackPoint& b) {
  EXPECT_EQ(a.lat, b.lat);
  EXPECT_EQ(a.lon, b.lon);
  EXPECT_EQ(a.has_ele(), b.has_ele());
  if (a.has_ele()) {
    EXPECT_EQ(a.ele, b.ele);
  }
  EXPECT_EQ(a.has_time(), b.has_time());
  if (a.has_time()) {
    EXPECT_NEAR(a.time, b.time, 5e-4);
  }
  for (auto m : {&TrackPoint::heart_rate, &TrackPoint::cadence, &TrackPoint::power, &TrackPoint::temperature,
                 &TrackPoint::speed}) {
    EXPECT_EQ(std::isnan(a.*m), std::isnan(b.*m));
    if (!std::isnan(a.*m)) {
      EXPECT_EQ(a.*m, b.*m);
    }
  }
}

}  // namespace

TEST(TextOutput, NumbersReadBackExactlyAndTimesToTheMillisecond) {
  for (double v : {46.1234567, -0.0000001, 7.76543219876, 1e-9, 1234.5, 0.1 + 0.2})
    EXPECT_EQ(std::strtod(format_number(v).c_str(), nullptr), v) << format_number(v);
  EXPECT_EQ(format_number(46.7), "46.7");
  EXPECT_EQ(format_number(23.1f), "23.1");
  EXPECT_EQ(format_iso_time(1717236000.0), "2024-06-01T10:00:00Z");
  EXPECT_EQ(format_iso_time(1717236000.25), "2024-06-01T10:00:00.250Z");
  EXPECT_EQ(format_iso_time(1717236059.9996), "2024-06-01T10:01:00Z");  // rounds up into the next second
  EXPECT_EQ(format_iso_time(-0.5), "1969-12-31T23:59:59.500Z");
}

TEST(TextOutput, EscapingAndInvalidUtf8) {
  EXPECT_EQ(json_string("a\"b\\c\n\x01"), "\"a\\\"b\\\\c\\n\\u0001\"");
  EXPECT_EQ(valid_utf8("caf\xC3\xA9"), "caf\xC3\xA9");
  EXPECT_EQ(valid_utf8("caf\xE9!"), "caf\xEF\xBF\xBD!");
  EXPECT_EQ(valid_utf8("\xC0\xAF"), "\xEF\xBF\xBD\xEF\xBF\xBD");  // overlong
  EXPECT_EQ(xml_escape("<a & \"b\">"), "&lt;a &amp; &quot;b&quot;&gt;");
  EXPECT_EQ(csv_field("plain"), "plain");
  EXPECT_EQ(csv_field("a,\"b\""), "\"a,\"\"b\"\"\"");
}

TEST(GeoJsonWriter, ReadsBackToTheSameTracksRoutesAndWaypoints) {
  const TrackFile f = sample();
  std::ostringstream out;
  write_geojson(f, out);
  auto src = ByteSource::from_memory(out.str(), "written.geojson");
  ReadResult r = read_geojson(*src, {});
  ASSERT_TRUE(r.ok()) << r.error->to_string() << "\n" << out.str();
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front().to_string();
  EXPECT_EQ(r.file.metadata.name, f.metadata.name);
  EXPECT_EQ(r.file.metadata.time, f.metadata.time);
  ASSERT_EQ(r.file.tracks.size(), 2u);
  const Track& t = r.file.tracks[0];
  EXPECT_EQ(t.name, f.tracks[0].name);
  EXPECT_EQ(t.description, f.tracks[0].description);
  EXPECT_EQ(t.type, "cycling");
  ASSERT_EQ(t.segments.size(), 2u);  // the empty segment is not written
  ASSERT_EQ(t.segments[0].points.size(), 3u);
  for (int i = 0; i < 3; ++i) expect_same_point(t.segments[0].points[i], f.tracks[0].segments[0].points[i]);
  for (int i = 0; i < 2; ++i) expect_same_point(t.segments[1].points[i], f.tracks[0].segments[2].points[i]);
  EXPECT_EQ(r.file.tracks[1].name, "plain \xEF\xBF\xBD");
  expect_same_point(r.file.tracks[1].segments.at(0).points.at(1), f.tracks[1].segments[0].points[1]);
  ASSERT_EQ(r.file.routes.size(), 1u);
  EXPECT_EQ(r.file.routes[0].name, "plan");
  expect_same_point(r.file.routes[0].points.at(1), f.routes[0].points[1]);
  ASSERT_EQ(r.file.waypoints.size(), 2u);
  EXPECT_EQ(r.file.waypoints[0].name, "Hut");
  EXPECT_EQ(r.file.waypoints[0].description, "beds");
  EXPECT_EQ(r.file.waypoints[0].symbol, "Lodge");
  expect_same_point(r.file.waypoints[0].point, f.waypoints[0].point);
  expect_same_point(r.file.waypoints[1].point, f.waypoints[1].point);
  // togeojson's keys, so that its users read the channels too.
  for (const char* key : {"\"coordinateProperties\"", "\"times\"", "\"heart\"", "\"cads\"", "\"powers\"", "\"atemps\"",
                          "\"speeds\"", "\"_gpxType\":\"rte\"", "\"MultiLineString\""})
    EXPECT_NE(out.str().find(key), std::string::npos) << key;
}

TEST(CsvWriter, HeaderAndOneRowPerPoint) {
  std::ostringstream out;
  write_csv(sample(), out);
  std::istringstream lines(out.str());
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "kind,track,segment,name,lat,lon,ele,time,hr,cad,power,temp,speed");
  std::getline(lines, line);
  EXPECT_EQ(line.substr(0, line.find(",\"")), "track,1,1");
  const std::string s = out.str();
  EXPECT_NE(s.find(",46.1234567,7.7654321,1000.25,2024-06-01T10:00:00.125Z,120,80,250.5,21.3,5.25\n"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("track,1,3,\"Ride"), std::string::npos);  // segment numbers as in the model
  EXPECT_NE(s.find("track,2,1,plain \xEF\xBF\xBD,-33.9,151.2,,,,,,,\n"), std::string::npos) << s;
  EXPECT_NE(s.find("route,1,,plan,45.1,6.1,500,,,,,,\n"), std::string::npos) << s;
  EXPECT_NE(s.find("waypoint,1,,Hut,46.5,7.5,2000,2024-06-01T10:00:00.500Z,,,,,\n"), std::string::npos) << s;
  EXPECT_NE(s.find("waypoint,2,,,0.5,-0.5,,,,,,,\n"), std::string::npos) << s;
  std::size_t rows = 0;
  for (char c : s) rows += c == '\n';
  EXPECT_EQ(rows, 1u + 5 + 1 /* the name's line break, quoted */ * 5 + 2 + 2 + 2);
}

TEST(KmlWriter, GxTracksWithTimesAndChannelArrays) {
  std::ostringstream out;
  write_kml(sample(), out);
  const std::string s = out.str();
  auto count = [&s](const std::string& needle) {
    std::size_t n = 0;
    for (auto at = s.find(needle); at != std::string::npos; at = s.find(needle, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("<gx:MultiTrack>"), 1u);
  EXPECT_EQ(count("<gx:Track>"), 2u);
  EXPECT_EQ(count("<gx:coord>"), 5u);
  EXPECT_EQ(count("<when>"), 4u + 1u);  // 4 timed track points + the waypoint's TimeStamp
  EXPECT_EQ(count("<when/>"), 1u);
  EXPECT_NE(s.find("<gx:coord>7.7654321 46.1234567 1000.25</gx:coord>"), std::string::npos);
  EXPECT_NE(s.find("<when>2024-06-01T10:00:00.125Z</when>"), std::string::npos);
  EXPECT_NE(
      s.find("<gx:SimpleArrayData name=\"heartrate\"><gx:value>120</gx:value><gx:value/><gx:value>122</gx:value>"),
      std::string::npos);
  EXPECT_NE(s.find("<gx:SimpleArrayData name=\"power\"><gx:value>250.5</gx:value>"), std::string::npos);
  EXPECT_EQ(count("<LineString>"), 2u);  // the track without times, and the route
  EXPECT_NE(s.find("<coordinates>151.2,-33.9 151.21,-33.91</coordinates>"), std::string::npos);
  EXPECT_NE(s.find("<value>route</value>"), std::string::npos);
  EXPECT_NE(s.find("<name>Ride, with \\ and &quot;quotes&quot;\nand a line</name>"), std::string::npos);
  EXPECT_NE(s.find("<coordinates>7.5,46.5,2000</coordinates>"), std::string::npos);
  EXPECT_GE(count("<altitudeMode>absolute</altitudeMode>"), 3u);
}
