// The KML reader on synthetic documents, one construct each.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "track/io/byte_source.hpp"
#include "track/io/readers.hpp"

using namespace trailray::track;

namespace {

ReadResult read(const std::string& xml, ReadOptions options = {}) {
  auto src = ByteSource::from_memory(xml, "test.kml");
  return read_kml(*src, options);
}

std::string kml(const std::string& body) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<kml xmlns=\"http://www.opengis.net/kml/2.2\" xmlns:gx=\"http://www.google.com/kml/ext/2.2\">\n"
         "<Document>\n" +
         body + "</Document>\n</kml>\n";
}

const Diagnostic* warning_containing(const ReadResult& r, const std::string& needle) {
  for (const auto& w : r.warnings)
    if (w.message.find(needle) != std::string::npos) return &w;
  return nullptr;
}

const std::string kGxTrack =
    "<Placemark><name>Ride</name><gx:Track><altitudeMode>absolute</altitudeMode>\n"
    "<when>2020-01-01T10:00:00Z</when><when>2020-01-01T13:00:05+03:00</when><when>2020-01-01T10:00:10Z</when>\n"
    "<gx:coord>8.1 47.1 500</gx:coord><gx:coord>8.2 47.2 510.5</gx:coord><gx:coord>8.3 47.3 520</gx:coord>\n"
    "<ExtendedData><SchemaData schemaUrl=\"#s\">\n"
    "<gx:SimpleArrayData name=\"HeartRate\"><gx:value>120</gx:value><gx:value>121</gx:value>"
    "<gx:value>122</gx:value></gx:SimpleArrayData>\n"
    "<gx:SimpleArrayData name=\"cadence\"><gx:value>80</gx:value><gx:value/><gx:value>82</gx:value>"
    "</gx:SimpleArrayData>\n"
    "<gx:SimpleArrayData name=\"power\"><gx:value>200</gx:value><gx:value>210</gx:value><gx:value>220</gx:value>"
    "</gx:SimpleArrayData>\n"
    "<gx:SimpleArrayData name=\"speed_of_wind\"><gx:value>3</gx:value><gx:value>3</gx:value><gx:value>3</gx:value>"
    "</gx:SimpleArrayData>\n"
    "</SchemaData></ExtendedData></gx:Track></Placemark>\n";

}  // namespace

TEST(KmlReader, GxTrackPairsTimesPositionsAndChannelsByIndex) {
  ReadResult r = read(kml("<name>My day</name><description>about it</description>\n" + kGxTrack));
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(r.file.format, Format::Kml);
  EXPECT_EQ(r.file.metadata.name, "My day");
  EXPECT_EQ(r.file.metadata.description, "about it");
  ASSERT_EQ(r.file.tracks.size(), 1u);
  const Track& t = r.file.tracks[0];
  EXPECT_EQ(t.name, "Ride");
  ASSERT_EQ(t.segments.size(), 1u);
  const auto& p = t.segments[0].points;
  ASSERT_EQ(p.size(), 3u);
  EXPECT_DOUBLE_EQ(p[0].lon, 8.1);
  EXPECT_DOUBLE_EQ(p[0].lat, 47.1);
  EXPECT_DOUBLE_EQ(p[1].ele, 510.5);
  EXPECT_DOUBLE_EQ(p[0].time, 1577872800.0);
  EXPECT_DOUBLE_EQ(p[1].time, 1577872805.0);  // +03:00 offset
  EXPECT_DOUBLE_EQ(p[2].time, 1577872810.0);
  EXPECT_FLOAT_EQ(p[0].heart_rate, 120.0f);  // "HeartRate": matched without case
  EXPECT_FLOAT_EQ(p[2].heart_rate, 122.0f);
  EXPECT_FLOAT_EQ(p[0].cadence, 80.0f);
  EXPECT_TRUE(std::isnan(p[1].cadence));  // empty gx:value
  EXPECT_FLOAT_EQ(p[1].power, 210.0f);
  EXPECT_TRUE(std::isnan(p[0].temperature));
  EXPECT_TRUE(std::isnan(p[0].speed));  // an unknown array is not a channel
}

