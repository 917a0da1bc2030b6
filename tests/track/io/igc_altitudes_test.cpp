// IGC reader: both altitudes of a fix are kept, the GNSS or pressure one in `ele` (as
// ReadOptions::igc_altitude picks) and each always in TrackPoint::gnss_altitude and
// TrackPoint::pressure_altitude.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "test_support.hpp"
#include "track/io/byte_source.hpp"
#include "track/io/load.hpp"
#include "track/io/readers.hpp"

using namespace trailray::track;

namespace {

using Alt = ReadOptions::IgcAltitude;

ReadResult read_alt(const std::string& text, Alt alt) {
  ReadOptions o;
  o.igc_altitude = alt;
  auto src = ByteSource::from_memory(text, "test.igc");
  return read_igc(*src, o);
}

const std::vector<TrackPoint>& points(const ReadResult& r) {
  static const std::vector<TrackPoint> kNone;
  if (r.file.tracks.empty() || r.file.tracks[0].segments.empty()) return kNone;
  return r.file.tracks[0].segments[0].points;
}

// A B record at 47N 8E: time HHMMSS, validity, pressure and GNSS altitude (5 characters each).
std::string b(const std::string& time, char validity, const std::string& pressure, const std::string& gnss) {
  return "B" + time + "4700000N00800000E" + std::string(1, validity) + pressure + gnss + "\r\n";
}

std::string igc(const std::string& body) { return "AXCT0123456789abcdef\r\nHFDTE010123\r\n" + body; }

const std::string kBoth =
    igc(b("100000", 'A', "01000", "01100") + b("100001", 'V', "01001", "00000") + b("100002", 'A', "-0012", "01090"));

}  // namespace

TEST(IgcAltitudes, BothChannelsAreKeptWhateverEleHolds) {
  for (Alt alt : {Alt::Auto, Alt::Gnss, Alt::Pressure}) {
    SCOPED_TRACE(static_cast<int>(alt));
    const auto r = read_alt(kBoth, alt);
    const auto& p = points(r);
    ASSERT_EQ(p.size(), 3u);
    EXPECT_EQ(p[0].pressure_altitude, 1000.0f);
    EXPECT_EQ(p[1].pressure_altitude, 1001.0f);
    EXPECT_EQ(p[2].pressure_altitude, -12.0f);
    EXPECT_EQ(p[0].gnss_altitude, 1100.0f);
    EXPECT_FALSE(p[1].has_gnss_altitude());  // a 'V' fix's GNSS 0: no 3D solution
    EXPECT_EQ(p[2].gnss_altitude, 1090.0f);
  }
  // `ele` is the chosen one: GNSS, pressure where a 'V' fix has no GNSS altitude (auto).
  const auto a = read_alt(kBoth, Alt::Auto);
  EXPECT_DOUBLE_EQ(points(a)[0].ele, 1100.0);
  EXPECT_DOUBLE_EQ(points(a)[1].ele, 1001.0);
  EXPECT_DOUBLE_EQ(points(a)[2].ele, 1090.0);
  const auto g = read_alt(kBoth, Alt::Gnss);
  EXPECT_DOUBLE_EQ(points(g)[0].ele, 1100.0);
  EXPECT_FALSE(points(g)[1].has_ele());
  EXPECT_DOUBLE_EQ(points(g)[2].ele, 1090.0);
  const auto p = read_alt(kBoth, Alt::Pressure);
  EXPECT_DOUBLE_EQ(points(p)[0].ele, 1000.0);
  EXPECT_DOUBLE_EQ(points(p)[2].ele, -12.0);
}

TEST(IgcAltitudes, AnAllZeroPressureChannelIsNotRecorded) {
  // A phone without a barometer writes 00000: no pressure altitude, in every mode.
  const std::string no_baro = igc(b("100000", 'A', "00000", "00512") + b("100001", 'A', "00000", "00520"));
  for (Alt alt : {Alt::Auto, Alt::Gnss, Alt::Pressure}) {
    const auto r = read_alt(no_baro, alt);
    ASSERT_EQ(points(r).size(), 2u);
    for (const TrackPoint& q : points(r)) EXPECT_FALSE(q.has_pressure_altitude());
  }
  EXPECT_DOUBLE_EQ(points(read_alt(no_baro, Alt::Auto))[1].ele, 520.0);
}

TEST(IgcAltitudes, AnAllZeroGnssChannelIsNotRecorded) {
  const std::string no_gnss = igc(b("100000", 'A', "00400", "00000") + b("100001", 'A', "00410", "00000"));
  for (Alt alt : {Alt::Auto, Alt::Gnss, Alt::Pressure}) {
    const auto r = read_alt(no_gnss, alt);
    ASSERT_EQ(points(r).size(), 2u);
    for (const TrackPoint& q : points(r)) EXPECT_FALSE(q.has_gnss_altitude());
  }
}

