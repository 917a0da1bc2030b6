#include <gtest/gtest.h>

#include <zlib.h>

#include <string>

#include "test_support.hpp"
#include "track/io/load.hpp"
#include "track/io/readers.hpp"

using namespace trailray::track;

namespace {

ReadResult read(const std::string& xml, ReadOptions options = {}) {
  auto src = ByteSource::from_memory(xml, "test.gpx");
  return read_gpx(*src, options);
}

const char* kGarmin = R"(<?xml version="1.0" encoding="UTF-8"?>
<gpx creator="Garmin Connect" version="1.1" xmlns="http://www.topografix.com/GPX/1/1"
     xmlns:ns3="http://www.garmin.com/xmlschemas/TrackPointExtension/v1">
  <metadata><name>Meta</name><author><name>Not the file name</name></author>
    <time>2023-05-06T09:00:00Z</time></metadata>
  <trk><name>Walk</name><type>hiking</type>
    <trkseg>
      <trkpt lat="48.0775180" lon="16.2823790"><ele>290.2</ele><time>2023-05-06T09:45:34.000Z</time>
        <extensions><ns3:TrackPointExtension><ns3:hr>96</ns3:hr><ns3:cad>80</ns3:cad><ns3:atemp>21.5</ns3:atemp>
        </ns3:TrackPointExtension></extensions></trkpt>
      <trkpt lat="48.0776" lon="16.2824"><ele>291</ele><time>2023-05-06T09:45:35Z</time></trkpt>
    </trkseg>
    <trkseg>
      <trkpt lat="48.0777" lon="16.2825"/>
    </trkseg>
  </trk>
</gpx>)";

}  // namespace

TEST(GpxReader, ReadsGarminTrackWithExtensions) {
  ReadResult r = read(kGarmin);
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_TRUE(r.warnings.empty());
  const TrackFile& f = r.file;
  EXPECT_EQ(f.metadata.creator, "Garmin Connect");
  EXPECT_EQ(f.metadata.name, "Meta");
  EXPECT_EQ(f.metadata.time, 1683363600.0);
  ASSERT_EQ(f.tracks.size(), 1u);
  EXPECT_EQ(f.tracks[0].name, "Walk");
  EXPECT_EQ(f.tracks[0].type, "hiking");
  ASSERT_EQ(f.tracks[0].segments.size(), 2u);
  ASSERT_EQ(f.tracks[0].segments[0].points.size(), 2u);
  const TrackPoint& p = f.tracks[0].segments[0].points[0];
  EXPECT_DOUBLE_EQ(p.lat, 48.0775180);
  EXPECT_DOUBLE_EQ(p.lon, 16.2823790);
  EXPECT_DOUBLE_EQ(p.ele, 290.2);
  EXPECT_DOUBLE_EQ(p.time, 1683366334.0);
  EXPECT_FLOAT_EQ(p.heart_rate, 96.0f);
  EXPECT_FLOAT_EQ(p.cadence, 80.0f);
  EXPECT_FLOAT_EQ(p.temperature, 21.5f);
  EXPECT_TRUE(std::isnan(p.power));
  const TrackPoint& q = f.tracks[0].segments[1].points[0];
  EXPECT_FALSE(q.has_ele());
  EXPECT_FALSE(q.has_time());
}