TEST(KmlReader, GxTrackWithMismatchedListsIsWarnedAndPairedByOrder) {
  ReadResult r =
      read(kml("<Placemark><gx:Track><when>2020-01-01T10:00:00Z</when>"
               "<gx:coord>8.1 47.1 1</gx:coord><gx:coord>8.2 47.2 1</gx:coord></gx:Track></Placemark>"));
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.tracks.size(), 1u);
  const auto& p = r.file.tracks[0].segments[0].points;
  ASSERT_EQ(p.size(), 2u);
  EXPECT_DOUBLE_EQ(p[0].time, 1577872800.0);
  EXPECT_TRUE(std::isnan(p[1].time));
  EXPECT_NE(warning_containing(r, "1 <when> and 2 <gx:coord>"), nullptr);
}

TEST(KmlReader, MultiTrackIsOneTrackWithASegmentPerGxTrack) {
  ReadResult r = read(
      kml("<Placemark><name>Run</name><ExtendedData><Data name=\"type\"><value>running</value></Data></ExtendedData>\n"
          "<gx:MultiTrack><altitudeMode>absolute</altitudeMode>\n"
          "<gx:Track><when>2020-01-01T10:00:00Z</when><gx:coord>8.1 47.1 100</gx:coord>"
          "<when>2020-01-01T10:00:01Z</when><gx:coord>8.2 47.2 101</gx:coord></gx:Track>\n"
          "<gx:Track><altitudeMode>clampToGround</altitudeMode><when>2020-01-01T11:00:00Z</when>"
          "<gx:coord>8.3 47.3 102</gx:coord></gx:Track>\n"
          "</gx:MultiTrack></Placemark>"));
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.tracks.size(), 1u);
  const Track& t = r.file.tracks[0];
  EXPECT_EQ(t.name, "Run");
  EXPECT_EQ(t.type, "running");
  ASSERT_EQ(t.segments.size(), 2u);
  ASSERT_EQ(t.segments[0].points.size(), 2u);
  EXPECT_DOUBLE_EQ(t.segments[0].points[1].ele, 101.0);  // the MultiTrack's absolute
  ASSERT_EQ(t.segments[1].points.size(), 1u);
  EXPECT_FALSE(t.segments[1].points[0].has_ele());  // its own clampToGround wins
  EXPECT_DOUBLE_EQ(t.segments[1].points[0].time, 1577876400.0);
}

TEST(KmlReader, LineStringTuplesWithAndWithoutAltitude) {
  ReadResult r = read(kml(
      "<Placemark><name>Line</name><LineString><altitudeMode>absolute</altitudeMode><coordinates>\n"
      "  8.1,47.1,500 8.2,47.2\n\t+008.3000,+47.300,520.25\n 8.4, 47.4, 530\n</coordinates></LineString></Placemark>"));
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.warnings.empty());
  ASSERT_EQ(r.file.tracks.size(), 1u);
  const auto& p = r.file.tracks[0].segments[0].points;
  ASSERT_EQ(p.size(), 4u);
  EXPECT_DOUBLE_EQ(p[0].ele, 500.0);
  EXPECT_FALSE(p[1].has_ele());
  EXPECT_DOUBLE_EQ(p[2].lon, 8.3);
  EXPECT_DOUBLE_EQ(p[2].ele, 520.25);
  EXPECT_DOUBLE_EQ(p[3].lat, 47.4);  // spaces after the commas: still one tuple
  EXPECT_FALSE(p[0].has_time());
}

