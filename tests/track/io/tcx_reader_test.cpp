#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "test_support.hpp"
#include "track/io/byte_source.hpp"
#include "track/io/load.hpp"
#include "track/io/readers.hpp"

using namespace trailray::track;

namespace {

ReadResult read(const std::string& xml, ReadOptions options = {}) {
  auto src = ByteSource::from_memory(xml, "test.tcx");
  return read_tcx(*src, options);
}

const std::string kHead =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<TrainingCenterDatabase xmlns=\"http://www.garmin.com/xmlschemas/TrainingCenterDatabase/v2\"\n"
    "  xmlns:ns3=\"http://www.garmin.com/xmlschemas/ActivityExtension/v2\">\n";
const std::string kTail = "</TrainingCenterDatabase>\n";

std::string trackpoint(const std::string& time, const std::string& lat, const std::string& lon,
                       const std::string& extra = "") {
  return "<Trackpoint><Time>" + time + "</Time><Position><LatitudeDegrees>" + lat +
         "</LatitudeDegrees><LongitudeDegrees>" + lon + "</LongitudeDegrees></Position>" + extra + "</Trackpoint>\n";
}

std::string activity(const std::string& sport, const std::string& body) {
  return kHead + "<Activities><Activity Sport=\"" + sport + "\"><Id>2021-06-01T08:00:00Z</Id>\n" + body +
         "</Activity></Activities>\n" + kTail;
}

bool any_warning_contains(const ReadResult& r, const std::string& needle) {
  for (const auto& w : r.warnings)
    if (w.message.find(needle) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(TcxReader, LapsBecomeSegmentsInFileOrder) {
  std::string body = "<Lap StartTime=\"2021-06-01T08:00:00Z\"><TotalTimeSeconds>10</TotalTimeSeconds><Track>\n" +
                     trackpoint("2021-06-01T08:00:00Z", "47.1", "8.1") +
                     trackpoint("2021-06-01T08:00:01Z", "47.2", "8.2") +
                     "</Track></Lap>\n<Lap StartTime=\"2021-06-01T08:10:00Z\"><Track>\n" +
                     trackpoint("2021-06-01T08:10:00Z", "47.3", "8.3") + "</Track></Lap>\n";
  ReadResult r = read(activity("Running", body));
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(r.file.format, Format::Tcx);
  ASSERT_EQ(r.file.tracks.size(), 1u);
  const Track& t = r.file.tracks[0];
  EXPECT_EQ(t.type, "Running");
  EXPECT_EQ(r.file.metadata.activity_type, "Running");
  EXPECT_EQ(r.file.metadata.time, 1622534400.0);  // Id
  ASSERT_EQ(t.segments.size(), 2u);
  ASSERT_EQ(t.segments[0].points.size(), 2u);
  ASSERT_EQ(t.segments[1].points.size(), 1u);
  EXPECT_DOUBLE_EQ(t.segments[0].points[0].lat, 47.1);
  EXPECT_DOUBLE_EQ(t.segments[0].points[1].lon, 8.2);
  EXPECT_DOUBLE_EQ(t.segments[1].points[0].lat, 47.3);
  EXPECT_EQ(t.segments[1].points[0].time, 1622534400.0 + 600.0);
}

TEST(TcxReader, SeveralTracksInOneLapStayInTheLapSegment) {
  std::string body = "<Lap StartTime=\"2021-06-01T08:00:00Z\"><Track>\n" +
                     trackpoint("2021-06-01T08:00:00Z", "47.1", "8.1") + "</Track><Track>\n" +
                     trackpoint("2021-06-01T08:05:00Z", "47.2", "8.2") +
                     trackpoint("2021-06-01T08:05:01Z", "47.3", "8.3") + "</Track></Lap>\n";
  ReadResult r = read(activity("Biking", body));
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.tracks.size(), 1u);
  ASSERT_EQ(r.file.tracks[0].segments.size(), 1u);
  const auto& pts = r.file.tracks[0].segments[0].points;
  ASSERT_EQ(pts.size(), 3u);
  EXPECT_DOUBLE_EQ(pts[0].lat, 47.1);
  EXPECT_DOUBLE_EQ(pts[1].lat, 47.2);
  EXPECT_DOUBLE_EQ(pts[2].lat, 47.3);
}

TEST(TcxReader, RecordedChannels) {
  std::string body =
      "<Lap StartTime=\"2021-06-01T08:00:00Z\"><Track>\n" +
      trackpoint("2021-06-01T08:00:00Z", "47.1", "8.1",
                 "<AltitudeMeters>512.5</AltitudeMeters><DistanceMeters>3.0</DistanceMeters>"
                 "<HeartRateBpm><Value>142</Value></HeartRateBpm><Cadence>88</Cadence>"
                 "<Extensions><ns3:TPX><ns3:Speed>7.25</ns3:Speed><ns3:Watts>231</ns3:Watts></ns3:TPX>"
                 "</Extensions>") +
      // ax: prefix (other writers), RunCadence in the extension, no <Cadence>.
      trackpoint("2021-06-01T08:00:01Z", "47.2", "8.2",
                 "<Extensions><ax:TPX xmlns:ax=\"http://www.garmin.com/xmlschemas/ActivityExtension/v2\">"
                 "<ax:Speed>3.5</ax:Speed><ax:RunCadence>84</ax:RunCadence></ax:TPX></Extensions>") +
      // Nothing but the position.
      trackpoint("2021-06-01T08:00:02Z", "47.3", "8.3") + "</Track></Lap>\n";
  ReadResult r = read(activity("Biking", body));
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.warnings.empty());
  const auto& pts = r.file.tracks.at(0).segments.at(0).points;
  ASSERT_EQ(pts.size(), 3u);
  EXPECT_DOUBLE_EQ(pts[0].ele, 512.5);
  EXPECT_FLOAT_EQ(pts[0].heart_rate, 142.0f);
  EXPECT_FLOAT_EQ(pts[0].cadence, 88.0f);
  EXPECT_FLOAT_EQ(pts[0].speed, 7.25f);
  EXPECT_FLOAT_EQ(pts[0].power, 231.0f);
  EXPECT_TRUE(std::isnan(pts[0].temperature));

  EXPECT_FLOAT_EQ(pts[1].speed, 3.5f);
  EXPECT_FLOAT_EQ(pts[1].cadence, 84.0f);
  EXPECT_TRUE(std::isnan(pts[1].heart_rate));
  EXPECT_TRUE(std::isnan(pts[1].power));
  EXPECT_FALSE(pts[1].has_ele());

  EXPECT_FALSE(pts[2].has_ele());
  EXPECT_TRUE(std::isnan(pts[2].heart_rate));
  EXPECT_TRUE(std::isnan(pts[2].cadence));
  EXPECT_TRUE(std::isnan(pts[2].speed));
  EXPECT_TRUE(std::isnan(pts[2].power));
}

TEST(TcxReader, LapSummaryValuesAreNotPointValues) {
  // Lap-level MaximumSpeed, AverageHeartRateBpm/Value and LX/AvgSpeed must not leak into points.
  std::string body =
      "<Lap StartTime=\"2021-06-01T08:00:00Z\"><MaximumSpeed>9.5</MaximumSpeed>"
      "<AverageHeartRateBpm><Value>150</Value></AverageHeartRateBpm><Cadence>90</Cadence><Track>\n" +
      trackpoint("2021-06-01T08:00:00Z", "47.1", "8.1") +
      "</Track><Extensions><ns3:LX><ns3:AvgSpeed>5.2</ns3:AvgSpeed></ns3:LX></Extensions></Lap>\n";
  ReadResult r = read(activity("Biking", body));
  ASSERT_TRUE(r.ok());
  const auto& p = r.file.tracks.at(0).segments.at(0).points.at(0);
  EXPECT_TRUE(std::isnan(p.speed));
  EXPECT_TRUE(std::isnan(p.heart_rate));
  EXPECT_TRUE(std::isnan(p.cadence));
}

TEST(TcxReader, TrackpointsWithoutPositionAreSkippedSilently) {
  std::string body = "<Lap StartTime=\"2021-06-01T08:00:00Z\"><Track>\n" +
                     trackpoint("2021-06-01T08:00:00Z", "47.1", "8.1") +
                     "<Trackpoint><Time>2021-06-01T08:00:01Z</Time></Trackpoint>\n"
                     "<Trackpoint><Time>2021-06-01T08:00:02Z</Time><HeartRateBpm><Value>120</Value>"
                     "</HeartRateBpm></Trackpoint>\n" +
                     trackpoint("2021-06-01T08:00:03Z", "47.2", "8.2") + "</Track></Lap>\n";
  ReadResult r = read(activity("Running", body), ReadOptions{.strict = true});
  ASSERT_TRUE(r.ok()) << r.error->to_string();  // not a warning, so not an error under strict
  EXPECT_TRUE(r.warnings.empty());
  const auto& pts = r.file.tracks.at(0).segments.at(0).points;
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_EQ(pts[0].time, 1622534400.0);
  EXPECT_EQ(pts[1].time, 1622534403.0);
}

TEST(TcxReader, LapWithoutPositionedPointsLeavesNoEmptySegment) {
  std::string body = "<Lap StartTime=\"2021-06-01T08:00:00Z\"><Track>\n" +
                     trackpoint("2021-06-01T08:00:00Z", "47.1", "8.1") +
                     "</Track></Lap>\n<Lap StartTime=\"2021-06-01T08:01:00Z\"><Track>"
                     "<Trackpoint><Time>2021-06-01T08:01:00Z</Time></Trackpoint></Track></Lap>\n"
                     "<Lap StartTime=\"2021-06-01T08:02:00Z\"><TotalTimeSeconds>1</TotalTimeSeconds></Lap>\n"
                     "<Lap StartTime=\"2021-06-01T08:03:00Z\"><Track>\n" +
                     trackpoint("2021-06-01T08:03:00Z", "47.3", "8.3") + "</Track></Lap>\n";
  ReadResult r = read(activity("Running", body));
  ASSERT_TRUE(r.ok());
  const Track& t = r.file.tracks.at(0);
  ASSERT_EQ(t.segments.size(), 2u);
  EXPECT_DOUBLE_EQ(t.segments[0].points.at(0).lat, 47.1);
  EXPECT_DOUBLE_EQ(t.segments[1].points.at(0).lat, 47.3);
}

TEST(TcxReader, InvalidCoordinatesAreDroppedWithOneCountedWarning) {
  // Lines 1-3: kHead, line 4: <Activities><Activity><Id>.
  std::string body = "<Lap StartTime=\"2021-06-01T08:00:00Z\"><Track>\n" +  // line 5
                     trackpoint("2021-06-01T08:00:00Z", "47.1", "8.1") +    // line 6
                     trackpoint("2021-06-01T08:00:01Z", "91.5", "8.1") +    // line 7: out of range
                     trackpoint("2021-06-01T08:00:02Z", "47.2", "north") +  // line 8: unparseable
                     "<Trackpoint><Position><LatitudeDegrees>47.3</LatitudeDegrees></Position>"
                     "</Trackpoint>\n" +                                   // line 9: no longitude
                     trackpoint("2021-06-01T08:00:04Z", "47.4", "-181") +  // line 10
                     trackpoint("2021-06-01T08:00:05Z", "47.5", "8.5") +
                     "</Track></Lap>\n";
  ReadResult r = read(activity("Running", body));
  ASSERT_TRUE(r.ok());
  const auto& pts = r.file.tracks.at(0).segments.at(0).points;
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_DOUBLE_EQ(pts[0].lat, 47.1);
  EXPECT_DOUBLE_EQ(pts[1].lat, 47.5);
  ASSERT_EQ(r.warnings.size(), 1u);
  const Diagnostic& w = r.warnings[0];
  EXPECT_EQ(w.file, "test.tcx");
  EXPECT_EQ(w.position.line, 7);  // the first bad <Trackpoint>
  EXPECT_EQ(w.position.column, 1);
  EXPECT_NE(w.message.find("invalid coordinates"), std::string::npos) << w.message;
  EXPECT_NE(w.message.find("91.5"), std::string::npos) << w.message;
  EXPECT_NE(w.message.find("4 times"), std::string::npos) << w.message;

  ReadResult strict = read(activity("Running", body), ReadOptions{.strict = true});
  ASSERT_FALSE(strict.ok());
  EXPECT_EQ(strict.error->position.line, 7);
  EXPECT_NE(strict.error->message.find("--strict"), std::string::npos);
}

TEST(TcxReader, UnreadableValuesAreWarnedAndThePointKept) {
  std::string body = "<Lap StartTime=\"2021-06-01T08:00:00Z\"><Track>\n" +
                     trackpoint("yesterday", "47.1", "8.1",
                                "<AltitudeMeters>high</AltitudeMeters><HeartRateBpm><Value>1e300</Value>"
                                "</HeartRateBpm>") +
                     "</Track></Lap>\n";
  ReadResult r = read(activity("Running", body));
  ASSERT_TRUE(r.ok());
  const auto& p = r.file.tracks.at(0).segments.at(0).points.at(0);
  EXPECT_FALSE(p.has_time());
  EXPECT_FALSE(p.has_ele());
  EXPECT_TRUE(std::isnan(p.heart_rate));  // too large for a float: ignored, not cast
  EXPECT_EQ(r.warnings.size(), 3u);
  EXPECT_TRUE(any_warning_contains(r, "unreadable <Time> 'yesterday'"));
  EXPECT_TRUE(any_warning_contains(r, "unreadable <AltitudeMeters> 'high'"));
  EXPECT_TRUE(any_warning_contains(r, "out-of-range"));
}

TEST(TcxReader, TimesWithFractionsAndOffsets) {
  std::string body = "<Lap StartTime=\"2021-06-01T08:00:00Z\"><Track>\n" +
                     trackpoint("2023-05-06T09:45:34.250Z", "47.1", "8.1") +
                     trackpoint("2023-05-06T11:45:35+02:00", "47.2", "8.2") +
                     trackpoint("2023-05-06T04:15:36.5-05:30", "47.3", "8.3") +
                     trackpoint("2023-05-06T09:45:37.000Z", "47.4", "8.4") + "</Track></Lap>\n";
  ReadResult r = read(activity("Running", body));
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.warnings.empty());
  const auto& pts = r.file.tracks.at(0).segments.at(0).points;
  ASSERT_EQ(pts.size(), 4u);
  EXPECT_NEAR(pts[0].time, 1683366334.25, 1e-6);
  EXPECT_EQ(pts[1].time, 1683366335.0);
  EXPECT_NEAR(pts[2].time, 1683366336.5, 1e-6);
  EXPECT_EQ(pts[3].time, 1683366337.0);
}