TEST(GpxReader, NamespacesDefaultPrefixedOrMissingReadAlike) {
  const std::string body = R"(<trk><trkseg><trkpt lat="1" lon="2"><ele>3</ele></trkpt></trkseg></trk>)";
  const std::string prefixed =
      R"(<g:gpx xmlns:g="http://www.topografix.com/GPX/1/0" version="1.0">)" +
      std::string(R"(<g:trk><g:trkseg><g:trkpt lat="1" lon="2"><g:ele>3</g:ele></g:trkpt></g:trkseg></g:trk></g:gpx>)");
  for (const std::string& doc :
       {R"(<gpx xmlns="http://www.topografix.com/GPX/1/1">)" + body + "</gpx>", "<gpx>" + body + "</gpx>", prefixed}) {
    ReadResult r = read(doc);
    ASSERT_TRUE(r.ok()) << doc;
    ASSERT_EQ(r.file.tracks.at(0).segments.at(0).points.size(), 1u) << doc;
    EXPECT_EQ(r.file.tracks[0].segments[0].points[0].ele, 3.0);
  }
}

TEST(GpxReader, Gpx10SpeedAndOtherVendorExtensions) {
  ReadResult r = read(R"(<gpx version="1.0"><trk><trkseg>
    <trkpt lat="1" lon="2"><speed>4.5</speed></trkpt>
    <trkpt lat="1" lon="2"><extensions><gpxdata:hr>120</gpxdata:hr><gpxdata:cadence>90</gpxdata:cadence>
       <gpxdata:temp>3</gpxdata:temp></extensions></trkpt>
    <trkpt lat="1" lon="2"><extensions><power>250</power><gpxtpx:TrackPointExtension><gpxtpx:speed>7</gpxtpx:speed>
       </gpxtpx:TrackPointExtension></extensions></trkpt>
    <trkpt lat="1" lon="2"><extensions><gpxx:TrackPointExtension><gpxx:Temperature>12</gpxx:Temperature>
       </gpxx:TrackPointExtension><heartrate>101</heartrate></extensions></trkpt>
  </trkseg></trk></gpx>)");
  ASSERT_TRUE(r.ok());
  const auto& pts = r.file.tracks[0].segments[0].points;
  ASSERT_EQ(pts.size(), 4u);
  EXPECT_FLOAT_EQ(pts[0].speed, 4.5f);
  EXPECT_FLOAT_EQ(pts[1].heart_rate, 120.0f);
  EXPECT_FLOAT_EQ(pts[1].cadence, 90.0f);
  EXPECT_FLOAT_EQ(pts[1].temperature, 3.0f);
  EXPECT_FLOAT_EQ(pts[2].power, 250.0f);
  EXPECT_FLOAT_EQ(pts[2].speed, 7.0f);
  EXPECT_FLOAT_EQ(pts[3].temperature, 12.0f);
  EXPECT_FLOAT_EQ(pts[3].heart_rate, 101.0f);
}

TEST(GpxReader, RoutesWaypointsAndGpx10Metadata) {
  ReadResult r = read(R"(<gpx version="1.0"><name>Old style</name><desc>d</desc><time>2020-01-01T00:00:00Z</time>
    <wpt lat="46.5" lon="7.5"><ele>2000</ele><name>Top</name><desc>Summit</desc><sym>Summit</sym></wpt>
    <rte><name>R</name><rtept lat="1" lon="1"><name>ignored</name></rtept><rtept lat="2" lon="2"/></rte></gpx>)");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.file.metadata.name, "Old style");
  EXPECT_EQ(r.file.metadata.description, "d");
  EXPECT_EQ(r.file.metadata.time, 1577836800.0);
  ASSERT_EQ(r.file.waypoints.size(), 1u);
  EXPECT_EQ(r.file.waypoints[0].name, "Top");
  EXPECT_EQ(r.file.waypoints[0].description, "Summit");
  EXPECT_EQ(r.file.waypoints[0].symbol, "Summit");
  EXPECT_EQ(r.file.waypoints[0].point.ele, 2000.0);
  ASSERT_EQ(r.file.routes.size(), 1u);
  EXPECT_EQ(r.file.routes[0].name, "R");
  EXPECT_EQ(r.file.routes[0].points.size(), 2u);
  EXPECT_TRUE(r.file.tracks.empty());
}

TEST(GpxReader, CdataEntitiesCommentsBomAndCrlf) {
  std::string doc =
      "\xEF\xBB\xBF<?xml version=\"1.0\"?>\r\n<gpx><!-- c --><trk><name><![CDATA[A & B]]></name>\r\n"
      "<trkseg><trkpt lat=\"1\" lon=\"2\"><!-- inside --><ele>5</ele></trkpt></trkseg></trk>"
      "<trk><name>C &amp; D &#233;</name></trk></gpx>\r\n";
  ReadResult r = read(doc);
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  ASSERT_EQ(r.file.tracks.size(), 2u);
  EXPECT_EQ(r.file.tracks[0].name, "A & B");
  EXPECT_EQ(r.file.tracks[1].name, "C & D \xC3\xA9");
  EXPECT_EQ(r.file.tracks[0].segments[0].points[0].ele, 5.0);
}

TEST(GpxReader, Utf16WithBom) {
  std::string utf8 =
      R"(<?xml version="1.0" encoding="UTF-16"?><gpx><wpt lat="37.5" lon="-122.5"><name>X</name></wpt></gpx>)";
  std::string utf16 = "\xFF\xFE";
  for (char c : utf8) utf16 += std::string{c, '\0'};
  ReadResult r = read(utf16);
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  ASSERT_EQ(r.file.waypoints.size(), 1u);
  EXPECT_EQ(r.file.waypoints[0].point.lon, -122.5);
}

TEST(GpxReader, InvalidCoordinatesAreDroppedWithOneCountedWarning) {
  ReadResult r = read(R"(<gpx><trk><trkseg>
<trkpt lat="1" lon="2"/>
<trkpt lat="NaN" lon="2"/>
<trkpt lat="91" lon="2"/>
<trkpt lat="1" lon="-180.5"/>
<trkpt lon="2"/>
<trkpt lat="1" lon="3"/>
</trkseg></trk></gpx>)");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.file.tracks[0].segments[0].points.size(), 2u);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].position.line, 3);
  EXPECT_NE(r.warnings[0].message.find("4 times"), std::string::npos) << r.warnings[0].message;
  EXPECT_NE(r.warnings[0].to_string().find("test.gpx:3:"), std::string::npos);
}

TEST(GpxReader, UnreadableValuesWarnAndEmptyElevationIsSilentlyAbsent) {
  ReadResult r = read(R"(<gpx><trk><trkseg><trkpt lat="1" lon="2"><ele/><time>soon</time></trkpt>
<trkpt lat="1" lon="2"><ele>high</ele></trkpt></trkseg></trk></gpx>)");
  ASSERT_TRUE(r.ok());
  const auto& pts = r.file.tracks[0].segments[0].points;
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_FALSE(pts[0].has_ele());
  EXPECT_FALSE(pts[0].has_time());
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_NE(r.warnings[0].message.find("<time> 'soon'"), std::string::npos);
  EXPECT_NE(r.warnings[1].message.find("<ele> 'high'"), std::string::npos);
  EXPECT_EQ(r.warnings[1].position.line, 2);
}

TEST(GpxReader, ChannelValueBeyondFloatRangeIsIgnored) {
  ReadResult r = read(
      R"(<gpx><trk><trkseg><trkpt lat="1" lon="2"><extensions><hr>1e300</hr></extensions></trkpt></trkseg></trk></gpx>)");
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(std::isnan(r.file.tracks[0].segments[0].points[0].heart_rate));
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].message.find("absurd <hr>"), std::string::npos);
}

