// IGC reader: crafted records for exact checks, then every real file in ../shared/data/igc.

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "test_support.hpp"
#include "track/io/byte_source.hpp"
#include "track/io/load.hpp"
#include "track/io/parse_util.hpp"
#include "track/io/readers.hpp"

using namespace trailray::track;

namespace {

using Alt = ReadOptions::IgcAltitude;

ReadResult read(const std::string& text, ReadOptions options = {}) {
  auto src = ByteSource::from_memory(text, "test.igc");
  return read_igc(*src, options);
}

ReadResult read_alt(const std::string& text, Alt alt) {
  ReadOptions o;
  o.igc_altitude = alt;
  return read(text, o);
}

const std::vector<TrackPoint>& points(const ReadResult& r) {
  static const std::vector<TrackPoint> kNone;
  if (r.file.tracks.empty() || r.file.tracks[0].segments.empty()) return kNone;
  return r.file.tracks[0].segments[0].points;
}

// A header with a flight date of 2023-01-01, then the given records.
std::string igc(const std::string& body, const std::string& date = "HFDTE010123\r\n") {
  return "AXCT0123456789abcdef\r\n" + date + body;
}

// A B record: time, latitude DDMMmmmN, longitude DDDMMmmmE, validity, pressure and GNSS
// altitude (5 characters each), extensions.
std::string b(const std::string& time, const std::string& lat = "4700000N", const std::string& lon = "00800000E",
              char validity = 'A', const std::string& pressure = "01000", const std::string& gnss = "01100",
              const std::string& ext = "") {
  return "B" + time + lat + lon + std::string(1, validity) + pressure + gnss + ext + "\r\n";
}

bool has_warning(const ReadResult& r, const std::string& needle) {
  return std::any_of(r.warnings.begin(), r.warnings.end(),
                     [&](const Diagnostic& d) { return d.message.find(needle) != std::string::npos; });
}

const Diagnostic* find_warning(const ReadResult& r, const std::string& needle) {
  for (const auto& d : r.warnings)
    if (d.message.find(needle) != std::string::npos) return &d;
  return nullptr;
}

std::string field(const ReadResult& r, const std::string& key) {
  for (const auto& [k, v] : r.file.metadata.fields)
    if (k == key) return v;
  return "<absent>";
}

constexpr double kJan1 = 1672531200.0;  // 2023-01-01T00:00:00Z

}  // namespace

// ---- coordinates ---------------------------------------------------------------------------

TEST(IgcReader, ConvertsCoordinatesToDegrees) {
  auto r = read(igc(b("101500", "5206343N", "00006198W") + b("101501", "4512345N", "01234567E")));
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_TRUE(r.warnings.empty());
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_NEAR(p[0].lat, 52.0 + 6.343 / 60.0, 1e-9);
  EXPECT_NEAR(p[0].lon, -(0.0 + 6.198 / 60.0), 1e-9);
  EXPECT_NEAR(p[1].lat, 45.0 + 12.345 / 60.0, 1e-9);
  EXPECT_NEAR(p[1].lon, 12.0 + 34.567 / 60.0, 1e-9);
  EXPECT_EQ(r.file.format, Format::Igc);
  ASSERT_EQ(r.file.tracks.size(), 1u);
  EXPECT_EQ(r.file.tracks[0].segments.size(), 1u);
}

TEST(IgcReader, SouthAndWestAreNegative) {
  auto r = read(igc(b("000000", "3839773S", "17608501E") + b("000001", "3839773N", "17608501W") +
                    b("000002", "0000001S", "00000001W")));
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_NEAR(p[0].lat, -(38.0 + 39.773 / 60.0), 1e-9);
  EXPECT_NEAR(p[0].lon, 176.0 + 8.501 / 60.0, 1e-9);
  EXPECT_NEAR(p[1].lat, 38.0 + 39.773 / 60.0, 1e-9);
  EXPECT_NEAR(p[1].lon, -(176.0 + 8.501 / 60.0), 1e-9);
  EXPECT_NEAR(p[2].lat, -0.001 / 60.0, 1e-12);
  EXPECT_NEAR(p[2].lon, -0.001 / 60.0, 1e-12);
  EXPECT_LT(p[2].lat, 0.0);
}

TEST(IgcReader, PolesAndAntimeridianAreValidBeyondIsDropped) {
  auto r = read(igc(b("000000", "9000000N", "18000000W") + b("000001", "9000001N", "00000000E") +
                    b("000002", "0000000N", "18000001E")));
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_DOUBLE_EQ(p[0].lat, 90.0);
  EXPECT_DOUBLE_EQ(p[0].lon, -180.0);
  const Diagnostic* w = find_warning(r, "out of range");
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->position.line, 4);
  EXPECT_NE(w->message.find("2 times"), std::string::npos) << w->message;
}

TEST(IgcReader, LadLodAddDecimalDigitsOfTheMinutes) {
  // The XCTrack layout: LAD at byte 36, LOD at byte 37.
  auto r = read(igc("I023636LAD3737LOD\r\n" + b("053823", "4315910N", "01151568E", 'A', "00000", "00512", "56") +
                    b("053824", "4315910S", "01151568W", 'A', "00000", "00512", "09")));
  ASSERT_TRUE(r.warnings.empty()) << r.warnings[0].to_string();
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_NEAR(p[0].lat, 43.0 + 15.9105 / 60.0, 1e-9);
  EXPECT_NEAR(p[0].lon, 11.0 + 51.5686 / 60.0, 1e-9);
  EXPECT_NEAR(p[1].lat, -(43.0 + 15.9100 / 60.0), 1e-9);
  EXPECT_NEAR(p[1].lon, -(11.0 + 51.5689 / 60.0), 1e-9);
  // The extra digit really changes the position (1e-4 minute = ~0.19 m).
  EXPECT_GT(std::abs(p[0].lat - (43.0 + 15.910 / 60.0)), 1e-6);
}