TEST(TcxReader, OneTrackPerActivityAndCreator) {
  std::string xml = kHead +
                    "<Activities>\n"
                    "<Activity Sport=\"Running\"><Id>not a time</Id><Lap StartTime=\"x\"><Track>" +
                    trackpoint("2021-06-01T08:00:00Z", "47.1", "8.1") +
                    "</Track></Lap><Creator><Name>Forerunner 965</Name><Version><VersionMajor>1</VersionMajor>"
                    "</Version></Creator></Activity>\n"
                    "<Activity Sport=\"Biking\"><Id>2021-06-02T08:00:00Z</Id><Lap StartTime=\"x\"><Track>" +
                    trackpoint("2021-06-02T08:00:00Z", "47.2", "8.2") +
                    trackpoint("2021-06-02T08:00:01Z", "47.3", "8.3") +
                    "</Track></Lap><Notes>evening ride</Notes></Activity>\n"
                    "</Activities>\n"
                    "<Author><Name>Garmin Connect</Name></Author>\n" +
                    kTail;
  ReadResult r = read(xml);
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.tracks.size(), 2u);
  EXPECT_EQ(r.file.tracks[0].type, "Running");
  EXPECT_EQ(r.file.tracks[1].type, "Biking");
  EXPECT_EQ(r.file.tracks[1].description, "evening ride");
  EXPECT_EQ(r.file.tracks[0].point_count(), 1u);
  EXPECT_EQ(r.file.tracks[1].point_count(), 2u);
  EXPECT_EQ(r.file.metadata.activity_type, "Running");
  EXPECT_EQ(r.file.metadata.time, 1622620800.0);         // the first parseable Id
  EXPECT_EQ(r.file.metadata.creator, "Forerunner 965");  // the device, not the Author
}