TEST(GpxReader, MalformedXmlNamesLineAndColumn) {
  ReadResult r = read("<gpx>\n<trk>\n  <trkseg></trk>\n</gpx>");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->position.line, 3);
  EXPECT_EQ(r.error->position.column, 13);
  EXPECT_NE(r.error->message.find("mismatched tag"), std::string::npos) << r.error->message;
  EXPECT_EQ(r.error->to_string().rfind("test.gpx:3:13: malformed XML", 0), 0u) << r.error->to_string();
}

TEST(GpxReader, PlainTextIsAnError) {
  ReadResult r = read("Error: no such file\n");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->position.line, 1);
  EXPECT_EQ(r.error->message, "not an XML document: syntax error");
}

TEST(GpxReader, WrongRootIsAnError) {
  ReadResult r = read("<kml><Document/></kml>");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error->message.find("root element is <kml>"), std::string::npos);
}

TEST(GpxReader, TruncatedFileKeepsCompletePointsWithWarning) {
  std::string doc = "<gpx><trk><trkseg>\n";
  for (int i = 0; i < 10; ++i) doc += "<trkpt lat=\"1\" lon=\"" + std::to_string(i) + "\"><ele>1</ele></trkpt>\n";
  doc += "<trkpt lat=\"1\" lon=\"11\"><ele>1";  // battery died here
  ReadResult r = read(doc);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.file.tracks[0].segments[0].points.size(), 10u);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].position.line, 12);
  EXPECT_NE(r.warnings[0].message.find("kept the 10 complete points"), std::string::npos) << r.warnings[0].message;

  ReadOptions strict;
  strict.strict = true;
  ReadResult s = read(doc, strict);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error->message.find("--strict"), std::string::npos);
}