TEST(IgcReader, LadLodWithTwoDigitsAndOtherExtensionsFirst) {
  // FXA 36-38, LAD 39-40, LOD 41-42.
  auto r = read(igc("I033638FXA3940LAD4142LOD\r\n" + b("120000", "4600000N", "00700000E", 'A', "01000", "01100",
                                                       "015"
                                                       "12"
                                                       "34")));
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NEAR(p[0].lat, 46.0 + 0.00012 / 60.0, 1e-11);
  EXPECT_NEAR(p[0].lon, 7.0 + 0.00034 / 60.0, 1e-11);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(IgcReader, BrokenLadKeepsTheFixAtBasePrecisionWithAWarning) {
  auto r = read(igc("I023636LAD3737LOD\r\n" + b("120000", "4600000N", "00700000E", 'A', "01000", "01100", "x7")));
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NEAR(p[0].lat, 46.0, 1e-12);                 // LAD ignored
  EXPECT_NEAR(p[0].lon, 7.0 + 0.0007 / 60.0, 1e-11);  // LOD still applied
  const Diagnostic* w = find_warning(r, "extension LAD");
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->position.line, 4);
  EXPECT_EQ(w->position.column, 36);
}

// ---- dates and times -----------------------------------------------------------------------

TEST(IgcReader, ShortHfdteForm) {
  auto r = read(igc(b("101530"), "HFDTE010123\r\n"));
  ASSERT_EQ(points(r).size(), 1u);
  EXPECT_DOUBLE_EQ(r.file.metadata.time, kJan1);
  EXPECT_DOUBLE_EQ(points(r)[0].time, kJan1 + 10 * 3600 + 15 * 60 + 30);
  EXPECT_EQ(field(r, "date"), "2023-01-01");
  EXPECT_TRUE(r.warnings.empty());
}

TEST(IgcReader, LongHfdteFormWithFlightNumber) {
  auto r = read(igc(b("101530"), "HFDTEDATE:280423,04\r\n"));
  ASSERT_EQ(points(r).size(), 1u);
  const double apr28 = static_cast<double>(days_from_civil(2023, 4, 28)) * 86400.0;
  EXPECT_DOUBLE_EQ(apr28, 1682640000.0);
  EXPECT_DOUBLE_EQ(r.file.metadata.time, apr28);
  EXPECT_DOUBLE_EQ(points(r)[0].time, apr28 + 36930);
  EXPECT_EQ(field(r, "date"), "2023-04-28");
  EXPECT_EQ(field(r, "flight_number"), "04");
  EXPECT_TRUE(r.warnings.empty());
}

TEST(IgcReader, TwoDigitYears) {
  EXPECT_DOUBLE_EQ(read(igc(b("000000"), "HFDTE311299\r\n")).file.metadata.time,
                   static_cast<double>(days_from_civil(1999, 12, 31)) * 86400.0);
  EXPECT_DOUBLE_EQ(read(igc(b("000000"), "HFDTE010180\r\n")).file.metadata.time,
                   static_cast<double>(days_from_civil(1980, 1, 1)) * 86400.0);
  EXPECT_DOUBLE_EQ(read(igc(b("000000"), "HFDTE010179\r\n")).file.metadata.time,
                   static_cast<double>(days_from_civil(2079, 1, 1)) * 86400.0);
  EXPECT_DOUBLE_EQ(read(igc(b("000000"), "HFDTE290224\r\n")).file.metadata.time,  // leap day
                   static_cast<double>(days_from_civil(2024, 2, 29)) * 86400.0);
}

TEST(IgcReader, InvalidDateIsAWarningAndTimesHaveNoDate) {
  for (const std::string date : {"HFDTE321399\r\n", "HFDTE290223\r\n", "HFDTEDATE:\r\n", "HFDTE01a123\r\n"}) {
    auto r = read(igc(b("101530"), date));
    ASSERT_EQ(points(r).size(), 1u) << date;
    EXPECT_TRUE(std::isnan(r.file.metadata.time)) << date;
    EXPECT_TRUE(has_warning(r, "unreadable HFDTE date")) << date;
    EXPECT_TRUE(has_warning(r, "no HFDTE date record")) << date;
    EXPECT_DOUBLE_EQ(points(r)[0].time, 36930.0) << date;
  }
}

TEST(IgcReader, NoDateKeepsTimeOfDayOn1970WithAWarning) {
  auto r = read(igc(b("235959") + b("000001"), ""));
  ASSERT_TRUE(r.ok());
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_DOUBLE_EQ(p[0].time, 86399.0);
  EXPECT_DOUBLE_EQ(p[1].time, 86401.0);  // the rollover still applies
  EXPECT_TRUE(std::isnan(r.file.metadata.time));
  EXPECT_TRUE(has_warning(r, "no HFDTE date record: times have no date"));
}