TEST(KmlReader, MultiGeometryLinesAreSegmentsAndItsPointsWaypoints) {
  ReadResult r =
      read(kml("<Placemark><name>Both</name><description>d</description><MultiGeometry>\n"
               "<LineString><coordinates>8.1,47.1 8.2,47.2</coordinates></LineString>\n"
               "<Point><coordinates>8.15,47.15</coordinates></Point>\n"
               "<LineString><coordinates>8.3,47.3 8.4,47.4 8.5,47.5</coordinates></LineString>\n"
               "<Polygon><outerBoundaryIs><LinearRing><coordinates>1,1 2,2 3,1 1,1</coordinates></LinearRing>"
               "</outerBoundaryIs></Polygon>\n"
               "</MultiGeometry></Placemark>"));
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.tracks.size(), 1u);
  ASSERT_EQ(r.file.tracks[0].segments.size(), 2u);  // the polygon is an area, not a track
  EXPECT_EQ(r.file.tracks[0].segments[0].points.size(), 2u);
  EXPECT_EQ(r.file.tracks[0].segments[1].points.size(), 3u);
  ASSERT_EQ(r.file.waypoints.size(), 1u);
  EXPECT_EQ(r.file.waypoints[0].name, "Both");
  EXPECT_EQ(r.file.waypoints[0].description, "d");
  EXPECT_DOUBLE_EQ(r.file.waypoints[0].point.lon, 8.15);
  // The area is left out saying so, with where it is (as the GeoJSON reader does).
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].message.find("<Polygon> skipped"), std::string::npos) << r.warnings[0].message;
  EXPECT_EQ(r.warnings[0].position.line, 3 + 5);  // kml() adds three lines before the placemark
}

TEST(KmlReader, NestedFoldersAndDocumentsAreReadInOrder) {
  ReadResult r =
      read(kml("<name>Top</name><Folder><name>Inner</name><Document><Folder>\n"
               "<Placemark><name>A</name><LineString><coordinates>1,1 2,2</coordinates></LineString>"
               "</Placemark>\n</Folder></Document>\n"
               "<Placemark><name>B</name><LineString><coordinates>3,3 4,4</coordinates></LineString>"
               "</Placemark></Folder>\n"
               "<Placemark><name>C</name><Point><coordinates>5,5</coordinates></Point></Placemark>\n"));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.file.metadata.name, "Top");  // the Document under <kml>, not the folders inside
  ASSERT_EQ(r.file.tracks.size(), 2u);
  EXPECT_EQ(r.file.tracks[0].name, "A");
  EXPECT_EQ(r.file.tracks[1].name, "B");
  ASSERT_EQ(r.file.waypoints.size(), 1u);
  EXPECT_EQ(r.file.waypoints[0].name, "C");
}

TEST(KmlReader, PointKeepsItsTimeStamp) {
  ReadResult r =
      read(kml("<Placemark><name>Summit</name><TimeStamp><when>2015-07-27T20:08:36+03:00</when>"
               "</TimeStamp><Point><altitudeMode>absolute</altitudeMode>"
               "<coordinates>40.44,56.41,138.5</coordinates></Point></Placemark>\n"
               "<Placemark><name>Untimed</name><Point><coordinates>40.5,56.5,0</coordinates></Point>"
               "</Placemark>"));
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.waypoints.size(), 2u);
  EXPECT_DOUBLE_EQ(r.file.waypoints[0].point.time, 1438016916.0);  // 17:08:36Z
  EXPECT_DOUBLE_EQ(r.file.waypoints[0].point.ele, 138.5);
  EXPECT_FALSE(r.file.waypoints[1].point.has_time());
  EXPECT_FALSE(r.file.waypoints[1].point.has_ele());  // clampToGround by default
}