TEST(GpxReader, EntityDeclarationsAreRejected) {
  std::string bomb = R"(<?xml version="1.0"?><!DOCTYPE gpx [<!ENTITY a "aaaaaaaaaa">)";
  char prev = 'a';
  for (char c = 'b'; c <= 'j'; ++c, ++prev)
    bomb += std::string("<!ENTITY ") + c + " \"" + std::string(10, '&').replace(0, 10, "") + [&] {
      std::string s;
      for (int i = 0; i < 10; ++i) s += std::string("&") + prev + ";";
      return s;
    }() + "\">";
  bomb += "]><gpx><trk><name>&j;</name></trk></gpx>";
  ReadResult r = read(bomb);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error->message.find("entity"), std::string::npos) << r.error->message;
}

TEST(GpxReader, DeepNestingIsRejected) {
  std::string doc = "<gpx>";
  for (int i = 0; i < 100000; ++i) doc += "<e>";
  ReadResult r = read(doc);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error->message.find("nested deeper"), std::string::npos) << r.error->message;
}

TEST(GpxReader, HugeAttributeIsRejected) {
  std::string doc =
      "<gpx><trk><trkseg><trkpt lat=\"" + std::string(10 << 20, '1') + "\" lon=\"1\"/></trkseg></trk></gpx>";
  ReadResult r = read(doc);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error->message.find("longer than 1 MiB"), std::string::npos) << r.error->message;
}

TEST(GpxReader, GzipFileAndFormatDetection) {
  const std::string doc =
      "<gpx><trk><trkseg><trkpt lat=\"1\" lon=\"2\"/><trkpt lat=\"1\" lon=\"3\"/></trkseg></trk></gpx>";
  trailray::test::TempFile gz("track.dat");  // misleading name: content decides
  gzFile f = gzopen(gz.str().c_str(), "wb");
  gzwrite(f, doc.data(), static_cast<unsigned>(doc.size()));
  gzclose(f);
  ReadResult r = load_track_file(gz.str());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_EQ(r.file.format, Format::Gpx);
  EXPECT_EQ(r.file.tracks[0].segments[0].points.size(), 2u);
}

TEST(GpxReader, MissingFileAndEmptyFileAreErrors) {
  ReadResult r = load_track_file("/nonexistent/dir/x.gpx");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error->to_string().find("/nonexistent/dir/x.gpx: cannot open"), std::string::npos);
  trailray::test::TempFile empty("empty.gpx");
  ReadResult e = load_track_file(empty.str());
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error->message.find("empty"), std::string::npos);
}