TEST(TcxReader, AuthorNameIsTheCreatorWhenNoDeviceIsNamed) {
  std::string xml = activity("Other", "");
  xml.insert(xml.find(kTail), "<Author><Name>Some App</Name></Author>\n");
  ReadResult r = read(xml);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.file.metadata.creator, "Some App");
  ASSERT_EQ(r.file.tracks.size(), 1u);
  EXPECT_TRUE(r.file.tracks[0].segments.empty());
}

TEST(TcxReader, FoldersAndWorkoutsAreIgnored) {
  std::string xml = kHead +
                    "<Folders><Activities><Running><ActivityRef><Id>2021-06-01T08:00:00Z</Id></ActivityRef>"
                    "</Running></Activities><Courses><CourseFolder Name=\"C\"><CourseNameRef><Id>X</Id>"
                    "</CourseNameRef></CourseFolder></Courses></Folders>\n"
                    "<Workouts><Workout Sport=\"Running\"><Name>Intervals</Name></Workout></Workouts>\n" +
                    kTail;
  ReadResult r = read(xml);
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.file.tracks.empty());
  EXPECT_TRUE(r.file.waypoints.empty());
  EXPECT_TRUE(std::isnan(r.file.metadata.time));
}

TEST(TcxReader, CourseWithTracksAndCoursePoints) {
  std::string xml =
      kHead +
      "<Courses><Course><Name>Lake loop</Name>\n"
      "<Lap><TotalTimeSeconds>100</TotalTimeSeconds><BeginPosition><LatitudeDegrees>10</LatitudeDegrees>"
      "<LongitudeDegrees>10</LongitudeDegrees></BeginPosition></Lap>\n"
      "<Track>\n" +
      trackpoint("2008-08-21T13:08:52Z", "34.1", "-118.7",
                 "<AltitudeMeters>308.5</AltitudeMeters><HeartRateBpm><Value>107</Value></HeartRateBpm>") +
      trackpoint("2008-08-21T13:08:54Z", "34.2", "-118.8") +
      "<Trackpoint><Time>2008-08-21T13:08:55Z</Time></Trackpoint></Track>\n"
      "<Track>\n" +
      trackpoint("2008-08-21T13:09:00Z", "34.3", "-118.9") +
      "</Track>\n"
      "<CoursePoint><Name>Turn L</Name><Time>2008-08-21T13:08:54Z</Time><Position>"
      "<LatitudeDegrees>34.2</LatitudeDegrees><LongitudeDegrees>-118.8</LongitudeDegrees></Position>"
      "<AltitudeMeters>300</AltitudeMeters><PointType>Left</PointType><Notes>at the bridge</Notes></CoursePoint>\n"
      "<CoursePoint><Name>Top</Name><Position><LatitudeDegrees>34.25</LatitudeDegrees>"
      "<LongitudeDegrees>-118.85</LongitudeDegrees></Position><PointType>Summit</PointType></CoursePoint>\n"
      "<Creator><Name>Garmin Training Center(r)</Name></Creator>\n"
      "</Course></Courses>\n" +
      kTail;
  ReadResult r = read(xml);
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_TRUE(r.warnings.empty());
  ASSERT_EQ(r.file.tracks.size(), 1u);
  const Track& t = r.file.tracks[0];
  EXPECT_EQ(t.name, "Lake loop");
  EXPECT_TRUE(t.type.empty());
  ASSERT_EQ(t.segments.size(), 2u);  // one per Track element; the Lap's BeginPosition is no point
  ASSERT_EQ(t.segments[0].points.size(), 2u);
  ASSERT_EQ(t.segments[1].points.size(), 1u);
  EXPECT_DOUBLE_EQ(t.segments[0].points[0].ele, 308.5);
  EXPECT_FLOAT_EQ(t.segments[0].points[0].heart_rate, 107.0f);
  EXPECT_EQ(t.segments[0].points[0].time, 1219324132.0);
  EXPECT_DOUBLE_EQ(t.segments[1].points[0].lon, -118.9);
  EXPECT_EQ(r.file.metadata.creator, "Garmin Training Center(r)");

  ASSERT_EQ(r.file.waypoints.size(), 2u);
  const Waypoint& w = r.file.waypoints[0];
  EXPECT_EQ(w.name, "Turn L");
  EXPECT_EQ(w.symbol, "Left");
  EXPECT_EQ(w.description, "at the bridge");
  EXPECT_DOUBLE_EQ(w.point.lat, 34.2);
  EXPECT_DOUBLE_EQ(w.point.lon, -118.8);
  EXPECT_DOUBLE_EQ(w.point.ele, 300.0);
  EXPECT_EQ(w.point.time, 1219324134.0);
  EXPECT_EQ(r.file.waypoints[1].name, "Top");
  EXPECT_EQ(r.file.waypoints[1].symbol, "Summit");
  EXPECT_FALSE(r.file.waypoints[1].point.has_time());
}