TEST(IgcAltitudes, AVFixWithAGnssAltitudeKeepsItInEveryMode) {
  // The Gnss rule: a 'V' fix's GNSS altitude counts unless it is 0. Auto still draws pressure there.
  const std::string text = igc(b("100000", 'A', "01000", "01100") + b("100001", 'V', "01001", "01105"));
  for (Alt alt : {Alt::Auto, Alt::Gnss, Alt::Pressure}) {
    const auto r = read_alt(text, alt);
    ASSERT_EQ(points(r).size(), 2u);
    EXPECT_EQ(points(r)[1].gnss_altitude, 1105.0f);
    EXPECT_EQ(points(r)[1].pressure_altitude, 1001.0f);
  }
  EXPECT_DOUBLE_EQ(points(read_alt(text, Alt::Auto))[1].ele, 1001.0);
  EXPECT_DOUBLE_EQ(points(read_alt(text, Alt::Gnss))[1].ele, 1105.0);
}

TEST(IgcAltitudes, ASingleGnssZeroOnAnAFixIsSeaLevel) {
  const auto r = read_alt(igc(b("100000", 'A', "00100", "00010") + b("100001", 'A', "00090", "00000")), Alt::Pressure);
  ASSERT_EQ(points(r).size(), 2u);
  EXPECT_EQ(points(r)[1].gnss_altitude, 0.0f);
  EXPECT_DOUBLE_EQ(points(r)[1].ele, 90.0);
}

TEST(IgcAltitudes, ASinglePressureZeroInARecordedChannelIsSeaLevel) {
  const auto r = read_alt(igc(b("100000", 'A', "00010", "00100") + b("100001", 'A', "00000", "00090")), Alt::Gnss);
  ASSERT_EQ(points(r).size(), 2u);
  EXPECT_EQ(points(r)[1].pressure_altitude, 0.0f);
}

TEST(IgcAltitudes, OnlyPressureRecordedLeavesGnssModeWithoutElevationButKeepsPressure) {
  const auto r = read_alt(igc(b("100000", 'A', "00400", "00000")), Alt::Gnss);
  ASSERT_EQ(points(r).size(), 1u);
  EXPECT_FALSE(points(r)[0].has_ele());
  EXPECT_EQ(points(r)[0].pressure_altitude, 400.0f);
}

TEST(IgcAltitudes, OnlyGnssRecordedLeavesPressureModeWithoutElevationButKeepsGnss) {
  const auto r = read_alt(igc(b("100000", 'A', "00000", "00512")), Alt::Pressure);
  ASSERT_EQ(points(r).size(), 1u);
  EXPECT_FALSE(points(r)[0].has_ele());
  EXPECT_EQ(points(r)[0].gnss_altitude, 512.0f);
}

TEST(IgcAltitudes, OtherFormatsHaveNoIgcAltitudes) {
  auto src = ByteSource::from_memory(
      "<gpx version=\"1.1\"><trk><trkseg><trkpt lat=\"47\" lon=\"8\"><ele>500</ele></trkpt></trkseg></trk></gpx>",
      "t.gpx");
  const auto r = read_gpx(*src, {});
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(points(r).size(), 1u);
  EXPECT_FALSE(points(r)[0].has_pressure_altitude());
  EXPECT_FALSE(points(r)[0].has_gnss_altitude());
}

// Every real IGC file: the pressure altitudes kept in auto mode are exactly the elevations that
// --igc-altitude pressure gives, fix by fix; none where the file has no barometer.
TEST(IgcAltitudesRealFiles, PressureAltitudeIsThePressureModesElevation) {
  TRAILRAY_REQUIRE_DATA(dir, "igc");
  std::size_t files = 0, with_baro = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string ext = e.path().extension().string();
    if (ext != ".igc" && ext != ".IGC") continue;
    SCOPED_TRACE(e.path().filename().string());
    ++files;
    ReadOptions pressure;
    pressure.igc_altitude = Alt::Pressure;
    const auto a = load_track_file(e.path().string());
    const auto p = load_track_file(e.path().string(), pressure);
    ASSERT_TRUE(a.ok() && p.ok());
    const auto& pa = points(a);
    const auto& pp = points(p);
    ASSERT_EQ(pa.size(), pp.size());
    bool any = false;
    for (std::size_t i = 0; i < pa.size(); ++i) {
      if (pp[i].has_ele()) {
        ASSERT_EQ(static_cast<double>(pa[i].pressure_altitude), pp[i].ele) << "fix " << i;
        any = true;
      } else {
        ASSERT_FALSE(pa[i].has_pressure_altitude()) << "fix " << i;
      }
      // The chosen altitude does not change the pressure channel.
      ASSERT_EQ(pa[i].has_pressure_altitude(), pp[i].has_pressure_altitude());
    }
    with_baro += any ? 1 : 0;
  }
  EXPECT_GT(files, 10u);
  EXPECT_GT(with_baro, 5u);
}