TEST(KmlReader, AltitudeModes) {
  auto ele_with = [](const std::string& mode_element) {
    ReadResult r = read(kml("<Placemark><LineString>" + mode_element +
                            "<coordinates>8.1,47.1,500 8.2,47.2,510</coordinates></LineString></Placemark>"));
    EXPECT_TRUE(r.ok());
    return r;
  };
  ReadResult absent = ele_with("");
  EXPECT_FALSE(absent.file.tracks[0].segments[0].points[0].has_ele());  // KML's default clampToGround
  EXPECT_TRUE(absent.warnings.empty());
  EXPECT_FALSE(ele_with("<altitudeMode>clampToGround</altitudeMode>").file.tracks[0].segments[0].points[1].has_ele());
  EXPECT_FALSE(
      ele_with("<gx:altitudeMode>clampToSeaFloor</gx:altitudeMode>").file.tracks[0].segments[0].points[1].has_ele());
  EXPECT_DOUBLE_EQ(ele_with(" <altitudeMode> absolute </altitudeMode>").file.tracks[0].segments[0].points[1].ele,
                   510.0);

  ReadResult relative = ele_with("<altitudeMode>relativeToGround</altitudeMode>");
  EXPECT_FALSE(relative.file.tracks[0].segments[0].points[0].has_ele());
  const Diagnostic* w = warning_containing(relative, "relative to the ground");
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->position.line, 4);  // the altitudeMode element
  ReadResult sea = ele_with("<gx:altitudeMode>relativeToSeaFloor</gx:altitudeMode>");
  EXPECT_NE(warning_containing(sea, "relative to the ground"), nullptr);

  ReadResult unknown = ele_with("<altitudeMode>onTheMoon</altitudeMode>");
  EXPECT_FALSE(unknown.file.tracks[0].segments[0].points[0].has_ele());
  EXPECT_NE(warning_containing(unknown, "unknown altitudeMode 'onTheMoon'"), nullptr);

  // After the coordinates, where the schema does not put it, it still applies.
  ReadResult after =
      read(kml("<Placemark><LineString><coordinates>8.1,47.1,500</coordinates>"
               "<altitudeMode>absolute</altitudeMode></LineString></Placemark>"));
  EXPECT_DOUBLE_EQ(after.file.tracks[0].segments[0].points[0].ele, 500.0);
}

TEST(KmlReader, BadCoordinatesAreDroppedWithOneCountedWarningNamingTheLine) {
  ReadResult r =
      read(kml("<Placemark><LineString><altitudeMode>absolute</altitudeMode><coordinates>\n"
               "8.1,47.1,1\n"
               "8.2,91,1\n"    // latitude out of range
               "abc,47.3,1\n"  // not a number
               "8.4\n"         // one component
               "1,2,3,4\n"     // four
               "8.5,47.5,1\n"
               "</coordinates></LineString></Placemark>\n"
               "<Placemark><gx:Track><when>2020-01-01T10:00:00Z</when><when>2020-01-01T10:00:01Z</when>"
               "<gx:coord>200 47 1</gx:coord><gx:coord>8 47 1</gx:coord></gx:Track></Placemark>"));
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.tracks.size(), 2u);
  EXPECT_EQ(r.file.tracks[0].segments[0].points.size(), 2u);
  ASSERT_EQ(r.file.tracks[1].segments[0].points.size(), 1u);
  EXPECT_DOUBLE_EQ(r.file.tracks[1].segments[0].points[0].time, 1577872801.0);  // the time of its own index
  ASSERT_EQ(r.warnings.size(), 1u);
  const Diagnostic& w = r.warnings[0];
  EXPECT_NE(w.message.find("'8.2,91,1'"), std::string::npos) << w.message;
  EXPECT_NE(w.message.find("5 times"), std::string::npos) << w.message;  // counted, not repeated
  EXPECT_EQ(w.position.line, 6);
  EXPECT_EQ(w.position.column, 1);
}

TEST(KmlReader, UnreadableTimesAndValuesAreWarned) {
  ReadResult r =
      read(kml("<Placemark><gx:Track><when>yesterday</when><gx:coord>8 47 1</gx:coord>"
               "<ExtendedData><SchemaData><gx:SimpleArrayData name=\"hr\"><gx:value>fast</gx:value>"
               "</gx:SimpleArrayData></SchemaData></ExtendedData></gx:Track></Placemark>"));
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.tracks.size(), 1u);
  EXPECT_FALSE(r.file.tracks[0].segments[0].points[0].has_time());
  EXPECT_TRUE(std::isnan(r.file.tracks[0].segments[0].points[0].heart_rate));
  EXPECT_NE(warning_containing(r, "unreadable <when> 'yesterday'"), nullptr);
  EXPECT_NE(warning_containing(r, "unreadable <gx:value> 'fast'"), nullptr);
}