TEST(IgcReader, DateAfterTheFixesStillApplies) {
  auto r = read("AXCT1\r\n" + b("000010") + "HFDTE010123\r\n");
  ASSERT_EQ(points(r).size(), 1u);
  EXPECT_DOUBLE_EQ(points(r)[0].time, kJan1 + 10);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(IgcReader, MidnightRolloverAdvancesTheDay) {
  auto r = read(igc(b("234808") + b("235959") + b("000000") + b("040830")));
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_DOUBLE_EQ(p[0].time, kJan1 + 23 * 3600 + 48 * 60 + 8);
  EXPECT_DOUBLE_EQ(p[1].time, kJan1 + 86399);
  EXPECT_DOUBLE_EQ(p[2].time, kJan1 + 86400);
  EXPECT_DOUBLE_EQ(p[3].time, kJan1 + 86400 + 4 * 3600 + 8 * 60 + 30);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(IgcReader, SmallBackwardStepsAreNotRollovers) {
  auto r = read(igc(b("120005") + b("120003") + b("110000") + b("120010")));
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_DOUBLE_EQ(p[0].time, kJan1 + 43205);
  EXPECT_DOUBLE_EQ(p[1].time, kJan1 + 43203);  // kept as recorded
  EXPECT_DOUBLE_EQ(p[2].time, kJan1 + 39600);  // an hour back: still the same day
  EXPECT_DOUBLE_EQ(p[3].time, kJan1 + 43210);
}

TEST(IgcReader, TwoRolloversForAMultiDayRecording) {
  auto r = read(igc(b("230000") + b("010000") + b("230000") + b("010000")));
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_DOUBLE_EQ(p[3].time, kJan1 + 2 * 86400 + 3600);
}

// ---- altitude ------------------------------------------------------------------------------

TEST(IgcReader, AutoUsesGnssOnValidFixesAndPressureOtherwise) {
  auto r = read(igc(b("100000", "4700000N", "00800000E", 'A', "01000", "01100") +
                    b("100001", "4700000N", "00800000E", 'V', "01001", "00000") +
                    b("100002", "4700000N", "00800000E", 'A', "-0012", "00000")));
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_DOUBLE_EQ(p[0].ele, 1100.0);
  EXPECT_DOUBLE_EQ(p[1].ele, 1001.0);  // 2D fix: pressure
  EXPECT_DOUBLE_EQ(p[2].ele, 0.0);     // 3D fix, GNSS present in the file: a real 0 is kept
  EXPECT_TRUE(r.warnings.empty());
}

TEST(IgcReader, AutoTreatsAnAllZeroPressureChannelAsAbsent) {
  // XCTrack without a barometer: a 'V' fix then has no usable altitude.
  auto r = read(igc(b("100000", "4700000N", "00800000E", 'A', "00000", "00512") +
                    b("100001", "4700000N", "00800000E", 'V', "00000", "00000")));
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_DOUBLE_EQ(p[0].ele, 512.0);
  EXPECT_FALSE(p[1].has_ele());
}

TEST(IgcReader, AutoTreatsAnAllZeroGnssChannelAsAbsent) {
  auto r = read(igc(b("100000", "4700000N", "00800000E", 'A', "-0053", "00000") +
                    b("100001", "4700000N", "00800000E", 'A', "00642", "00000")));
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_DOUBLE_EQ(p[0].ele, -53.0);
  EXPECT_DOUBLE_EQ(p[1].ele, 642.0);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(IgcReader, AutoWithNoAltitudeAtAllWarns) {
  auto r = read(igc(b("100000", "4700000N", "00800000E", 'A', "00000", "00000")));
  ASSERT_EQ(points(r).size(), 1u);
  EXPECT_FALSE(points(r)[0].has_ele());
  EXPECT_TRUE(has_warning(r, "GNSS and pressure altitude are 0 on every fix"));
}

TEST(IgcReader, ForcedGnssAndPressure) {
  const std::string text = igc(b("100000", "4700000N", "00800000E", 'A', "01000", "01100") +
                               b("100001", "4700000N", "00800000E", 'V', "01001", "00000") +
                               b("100002", "4700000N", "00800000E", 'V', "-0007", "01105"));
  auto g = read_alt(text, Alt::Gnss);
  ASSERT_EQ(points(g).size(), 3u);
  EXPECT_DOUBLE_EQ(points(g)[0].ele, 1100.0);
  EXPECT_FALSE(points(g)[1].has_ele());  // 2D fix without GNSS altitude
  EXPECT_DOUBLE_EQ(points(g)[2].ele, 1105.0);
  EXPECT_TRUE(g.warnings.empty());

  auto p = read_alt(text, Alt::Pressure);
  ASSERT_EQ(points(p).size(), 3u);
  EXPECT_DOUBLE_EQ(points(p)[0].ele, 1000.0);
  EXPECT_DOUBLE_EQ(points(p)[1].ele, 1001.0);
  EXPECT_DOUBLE_EQ(points(p)[2].ele, -7.0);
  EXPECT_TRUE(p.warnings.empty());
}

TEST(IgcReader, ForcedChannelThatIsAbsentGivesNoElevationAndAWarning) {
  const std::string no_baro = igc(b("100000", "4700000N", "00800000E", 'A', "00000", "00512"));
  auto p = read_alt(no_baro, Alt::Pressure);
  ASSERT_EQ(points(p).size(), 1u);
  EXPECT_FALSE(points(p)[0].has_ele());
  EXPECT_TRUE(has_warning(p, "pressure altitude is 0 on every fix"));

  const std::string no_gnss = igc(b("100000", "4700000N", "00800000E", 'A', "00400", "00000"));
  auto g = read_alt(no_gnss, Alt::Gnss);
  ASSERT_EQ(points(g).size(), 1u);
  EXPECT_FALSE(points(g)[0].has_ele());
  EXPECT_TRUE(has_warning(g, "GNSS altitude is 0 on every fix"));
}

// ---- headers -------------------------------------------------------------------------------

TEST(IgcReader, HeadersBecomeFieldsInFileOrder) {
  auto r = read(
      "ALXV79MFLIGHT:1\r\n"
      "HFDTE050822\r\n"
      "HFFXA015\r\n"
      "HFPLTPILOTINCHARGE:  Jane Doe  \r\n"
      "HFCM2CREW2:\r\n"
      "HFGTYGLIDERTYPE:ASG 29E 18m\r\n"
      "HFGIDGLIDERID:D-KGSA\r\n"
      "HFDTM100GPSDATUM:WGS-1984\r\n"
      "HFRFWFIRMWAREVERSION:9.0\r\n"
      "HFRHWHARDWAREVERSION:3\r\n"
      "HFFTYFRTYPE:LXNAV,LX9000F\r\n"
      "HFCIDCOMPETITIONID:29\r\n"
      "HFCCLCOMPETITION CLASS:18-meter\r\n"
      "HOSITSite:Amisb\xC3\xBChl\r\n"
      "HFALPALTPRESSURE:ISA\r\n"
      "HPCM2Crew2:Second:Person\r\n"
      "HFXYZSOMETHING:odd\r\n" +
      b("103532"));
  ASSERT_TRUE(r.ok());
  const std::vector<std::pair<std::string, std::string>> expected{
      {"date", "2022-08-05"},
      {"fix_accuracy", "015"},
      {"pilot", "Jane Doe"},
      {"glider_type", "ASG 29E 18m"},
      {"glider_id", "D-KGSA"},
      {"gps_datum", "WGS-1984"},
      {"firmware", "9.0"},
      {"hardware", "3"},
      {"recorder", "LXNAV,LX9000F"},
      {"competition_id", "29"},
      {"competition_class", "18-meter"},
      {"site", "Amisb\xC3\xBChl"},
      {"altitude_pressure", "ISA"},
      {"copilot", "Second:Person"},
      {"HFXYZ", "odd"},
  };
  EXPECT_EQ(r.file.metadata.fields, expected);
  EXPECT_EQ(r.file.metadata.creator, "LXNAV 79MFLIGHT:1");
  EXPECT_EQ(r.file.metadata.activity_type, "flight");
  EXPECT_TRUE(r.warnings.empty());
}

TEST(IgcReader, CreatorOfAnUnknownManufacturerIsTheRawARecord) {
  auto r = read("ABCDEFGFLIGHT:2\r\nHFDTE010123\r\n" + b("000000"));
  EXPECT_EQ(r.file.metadata.creator, "BCDEFGFLIGHT:2");
  auto x = read("AXCTb9d15853a7c25f72\r\nHFDTE010123\r\n" + b("000000"));
  EXPECT_EQ(x.file.metadata.creator, "XCTrack b9d15853a7c25f72");
}

TEST(IgcReader, Latin1HeaderTextBecomesUtf8) {
  auto r = read(igc("HFPLTPILOT:J\xF6rg M\xFCller\r\n" + b("000000")));
  EXPECT_EQ(field(r, "pilot"), "J\xC3\xB6rg M\xC3\xBCller");
}

TEST(IgcReader, OtherRecordTypesAreIgnored) {
  auto r =
      read(igc("I023636LAD3737LOD\r\n"
               "J010812HDT\r\n"
               "C050822094632000000000305\r\n"
               "C4826967N00136183E002departSud\r\n"
               "LLXVOZ=-1,Style=2,R1=5000m\r\n"
               "LXCTsomething B1234\r\n" +
               b("100000", "4700000N", "00800000E", 'A', "01000", "01100", "00") +
               "F103532270308211410013222\r\n"
               "K100001090\r\n"
               "E100001PEV\r\n"
               "D20331\r\n" +
               b("100002", "4700000N", "00800000E", 'A', "01000", "01100", "00") +
               "G6A8B9C0D\r\nGREJNGJERJKNJKRE31895478537H43982FJN9248F942389T433T\r\n"));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(points(r).size(), 2u);
  EXPECT_TRUE(r.warnings.empty()) << r.warnings[0].to_string();
}

TEST(IgcReader, LfCrlfAndCrLineEndingsReadAlike) {
  const std::string crlf = igc(b("100000") + b("100001", "4700001N") + "HFGTYGLIDERTYPE:X\r\n" + b("100002"));
  std::string lf, cr;
  for (char c : crlf) {
    if (c != '\r') lf += c;
    if (c != '\n') cr += c;
  }
  for (const std::string& text : {crlf, lf, cr}) {
    auto r = read(text);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(points(r).size(), 3u);
    EXPECT_NEAR(points(r)[1].lat, 47.0 + 0.001 / 60.0, 1e-12);
    EXPECT_DOUBLE_EQ(points(r)[2].time, kJan1 + 36002);
    EXPECT_EQ(field(r, "glider_type"), "X");
    EXPECT_TRUE(r.warnings.empty());
  }
}

TEST(IgcReader, Utf8BomBeforeTheARecord) {
  auto r = read("\xEF\xBB\xBF" + igc(b("100000")));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.file.metadata.creator, "XCTrack 0123456789abcdef");
  EXPECT_EQ(points(r).size(), 1u);
}

// ---- bad input -----------------------------------------------------------------------------

TEST(IgcReader, TooShortBRecordsAreDroppedWithOneCountedWarning) {
  auto r = read(igc(b("100000") + "B1000014700000N00800000EA0100001\r\n" + "B\r\n" + b("100002") + "B10000347\r\n"));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(points(r).size(), 2u);
  ASSERT_EQ(r.warnings.size(), 1u);
  const Diagnostic& w = r.warnings[0];
  EXPECT_EQ(w.position.line, 4);
  EXPECT_EQ(w.position.column, 1);
  EXPECT_NE(w.message.find("too short"), std::string::npos);
  EXPECT_NE(w.message.find("3 times in all"), std::string::npos) << w.message;
  EXPECT_EQ(w.file, "test.igc");
}

struct BadRecord {
  std::string line;
  std::string message;  // part of the warning
  std::int64_t column;
};

TEST(IgcReader, BRecordsWithBadFieldsAreDroppedWithAWarningPerKind) {
  const std::vector<BadRecord> cases{
      {"B1o00004700000N00800000EA0100001100", "time '1o0000'", 2},
      {"B2500004700000N00800000EA0100001100", "is not HHMMSS", 2},
      {"B1060004700000N00800000EA0100001100", "is not HHMMSS", 2},
      {"B100000470000xN00800000EA0100001100", "latitude", 8},
      {"B1000004700000X00800000EA0100001100", "latitude", 8},
      {"B1000004760000N00800000EA0100001100", "latitude", 8},  // 60 minutes
      {"B1000009100000N00800000EA0100001100", "out of range", 8},
      {"B1000004700000N0080 000EA0100001100", "longitude", 16},
      {"B1000004700000N00800000ZA0100001100", "longitude", 16},
      {"B1000004700000N18100000EA0100001100", "out of range", 8},
      {"B1000004700000N00800000EX0100001100", "validity 'X'", 25},
      {"B1000004700000N00800000EA01o0001100", "pressure altitude", 26},
      {"B1000004700000N00800000EA010000--00", "GNSS altitude", 31},
      {"B1000004700000N00800000EA0100001-00", "GNSS altitude", 31},
      {"B1000000000000N00000000EV0100001100", "without a position", 8},
  };
  for (const BadRecord& c : cases) {
    auto r = read(igc(b("095959") + c.line + "\r\n" + b("100001")));
    ASSERT_TRUE(r.ok()) << c.line;
    EXPECT_EQ(points(r).size(), 2u) << c.line;
    ASSERT_EQ(r.warnings.size(), 1u) << c.line;
    EXPECT_NE(r.warnings[0].message.find(c.message), std::string::npos) << c.line << ": " << r.warnings[0].message;
    EXPECT_NE(r.warnings[0].message.find("fix dropped"), std::string::npos) << r.warnings[0].message;
    EXPECT_EQ(r.warnings[0].position.line, 4) << c.line;
    EXPECT_EQ(r.warnings[0].position.column, c.column) << c.line;
    // Under strict, the first warning becomes the error.
    ReadOptions strict;
    strict.strict = true;
    auto s = read(igc(b("095959") + c.line + "\r\n"), strict);
    ASSERT_FALSE(s.ok()) << c.line;
    EXPECT_EQ(s.error->position.line, 4);
  }
}

TEST(IgcReader, ValidZeroZeroFixWithAIsKept) {
  auto r = read(igc(b("100000", "0000000N", "00000000E", 'A')));
  EXPECT_EQ(points(r).size(), 1u);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(IgcReader, CorruptExtensionKeepsTheFix) {
  // As in aerofiles_bad-line.igc line 55: the base 35 characters are fine.
  const std::string iline = "I083638FXA3941ENL4246TAS4751GSP5254TRT5559VAT6063OAT6467ACZ\r\n";
  auto r = read(igc(iline + "B1350184747318N00025056EA01307014470080041653816206072-021401010100\r\n" +
                    "B1350194747325N00025090EA01308014470080041629316071072-022401010cKYI\r\n"));
  ASSERT_TRUE(r.ok());
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_NEAR(p[1].lat, 47.0 + 47.325 / 60.0, 1e-9);
  EXPECT_DOUBLE_EQ(p[1].ele, 1447.0);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].position.line, 5);
  EXPECT_EQ(r.warnings[0].position.column, 64);
  EXPECT_NE(r.warnings[0].message.find("extension ACZ"), std::string::npos) << r.warnings[0].message;
  EXPECT_NE(r.warnings[0].message.find("fix kept"), std::string::npos);
}

TEST(IgcReader, BRecordShorterThanItsIRecordKeepsTheFix) {
  auto r = read(
      igc("I023636LAD3737LOD\r\n" + b("100000", "4700000N", "00800000E", 'A', "01000", "01100", "5") + b("100001")));
  ASSERT_EQ(points(r).size(), 2u);
  EXPECT_NEAR(points(r)[0].lat, 47.0 + 0.0005 / 60.0, 1e-12);  // LAD present, LOD missing
  EXPECT_NEAR(points(r)[1].lat, 47.0, 1e-12);
  const Diagnostic* w = find_warning(r, "shorter than its I record declares");
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->position.line, 4);
  EXPECT_NE(w->message.find("2 times"), std::string::npos);
}