// Likewise the GNSS altitudes kept in pressure mode are exactly the elevations of
// --igc-altitude gnss, fix by fix, and auto keeps the same.
TEST(IgcAltitudesRealFiles, GnssAltitudeIsTheGnssModesElevation) {
  TRAILRAY_REQUIRE_DATA(dir, "igc");
  std::size_t files = 0, with_gnss = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string ext = e.path().extension().string();
    if (ext != ".igc" && ext != ".IGC") continue;
    SCOPED_TRACE(e.path().filename().string());
    ++files;
    ReadOptions pressure, gnss;
    pressure.igc_altitude = Alt::Pressure;
    gnss.igc_altitude = Alt::Gnss;
    const auto p = load_track_file(e.path().string(), pressure);
    const auto g = load_track_file(e.path().string(), gnss);
    const auto a = load_track_file(e.path().string());
    ASSERT_TRUE(p.ok() && g.ok() && a.ok());
    const auto& pp = points(p);
    const auto& pg = points(g);
    const auto& pa = points(a);
    ASSERT_EQ(pp.size(), pg.size());
    ASSERT_EQ(pa.size(), pg.size());
    bool any = false;
    for (std::size_t i = 0; i < pp.size(); ++i) {
      if (pg[i].has_ele()) {
        ASSERT_EQ(static_cast<double>(pp[i].gnss_altitude), pg[i].ele) << "fix " << i;
        any = true;
      } else {
        ASSERT_FALSE(pp[i].has_gnss_altitude()) << "fix " << i;
      }
      // The chosen altitude does not change the GNSS channel.
      ASSERT_EQ(pa[i].has_gnss_altitude(), pp[i].has_gnss_altitude()) << "fix " << i;
      if (pp[i].has_gnss_altitude()) {
        ASSERT_EQ(pa[i].gnss_altitude, pp[i].gnss_altitude) << "fix " << i;
      }
    }
    with_gnss += any ? 1 : 0;
  }
  EXPECT_GT(files, 10u);
  EXPECT_GT(with_gnss, 5u);
}

TEST(IgcAltitudesRealFiles, InterlakenHasBothAltitudes) {
  TRAILRAY_REQUIRE_DATA(path, "igc/goigc_0100_interlaken.igc");
  const auto r = load_track_file(path.string());
  ASSERT_TRUE(r.ok());
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 1149u);
  double gnss_lo = 1e9, gnss_hi = -1e9, baro_lo = 1e9, baro_hi = -1e9;
  for (const TrackPoint& q : p) {
    ASSERT_TRUE(q.has_ele());
    ASSERT_TRUE(q.has_pressure_altitude());
    gnss_lo = std::min(gnss_lo, q.ele);
    gnss_hi = std::max(gnss_hi, q.ele);
    baro_lo = std::min(baro_lo, static_cast<double>(q.pressure_altitude));
    baro_hi = std::max(baro_hi, static_cast<double>(q.pressure_altitude));
  }
  // The ranges of MANIFEST.md: GNSS 568..1596 m, pressure 486..1462 m.
  EXPECT_EQ(gnss_lo, 568.0);
  EXPECT_EQ(gnss_hi, 1596.0);
  EXPECT_EQ(baro_lo, 486.0);
  EXPECT_EQ(baro_hi, 1462.0);
}

// `--igc-altitude pressure` draws the pressure altitude and still keeps the GNSS one, with the
// ranges of MANIFEST.md.
TEST(IgcAltitudesRealFiles, InterlakenInPressureModeKeepsTheGnssAltitude) {
  TRAILRAY_REQUIRE_DATA(path, "igc/goigc_0100_interlaken.igc");
  ReadOptions pressure;
  pressure.igc_altitude = Alt::Pressure;
  const auto r = load_track_file(path.string(), pressure);
  ASSERT_TRUE(r.ok());
  const auto& p = points(r);
  ASSERT_EQ(p.size(), 1149u);
  double gnss_lo = 1e9, gnss_hi = -1e9, ele_lo = 1e9, ele_hi = -1e9;
  for (const TrackPoint& q : p) {
    ASSERT_TRUE(q.has_gnss_altitude());
    ASSERT_EQ(q.ele, static_cast<double>(q.pressure_altitude));
    gnss_lo = std::min(gnss_lo, static_cast<double>(q.gnss_altitude));
    gnss_hi = std::max(gnss_hi, static_cast<double>(q.gnss_altitude));
    ele_lo = std::min(ele_lo, q.ele);
    ele_hi = std::max(ele_hi, q.ele);
  }
  EXPECT_EQ(gnss_lo, 568.0);
  EXPECT_EQ(gnss_hi, 1596.0);
  EXPECT_EQ(ele_lo, 486.0);
  EXPECT_EQ(ele_hi, 1462.0);
}