TEST(TcxReader, CoursePointWithBadPositionIsWarned) {
  std::string xml = kHead +
                    "<Courses><Course><Name>C</Name>\n"
                    "<CoursePoint><Name>Nowhere</Name><PointType>Generic</PointType></CoursePoint>\n" +
                    kTail;
  xml.insert(xml.find(kTail), "</Course></Courses>\n");
  ReadResult r = read(xml);
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.file.waypoints.empty());
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].position.line, 5);
  EXPECT_NE(r.warnings[0].message.find("course point with invalid coordinates"), std::string::npos)
      << r.warnings[0].message;
}

TEST(TcxReader, WrongRootIsAnError) {
  ReadResult r = read("<?xml version=\"1.0\"?>\n<gpx version=\"1.1\"><trk/></gpx>\n");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->message, "root element is <gpx>, expected <TrainingCenterDatabase>: not a TCX file");
  EXPECT_EQ(r.error->position.line, 2);
  EXPECT_TRUE(r.file.tracks.empty());
}

TEST(TcxReader, PrefixedRootIsAccepted) {
  std::string xml =
      "<tcx:TrainingCenterDatabase xmlns:tcx=\"http://www.garmin.com/xmlschemas/TrainingCenterDatabase/v2\">"
      "<tcx:Activities><tcx:Activity Sport=\"Running\"><tcx:Lap><tcx:Track><tcx:Trackpoint><tcx:Position>"
      "<tcx:LatitudeDegrees>1.5</tcx:LatitudeDegrees><tcx:LongitudeDegrees>2.5</tcx:LongitudeDegrees>"
      "</tcx:Position></tcx:Trackpoint></tcx:Track></tcx:Lap></tcx:Activity></tcx:Activities>"
      "</tcx:TrainingCenterDatabase>";
  ReadResult r = read(xml);
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.tracks.size(), 1u);
  ASSERT_EQ(r.file.tracks[0].point_count(), 1u);
  EXPECT_DOUBLE_EQ(r.file.tracks[0].segments[0].points[0].lon, 2.5);
}