TEST(IgcReader, BadIRecordsAreWarnedAboutAndIgnored) {
  auto r = read(igc("I0x3636LAD\r\n" + b("100000", "4700000N", "00800000E", 'A', "01000", "01100", "5") +
                    "I033636LAD3737LOD\r\n" + b("100001", "4700000N", "00800000E", 'A', "01000", "01100", "56") +
                    "I021036LAD3737LOD\r\n" + b("100002", "4700000N", "00800000E", 'A', "01000", "01100", "56")));
  ASSERT_TRUE(r.ok());
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_NEAR(p[0].lat, 47.0, 1e-12);                  // no usable I record: base precision
  EXPECT_NEAR(p[1].lat, 47.0 + 0.0005 / 60.0, 1e-12);  // 2 of 3 declared entries present
  EXPECT_NEAR(p[1].lon, 8.0 + 0.0006 / 60.0, 1e-12);
  EXPECT_NEAR(p[2].lat, 47.0, 1e-12);  // LAD range 10-36 overlaps the base record
  EXPECT_NEAR(p[2].lon, 8.0 + 0.0006 / 60.0, 1e-12);
  const Diagnostic* w = find_warning(r, "I record");
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->position.line, 3);
  EXPECT_NE(w->message.find("3 times in all"), std::string::npos) << w->message;
}