TEST(KmlReader, PrefixedKml21AndCdataNamesRead) {
  ReadResult r = read(
      "<ns3:kml xmlns:ns3=\"http://earth.google.com/kml/2.1\"><ns3:Document><ns3:name><![CDATA[\n Trip & co ]]>"
      "</ns3:name><ns3:Placemark><ns3:name>P &amp; Q</ns3:name><ns3:Point><ns3:coordinates>1.5,2.5,0"
      "</ns3:coordinates></ns3:Point></ns3:Placemark></ns3:Document></ns3:kml>");
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_EQ(r.file.metadata.name, "Trip & co");
  ASSERT_EQ(r.file.waypoints.size(), 1u);
  EXPECT_EQ(r.file.waypoints[0].name, "P & Q");
}

TEST(KmlReader, Utf16DocumentIsRead) {
  const std::string utf8 =
      kml("<Placemark><name>Zürich</name><Point><coordinates>8.5,47.4</coordinates></Point>"
          "</Placemark>");
  std::string utf16 = "\xFF\xFE";
  for (std::size_t i = 0; i < utf8.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(utf8[i]);
    char32_t cp = c;
    if (c >= 0xC0) cp = ((c & 0x1F) << 6) | (static_cast<unsigned char>(utf8[++i]) & 0x3F);  // 2-byte only here
    utf16.push_back(static_cast<char>(cp & 0xFF));
    utf16.push_back(static_cast<char>(cp >> 8));
  }
  ReadResult r = read(utf16);
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  ASSERT_EQ(r.file.waypoints.size(), 1u);
  EXPECT_EQ(r.file.waypoints[0].name, "Zürich");
}

TEST(KmlReader, NetworkLinksAreNotFollowedAndSaySo) {
  ReadResult r = read(kml("<NetworkLink><Link><href>http://example.com/a.kml</href></Link></NetworkLink>"));
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.file.tracks.empty());
  EXPECT_NE(warning_containing(r, "NetworkLink"), nullptr);
}

TEST(KmlReader, CutFileKeepsCompletePointsWithAWarning) {
  const std::string full = kml(kGxTrack);
  const std::string cut = full.substr(0, full.find("<gx:coord>8.3"));
  ReadResult r = read(cut);
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  ASSERT_EQ(r.file.tracks.size(), 1u);
  EXPECT_EQ(r.file.tracks[0].segments[0].points.size(), 2u);
  EXPECT_NE(warning_containing(r, "kept the 2 complete points"), nullptr);
  // Cut inside a LineString's coordinates: the tuples before the last are complete (the last
  // might have gone on: "2,2" could have been "2,2,5").
  const std::string line =
      kml("<Placemark><LineString><coordinates>1,1 2,2 3,3</coordinates></LineString></Placemark>");
  ReadResult r2 = read(line.substr(0, line.find("3,3")));
  ASSERT_TRUE(r2.ok());
  ASSERT_EQ(r2.file.tracks.size(), 1u);
  EXPECT_EQ(r2.file.tracks[0].point_count(), 1u);
  ReadOptions strict;
  strict.strict = true;
  EXPECT_FALSE(read(cut, strict).ok());
}

TEST(KmlReader, ErrorsNameLineAndColumn) {
  ReadResult r = read("<kml>\n<Document>\n  <Placemark></Document>\n</kml>\n");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->file, "test.kml");
  EXPECT_EQ(r.error->position.line, 3);
  EXPECT_EQ(r.error->position.column, 16);  // the name in </Document>
  EXPECT_NE(r.error->message.find("mismatched tag"), std::string::npos);

  ReadResult wrong_root = read("<gpx><trk/></gpx>");
  ASSERT_FALSE(wrong_root.ok());
  EXPECT_NE(wrong_root.error->message.find("expected <kml>"), std::string::npos);
}