TEST(TcxReader, TruncatedFileKeepsCompletePoints) {
  std::string full = activity("Running", "<Lap StartTime=\"2021-06-01T08:00:00Z\"><Track>\n" +
                                             trackpoint("2021-06-01T08:00:00Z", "47.1", "8.1") +
                                             trackpoint("2021-06-01T08:00:01Z", "47.2", "8.2") +
                                             trackpoint("2021-06-01T08:00:02Z", "47.3", "8.3") + "</Track></Lap>\n");
  // Cut inside the third point's longitude.
  std::string cut = full.substr(0, full.find("8.3"));
  ReadResult r = read(cut);
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  ASSERT_EQ(r.file.tracks.size(), 1u);
  ASSERT_EQ(r.file.tracks[0].segments.size(), 1u);
  ASSERT_EQ(r.file.tracks[0].segments[0].points.size(), 2u);
  EXPECT_DOUBLE_EQ(r.file.tracks[0].segments[0].points[1].lat, 47.2);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].message.find("kept the 2 complete points"), std::string::npos) << r.warnings[0].message;
  EXPECT_GT(r.warnings[0].position.line, 0);

  ReadResult strict = read(cut, ReadOptions{.strict = true});
  ASSERT_FALSE(strict.ok());
  EXPECT_NE(strict.error->message.find("cut short"), std::string::npos) << strict.error->message;
  EXPECT_NE(strict.error->message.find("--strict"), std::string::npos);
}