TEST(IgcReader, CutFileKeepsTheCompletePointsWithAWarning) {
  const std::string text = igc(b("100000") + b("100001")) + "B1000024700000N0080";
  auto r = read(text);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(points(r).size(), 2u);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].message.find("file ends inside a record (cut short?)"), std::string::npos);
  EXPECT_NE(r.warnings[0].message.find("kept the 2 complete points"), std::string::npos) << r.warnings[0].message;
  EXPECT_EQ(r.warnings[0].position.line, 5);

  ReadOptions strict;
  strict.strict = true;
  auto s = read(text, strict);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error->message.find("file ends inside a record"), std::string::npos);
  EXPECT_NE(s.error->message.find("(--strict)"), std::string::npos);
  EXPECT_EQ(s.error->position.line, 5);
}

TEST(IgcReader, CutInsideTheExtensionsIsACutToo) {
  auto r = read(igc("I023636LAD3737LOD\r\n" + b("100000", "4700000N", "00800000E", 'A', "01000", "01100", "12")) +
                "B1000014700000N00800000EA01000011001");
  EXPECT_EQ(points(r).size(), 1u);
  EXPECT_TRUE(has_warning(r, "file ends inside a record"));
}

TEST(IgcReader, CompleteLastRecordWithoutLineEndingIsKept) {
  std::string text = igc(b("100000") + b("100001"));
  text.resize(text.size() - 2);  // drop the final CRLF
  auto r = read(text);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(points(r).size(), 2u);
  EXPECT_TRUE(r.warnings.empty());
  ReadOptions strict;
  strict.strict = true;
  EXPECT_TRUE(read(text, strict).ok());
}