// Every real GPX in shared/data loads (or fails with a clear, positioned error for the one
// that is not XML), with the point counts of MANIFEST.md.
TEST(GpxReaderRealData, PointCountsMatchManifest) {
  TRAILRAY_REQUIRE_DATA(dir, "gpx");
  struct Expect {
    const char* file;
    std::size_t trk, seg, trkpt, rte, rtept, wpt;
  };
  const Expect cases[] = {
      {"alpinemaps_example.gpx", 1, 2, 5, 0, 0, 0},
      {"alpinemaps_husarentempel.gpx", 1, 1, 891, 0, 0, 0},
      {"gpsbabel_basecamp.gpx", 1, 1, 2, 1, 2, 2},
      {"gpsbabel_dg100.gpx", 1, 1, 12027, 0, 0, 0},
      {"gpsbabel_mtk_logger_m241_multiple_tracks.gpx", 6, 6, 14263, 0, 0, 0},
      {"gpsbabel_lowrance-utf16-test.gpx", 0, 0, 0, 0, 0, 1},
      {"gpxpy_cerknicko-jezero.gpx", 8, 8, 296, 0, 0, 7},
      {"gpxpy_gpx1.1_with_all_fields.gpx", 2, 2, 1, 2, 5, 2},
      {"gpxpy_route.gpx", 0, 0, 0, 1, 55, 0},
      {"gpxpy_track_with_speed.gpx", 1, 1, 3, 0, 0, 0},
      {"gpxpy_unicode_with_bom.gpx", 0, 0, 0, 0, 0, 1},
      {"togeojson_blue_hills.gpx", 3, 14, 1243, 0, 0, 46},
      {"togeojson_empty_trk.gpx", 1, 1, 0, 0, 0, 0},
      {"togeojson_osm.gpx", 3, 3, 5000, 0, 0, 0},
      {"gpxstudio_with_tracks_and_segments.gpx", 2, 4, 79, 0, 0, 0},
  };
  for (const Expect& e : cases) {
    ReadResult r = load_track_file((dir / e.file).string());
    ASSERT_TRUE(r.ok()) << e.file << ": " << r.error->to_string();
    std::size_t seg = 0, pts = 0, rtept = 0;
    for (const auto& t : r.file.tracks) {
      seg += t.segments.size();
      pts += t.point_count();
    }
    for (const auto& rt : r.file.routes) rtept += rt.points.size();
    EXPECT_EQ(r.file.tracks.size(), e.trk) << e.file;
    EXPECT_EQ(seg, e.seg) << e.file;
    EXPECT_EQ(pts, e.trkpt) << e.file;
    EXPECT_EQ(r.file.routes.size(), e.rte) << e.file;
    EXPECT_EQ(rtept, e.rtept) << e.file;
    EXPECT_EQ(r.file.waypoints.size(), e.wpt) << e.file;
  }
}

TEST(GpxReaderRealData, HeartRateAndTemperatureExtensions) {
  TRAILRAY_REQUIRE_DATA(dir, "gpx");
  ReadResult hr = load_track_file((dir / "togeojson_run_gpxtpx.gpx").string());
  ASSERT_TRUE(hr.ok());
  std::size_t with_hr = 0;
  for (const auto& p : hr.file.tracks[0].segments[0].points) with_hr += !std::isnan(p.heart_rate);
  EXPECT_EQ(with_hr, 1118u);
  ReadResult t = load_track_file((dir / "gpsbabel_garminconnect.gpx").string());
  ASSERT_TRUE(t.ok());
  const TrackPoint& p = t.file.tracks[0].segments[0].points[0];
  EXPECT_FALSE(std::isnan(p.heart_rate));
  EXPECT_FALSE(std::isnan(p.temperature));
  ReadResult cad = load_track_file((dir / "gpsbabel_gtrnctr_power.gpx").string());
  ASSERT_TRUE(cad.ok());
  std::size_t with_cad = 0;
  for (const auto& q : cad.file.tracks[0].segments[0].points) with_cad += !std::isnan(q.cadence);
  EXPECT_GT(with_cad, 1000u);
}

TEST(GpxReaderRealData, NotXmlGivesPositionedError) {
  TRAILRAY_REQUIRE_DATA(path, "gpx/gpsbabel_trackfilter_discard_err.gpx");
  ReadResult r = load_track_file(path.string());
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->position.line, 1);
  EXPECT_NE(r.error->to_string().find(path.string() + ":1:"), std::string::npos) << r.error->to_string();
}