TEST(TcxReader, MalformedXmlNamesLineAndColumn) {
  std::string xml = kHead +                                       // lines 1-3
                    "<Activities><Activity Sport=\"Running\">\n"  // line 4
                    "  <Id>2021-06-01T08:00:00Z</Idd>\n" +        // line 5: mismatched tag
                    "</Activity></Activities>\n" +
                    kTail;
  ReadResult r = read(xml);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error->message.find("malformed XML"), std::string::npos) << r.error->message;
  EXPECT_EQ(r.error->position.line, 5);
  EXPECT_EQ(r.error->position.column, 29);  // the error points at the name in "</Idd>"
  EXPECT_EQ(r.error->to_string(), "test.tcx:5:29: malformed XML: mismatched tag");
}

TEST(TcxReader, NotXmlAtAllIsAnError) {
  ReadResult r = read("this is not xml\n");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->position.line, 1);
}

// --- the real files (../shared/data; skipped when absent) ---------------------------------------

TEST(TcxReaderData, GpsbabelBikeActivity) {
  TRAILRAY_REQUIRE_DATA(path, "tcx/gpsbabel_bike.tcx");
  ReadResult r = load_track_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(r.file.format, Format::Tcx);
  ASSERT_EQ(r.file.tracks.size(), 1u);
  const Track& t = r.file.tracks[0];
  EXPECT_EQ(t.type, "Biking");
  EXPECT_EQ(r.file.metadata.activity_type, "Biking");
  EXPECT_EQ(r.file.metadata.creator, "Forerunner 910XT");
  EXPECT_EQ(r.file.metadata.time, 1367349837.0);  // Id 2013-04-30T19:23:57.000Z
  EXPECT_EQ(t.point_count(), 1812u);              // MANIFEST: 1812 trackpoints, all with position
  ASSERT_EQ(t.segments.size(), 2u);               // 2 laps
  EXPECT_EQ(t.segments[0].points.size(), 901u);
  EXPECT_EQ(t.segments[1].points.size(), 911u);

  const TrackPoint& first = t.segments[0].points.front();
  EXPECT_EQ(first.time, 1367349837.0);
  EXPECT_DOUBLE_EQ(first.lat, 40.78170446678996);
  EXPECT_DOUBLE_EQ(first.lon, -73.96090054884553);
  EXPECT_NEAR(first.ele, 58.2, 1e-6);
  EXPECT_FLOAT_EQ(first.speed, 0.0f);
  EXPECT_EQ(t.segments[1].points.front().time, 1367350738.0);  // lap 2 starts 19:38:58
  EXPECT_EQ(t.segments[1].points.back().time, 1367351651.0);   // 19:54:11

  float max_speed = 0.0f;
  for (const auto& s : t.segments)
    for (const auto& p : s.points) {
      ASSERT_TRUE(valid_coordinates(p.lat, p.lon));
      ASSERT_TRUE(p.has_time());
      ASSERT_TRUE(p.has_ele());
      ASSERT_FALSE(std::isnan(p.speed));      // every point has TPX/Speed
      ASSERT_TRUE(std::isnan(p.heart_rate));  // MANIFEST: hr=0
      max_speed = std::max(max_speed, p.speed);
    }
  EXPECT_NEAR(max_speed, 9.659f, 1e-3f);
}