TEST(IgcReader, NotIgcIsAnErrorNamingLine1) {
  std::string junk;
  for (int i = 0; i < 5000; ++i) junk.push_back(static_cast<char>((i * 7919 + 13) % 256));
  for (const std::string& text : {junk, std::string(), std::string("hello world\nthis is text\n"),
                                  std::string("<?xml version=\"1.0\"?><gpx></gpx>")}) {
    auto r = read(text);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error->position.line, 1);
    EXPECT_NE(r.error->message.find("not an IGC file"), std::string::npos) << r.error->message;
    EXPECT_EQ(r.error->file, "test.igc");
    EXPECT_TRUE(r.file.tracks.empty());
  }
}

TEST(IgcReader, HeadersWithoutFixesIsAWarningNotAnError) {
  auto r = read("AXCT1\r\nHFDTE010123\r\nHFPLTPILOT:X\r\n");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(points(r).size(), 0u);
  EXPECT_TRUE(has_warning(r, "no B records"));
  EXPECT_DOUBLE_EQ(r.file.metadata.time, kJan1);
}

TEST(IgcReader, FileWithoutARecordIsStillIgc) {
  // igclib_flight_with_middle_landing.igc starts with HFDTE.
  auto r = read(b("100000"));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(points(r).size(), 1u);
}

TEST(IgcReader, OverlongLinesDoNotCrashAndAreSkipped) {
  const std::string huge_b = "B1000014700000N00800000EA0100001100" + std::string(200000, '7') + "\r\n";
  const std::string huge_l = "L" + std::string(3u << 20, 'x') + "\r\n";
  auto r = read(igc(b("100000") + huge_b + huge_l + b("100002")));
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(points(r).size(), 2u);
  EXPECT_DOUBLE_EQ(points(r)[1].time, kJan1 + 36002);
  const Diagnostic* w = find_warning(r, "line longer than");
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->position.line, 4);
  EXPECT_NE(w->message.find("2 times"), std::string::npos);
}

TEST(IgcReader, GarbageBytesInsideAFileDoNotCrash) {
  std::string text = igc(b("100000"));
  for (int i = 0; i < 3000; ++i) {
    char c = static_cast<char>((i * 131 + 7) % 256);
    text.push_back(i % 40 == 0 ? 'B' : c);
  }
  text += "\r\n" + b("100001");
  auto r = read(text);
  ASSERT_TRUE(r.ok());
  EXPECT_GE(points(r).size(), 2u);
  for (const auto& p : points(r)) EXPECT_TRUE(valid_coordinates(p.lat, p.lon));
}

TEST(IgcReader, GzipInputIsRead) {
  const std::string plain = igc(b("100000") + b("100001"));
  std::string gz(plain.size() + 128, '\0');
  z_stream zs{};
  ASSERT_EQ(deflateInit2(&zs, Z_BEST_SPEED, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY), Z_OK);
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(plain.data()));
  zs.avail_in = static_cast<uInt>(plain.size());
  zs.next_out = reinterpret_cast<Bytef*>(gz.data());
  zs.avail_out = static_cast<uInt>(gz.size());
  ASSERT_EQ(deflate(&zs, Z_FINISH), Z_STREAM_END);
  gz.resize(zs.total_out);
  deflateEnd(&zs);
  ASSERT_EQ(static_cast<unsigned char>(gz[0]), 0x1f);
  auto r = read(gz);
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(points(r).size(), 2u);
  EXPECT_DOUBLE_EQ(points(r)[1].time, kJan1 + 36001);
}

// ---- real files ----------------------------------------------------------------------------