TEST(KmlReader, LineStringLongerThanTheScannersValueLimitIsReadWhole) {
  // 200,000 tuples (about 5 MB of text, past the 1 MiB the scanner holds as one value), with a
  // bad one near the end whose line is still named.
  std::string coordinates = "\n";
  for (int i = 0; i < 200000; ++i) {
    if (i == 199990) coordinates += "8.5,95.0,1\n";
    coordinates += std::to_string(8.0 + i * 1e-6) + "," + std::to_string(47.0 + i * 1e-6) + "," +
                   std::to_string(500 + i % 100) + "\n";
  }
  const std::string doc =
      kml("<Placemark><LineString><altitudeMode>absolute</altitudeMode>"
          "<coordinates>" +
          coordinates + "</coordinates></LineString></Placemark>");
  ASSERT_GT(doc.size(), 4u << 20);
  ReadResult r = read(doc);
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  ASSERT_EQ(r.file.tracks.size(), 1u);
  const auto& p = r.file.tracks[0].segments[0].points;
  ASSERT_EQ(p.size(), 200000u);
  EXPECT_NEAR(p[123456].lon, 8.123456, 1e-9);
  EXPECT_DOUBLE_EQ(p[123456].ele, 556.0);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].position.line, 4 + 199990 + 1);  // the document's 4th line holds <coordinates>
  EXPECT_EQ(r.warnings[0].position.column, 1);
}

// A source that gives a few bytes per read, so the scanner's buffer ends everywhere: inside
// names, numbers and character references.
class TrickleSource final : public ByteSource {
 public:
  TrickleSource(std::string data, std::size_t step)
      : ByteSource("test.kml", "test.kml"), data_(std::move(data)), step_(step) {}
  std::ptrdiff_t read(char* out, std::size_t max) override {
    const std::size_t n = std::min({max, step_, data_.size() - at_});
    data_.copy(out, n, at_);
    at_ += n;
    return static_cast<std::ptrdiff_t>(n);
  }
  std::string error() const override { return {}; }

 private:
  std::string data_;
  std::size_t step_, at_ = 0;
};

TEST(KmlReader, ReadsAlikeWhateverChunksTheInputComesIn) {
  const std::string doc = kml("<name>A &amp; B &#x263A; &lt;&gt;</name>\n" + kGxTrack +
                              "<Placemark><name>Line &quot;1&quot;</name><LineString><coordinates>"
                              "8.1,47.1&#32;8.2,47.2&#x0A;8.3,47.3 bad,1 <![CDATA[8.4,47.4]]> 8.5,47.5"
                              "</coordinates></LineString></Placemark>");
  const ReadResult whole = read(doc);
  ASSERT_TRUE(whole.ok()) << whole.error->to_string();
  EXPECT_EQ(whole.file.metadata.name, "A & B \u263A <>");
  ASSERT_EQ(whole.file.tracks.size(), 2u);
  EXPECT_EQ(whole.file.tracks[1].name, "Line \"1\"");
  EXPECT_EQ(whole.file.tracks[1].point_count(), 5u);
  ASSERT_EQ(whole.warnings.size(), 1u);
  for (std::size_t step = 1; step <= 9; ++step) {
    TrickleSource src(doc, step);
    const ReadResult r = read_kml(src, {});
    ASSERT_TRUE(r.ok()) << step << ": " << r.error->to_string();
    EXPECT_EQ(r.file.metadata.name, whole.file.metadata.name) << step;
    ASSERT_EQ(r.file.tracks.size(), 2u) << step;
    EXPECT_EQ(r.file.tracks[1].name, whole.file.tracks[1].name) << step;
    for (std::size_t t = 0; t < 2; ++t) {
      const auto& a = r.file.tracks[t].segments[0].points;
      const auto& b = whole.file.tracks[t].segments[0].points;
      ASSERT_EQ(a.size(), b.size()) << step;
      for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].lon, b[i].lon) << step;
        EXPECT_EQ(a[i].lat, b[i].lat) << step;
      }
    }
    ASSERT_EQ(r.warnings.size(), 1u) << step;
    EXPECT_EQ(r.warnings[0].position.line, whole.warnings[0].position.line) << step;
  }
}