TEST(TcxReaderData, GpsbabelCourse) {
  TRAILRAY_REQUIRE_DATA(path, "tcx/gpsbabel_course.tcx");
  ReadResult r = load_track_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_TRUE(r.warnings.empty());
  ASSERT_EQ(r.file.tracks.size(), 1u);
  const Track& t = r.file.tracks[0];
  EXPECT_EQ(t.name, "ThursRide");
  EXPECT_EQ(r.file.metadata.creator, "Garmin Training Center(r)");
  EXPECT_TRUE(r.file.waypoints.empty());  // no CoursePoints in this file
  // 1205 Trackpoints, 3 of them time-only (13:30:57, 13:30:58, 14:58:07): 1202 kept. (MANIFEST
  // says "with position=1204": it counts the Lap's BeginPosition/EndPosition too.)
  EXPECT_EQ(t.point_count(), 1202u);
  ASSERT_EQ(t.segments.size(), 2u);  // two Track elements
  EXPECT_EQ(t.segments[0].points.size(), 263u);
  EXPECT_EQ(t.segments[1].points.size(), 939u);

  const TrackPoint& first = t.segments[0].points.front();
  EXPECT_EQ(first.time, 1219324132.0);  // 2008-08-21T13:08:52Z
  EXPECT_DOUBLE_EQ(first.lat, 34.1738977);
  EXPECT_DOUBLE_EQ(first.lon, -118.7587927);
  EXPECT_NEAR(first.ele, 308.7204590, 1e-6);
  EXPECT_FLOAT_EQ(first.heart_rate, 107.0f);
  EXPECT_FLOAT_EQ(t.segments[1].points.back().heart_rate, 101.0f);
  for (const auto& s : t.segments)
    for (const auto& p : s.points) {
      ASSERT_FALSE(std::isnan(p.heart_rate));  // hr on every positioned point
      ASSERT_TRUE(p.has_ele());
      ASSERT_TRUE(p.lat > 34.13 && p.lat < 34.20 && p.lon > -118.96 && p.lon < -118.75);
    }
}