namespace {

struct RealFile {
  const char* name;
  int day, month, year;  // HFDTE
  int count;             // B fixes (MANIFEST.md)
  int first, last;       // HHMMSS of the first and last fix (UTC)
  int last_day;          // days after the flight date of the last fix
  int gnss_min, gnss_max, baro_min, baro_max;
};

const RealFile kRealFiles[] = {
    {"aerofiles_bad-line.igc", 5, 8, 2022, 9, 103532, 135021, 0, 191, 1447, 92, 1308},
    {"aerofiles_skytraxx21-2023-04-15.igc", 15, 4, 2023, 2008, 73937, 81304, 0, 1, 704, -53, 642},
    {"aerofiles_xctrack-2023-04-28.igc", 28, 4, 2023, 979, 53823, 55441, 0, 434, 512, 0, 0},
    {"goigc_0100_interlaken.igc", 2, 10, 2023, 1149, 142034, 143942, 0, 568, 1596, 486, 1462},
    {"goigc_0192_kitzbuehel.igc", 3, 10, 2023, 3399, 104115, 113753, 0, 599, 2120, 0, 0},
    {"goigc_2024-06-18_Renato_Spaeni_420032.igc", 18, 6, 2024, 6631, 91125, 162256, 0, 451, 3663, 398, 3453},
    {"goigc_Kz9PYR1v.igc", 21, 6, 2015, 5338, 130110, 143114, 0, 855, 3760, 855, 3760},
    {"gpsbabel_92HV66G1.igc", 17, 2, 2019, 2470, 173257, 193425, 0, 28, 1314, 17, 1252},
    {"igclib_flight_with_middle_landing.igc", 9, 3, 2019, 14819, 112318, 153632, 0, 199, 1185, 87, 1077},
    {"igclib_napret.igc", 3, 4, 2016, 5380, 120000, 132939, 0, 259, 1143, 218, 1088},
    {"igclib_new_zealand.igc", 6, 11, 2009, 5367, 234808, 40830, 1, 457, 1878, 351, 1792},
    {"igclib_no_time_increment.igc", 1, 2, 2003, 200, 101648, 102403, 0, 121, 955, 123, 962},
    {"igcparser_654G6NG1.IGC", 4, 5, 2016, 9762, 81042, 190454, 0, 230, 2517, 47, 2390},
    {"igcparser_lad_lod_extensions.igc", 20, 2, 2023, 424, 164659, 165418, 0, 1097, 1719, 0, 0},
    {"xcscore_discontinuity.igc", 20, 3, 2019, 4708, 131226, 154148, 0, 143, 2020, 29, 1919},
    {"xcscore_dup-fixes.igc", 21, 6, 2019, 65924, 103157, 131851, 0, 236, 1997, 0, 0},
    {"xcscore_hiking-up.igc", 24, 6, 2019, 22180, 44617, 123320, 0, 807, 3086, 717, 2879},
    {"xcscore_trifai-xcontest-452.21.igc", 4, 6, 2019, 35041, 75941, 174341, 0, 747, 3892, 668, 3822},
};

double utc(const RealFile& f, int hhmmss, int extra_days) {
  const double day = static_cast<double>(
      days_from_civil(f.year, static_cast<unsigned>(f.month), static_cast<unsigned>(f.day)) + extra_days);
  return day * 86400.0 + (hhmmss / 10000) * 3600 + (hhmmss / 100 % 100) * 60 + hhmmss % 100;
}

void ele_range(const ReadResult& r, double& lo, double& hi, std::size_t& with_ele) {
  lo = 1e9;
  hi = -1e9;
  with_ele = 0;
  for (const auto& p : points(r)) {
    if (!p.has_ele()) continue;
    ++with_ele;
    lo = std::min(lo, p.ele);
    hi = std::max(hi, p.ele);
  }
}

}  // namespace

TEST(IgcRealFiles, CountsTimesAndAltitudesMatchTheManifest) {
  TRAILRAY_REQUIRE_DATA(dir, "igc");
  for (const RealFile& f : kRealFiles) {
    SCOPED_TRACE(f.name);
    const std::string path = (dir / f.name).string();
    ASSERT_TRUE(std::filesystem::exists(path));
    auto r = load_track_file(path);
    ASSERT_TRUE(r.ok()) << r.error->to_string();
    EXPECT_EQ(r.file.format, Format::Igc);
    ASSERT_EQ(r.file.tracks.size(), 1u);
    ASSERT_EQ(r.file.tracks[0].segments.size(), 1u);
    const auto& p = points(r);
    ASSERT_EQ(p.size(), static_cast<std::size_t>(f.count));
    EXPECT_DOUBLE_EQ(r.file.metadata.time, utc(f, 0, 0));
    EXPECT_DOUBLE_EQ(p.front().time, utc(f, f.first, 0));
    EXPECT_DOUBLE_EQ(p.back().time, utc(f, f.last, f.last_day));
    EXPECT_EQ(r.file.metadata.activity_type, "flight");
    for (const auto& q : p) ASSERT_TRUE(valid_coordinates(q.lat, q.lon));
    // Only bad-line.igc has a problem (its line 55).
    if (std::string(f.name) == "aerofiles_bad-line.igc") {
      EXPECT_EQ(r.warnings.size(), 1u);
    } else {
      EXPECT_TRUE(r.warnings.empty()) << r.warnings[0].to_string();
    }

    // Auto: every fix is a valid 'A' fix with GNSS altitude, so the GNSS range.
    double lo = 0, hi = 0;
    std::size_t n = 0;
    ele_range(r, lo, hi, n);
    EXPECT_EQ(n, p.size());
    EXPECT_EQ(lo, f.gnss_min);
    EXPECT_EQ(hi, f.gnss_max);

    ReadOptions pressure;
    pressure.igc_altitude = Alt::Pressure;
    auto rp = load_track_file(path, pressure);
    ASSERT_TRUE(rp.ok());
    ele_range(rp, lo, hi, n);
    if (f.baro_min == 0 && f.baro_max == 0) {
      EXPECT_EQ(n, 0u);  // no barometer
      EXPECT_TRUE(has_warning(rp, "pressure altitude is 0 on every fix"));
    } else {
      EXPECT_EQ(n, p.size());
      EXPECT_EQ(lo, f.baro_min);
      EXPECT_EQ(hi, f.baro_max);
    }
  }
}

TEST(IgcRealFiles, EveryIgcFileInTheDataFolderIsListed) {
  TRAILRAY_REQUIRE_DATA(dir, "igc");
  std::size_t n = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    // Sub-folders hold other data sets (scoring/: flights with known cross-country scores).
    if (!e.is_regular_file()) continue;
    const std::string name = e.path().filename().string();
    ++n;
    EXPECT_TRUE(
        std::any_of(std::begin(kRealFiles), std::end(kRealFiles), [&](const RealFile& f) { return name == f.name; }))
        << name << " has no expectations in kRealFiles";
  }
  EXPECT_EQ(n, std::size(kRealFiles));
}

TEST(IgcRealFiles, NewZealandCrossesUtcMidnight) {
  TRAILRAY_REQUIRE_DATA(path, "igc/igclib_new_zealand.igc");
  auto r = load_track_file(path.string());
  ASSERT_TRUE(r.ok());
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 5367u);
  const double midnight = static_cast<double>(days_from_civil(2009, 11, 7)) * 86400.0;
  std::size_t before = 0, after = 0, big_steps = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    (p[i].time < midnight ? before : after)++;
    if (i > 0 && std::abs(p[i].time - p[i - 1].time) > 3600) ++big_steps;
  }
  EXPECT_GT(before, 0u);
  EXPECT_GT(after, 0u);
  EXPECT_EQ(big_steps, 0u);  // no day-sized jump anywhere
  EXPECT_DOUBLE_EQ(p.back().time - p.front().time, 4 * 3600 + 20 * 60 + 22);
  EXPECT_LT(p.front().lat, 0.0);  // southern hemisphere
  EXPECT_GT(p.front().lon, 176.0);
}

TEST(IgcRealFiles, LadLodFileHasExtraPrecision) {
  TRAILRAY_REQUIRE_DATA(path, "igc/igcparser_lad_lod_extensions.igc");
  auto r = load_track_file(path.string());
  ASSERT_TRUE(r.ok());
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 424u);
  // B1646594458082N00549988EA000000171983: LAD '8', LOD '3'.
  EXPECT_NEAR(p[0].lat, 44.0 + 58.0828 / 60.0, 1e-9);
  EXPECT_NEAR(p[0].lon, 5.0 + 49.9883 / 60.0, 1e-9);
  EXPECT_DOUBLE_EQ(p[0].ele, 1719.0);  // pressure altitude is always 0 in this file
  EXPECT_EQ(field(r, "glider_type"), "GIN GLIDERS Explorer");
  EXPECT_EQ(field(r, "date"), "2023-02-20");
  EXPECT_EQ(r.file.metadata.creator, "XCTrack b2adde51d8560c30");
}

TEST(IgcRealFiles, BadLineKeepsTheFixAndWarnsAboutLine55) {
  TRAILRAY_REQUIRE_DATA(path, "igc/aerofiles_bad-line.igc");
  auto r = load_track_file(path.string());
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(points(r).size(), 9u);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].position.line, 55);
  EXPECT_NE(r.warnings[0].message.find("ACZ"), std::string::npos);
  // Line 55 itself: B1350194747325N00025090EA...
  EXPECT_NEAR(points(r)[6].lat, 47.0 + 47.325 / 60.0, 1e-9);
  EXPECT_DOUBLE_EQ(points(r)[6].time, utc(kRealFiles[0], 135019, 0));
  // The 3-hour gap stays in the data (cleaning decides what it means).
  EXPECT_DOUBLE_EQ(points(r)[4].time - points(r)[3].time,
                   utc(kRealFiles[0], 135017, 0) - utc(kRealFiles[0], 103536, 0));

  ReadOptions strict;
  strict.strict = true;
  auto s = load_track_file(path.string(), strict);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error->position.line, 55);
}

TEST(IgcRealFiles, HeadersOfARealFile) {
  TRAILRAY_REQUIRE_DATA(path, "igc/goigc_0100_interlaken.igc");
  auto r = load_track_file(path.string());
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(field(r, "site"), "Amisb\xC3\xBChl");
  EXPECT_EQ(field(r, "glider_type"), "OZONE Photon");
  EXPECT_EQ(field(r, "recorder"), "samsung SM-S906B 13");
  EXPECT_EQ(field(r, "gps_datum"), "WGS-84");
  EXPECT_EQ(field(r, "competition_class"), "FAI-3");
  EXPECT_EQ(field(r, "pilot"), "<absent>");  // HFPLTPILOTINCHARGE: is empty
  EXPECT_EQ(field(r, "flight_number"), "01");
}

TEST(IgcRealFiles, NoTimeIncrementAndDuplicatesAreKeptAsRecorded) {
  TRAILRAY_REQUIRE_DATA(path, "igc/igclib_no_time_increment.igc");
  auto r = load_track_file(path.string());
  ASSERT_TRUE(r.ok());
  const auto& p = points(r);
  std::size_t same = 0;
  for (std::size_t i = 1; i < p.size(); ++i)
    if (p[i].time == p[i - 1].time) ++same;
  EXPECT_GT(same, 0u);
}

TEST(IgcRealFiles, CutCopyOfARealFile) {
  TRAILRAY_REQUIRE_DATA(path, "igc/goigc_0100_interlaken.igc");
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t b500 = [&] {
    std::size_t pos = 0;
    for (int i = 0; i < 500; ++i) pos = text.find("\nB", pos) + 1;
    return pos;
  }();
  const std::string cut = text.substr(0, b500 + 20);  // inside the 500th B record
  auto r = read(cut);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(points(r).size(), 499u);
  EXPECT_TRUE(has_warning(r, "file ends inside a record"));
}

TEST(IgcReader, FlightIsNamedByDateAndSiteNotPilot) {
  auto src = ByteSource::from_memory(
      "AXCT123\r\nHFDTEDATE:140724,01\r\nHFPLTPILOTINCHARGE:Jane Doe\r\nHOSITSite:Amisb\xC3\xBChl\r\n"
      "B1200004642850N00749446EA0159401594\r\n",
      "named.igc");
  ReadResult r = read_igc(*src, {});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.file.tracks.at(0).name, "Flight 2024-07-14 from Amisb\xC3\xBChl");
}

TEST(IgcReader, APlaceholderSiteIsLeftOutOfTheNameAndKeptInTheHeader) {
  for (const char* site : {"None", "?", " NIL ", "n/a", "---", "Unknown"}) {
    auto src = ByteSource::from_memory(std::string("AXCT123\r\nHFDTEDATE:140724,01\r\nHFSITSite:") + site +
                                           "\r\nB1200004642850N00749446EA0159401594\r\n",
                                       "placeholder.igc");
    ReadResult r = read_igc(*src, {});
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.file.tracks.at(0).name, "Flight 2024-07-14") << site;
    bool kept = false;
    for (const auto& [key, value] : r.file.metadata.fields) kept = kept || key == "site";
    EXPECT_TRUE(kept) << site;
  }
  // A site that only looks short is a site.
  auto src = ByteSource::from_memory(
      "AXCT123\r\nHFDTEDATE:140724,01\r\nHFSITSite:Na Kopci\r\nB1200004642850N00749446EA0159401594\r\n", "k.igc");
  EXPECT_EQ(read_igc(*src, {}).file.tracks.at(0).name, "Flight 2024-07-14 from Na Kopci");
}
