// The OpenAir reader: arcs and circles at the right distance from their centre, DA vs DB, the
// V D= direction, the shared real and edge-case files, encodings, and broken input as FILE:LINE.
#include <gtest/gtest.h>

#include <GeographicLib/Geodesic.hpp>
#include <cmath>
#include <numbers>
#include <set>

#include "test_support.hpp"
#include "track/airspace/arc_geometry.hpp"
#include "track/airspace/openair_reader.hpp"

using namespace trailray::track::airspace;
using trailray::geo::LatLon;

namespace {

AirspaceReadResult read(const std::string& text, trailray::track::ReadOptions options = {}) {
  return read_openair(text, "test.txt", options);
}

double distance_m(LatLon a, LatLon b) {
  double d = 0, azi = 0;
  geodesic_inverse(a, b, d, azi);
  return d;
}

double azimuth_deg(LatLon a, LatLon b) {
  double d = 0, azi = 0;
  geodesic_inverse(a, b, d, azi);
  return azi < 0 ? azi + 360 : azi;
}

// Every vertex at `radius_m` from `centre`, and every chord's midpoint at most 1 m inside
// (kMaxChordErrorM, plus the midpoint's own flat-earth error, far below a millimetre here).
void expect_on_circle(const std::vector<LatLon>& points, LatLon centre, double radius_m) {
  ASSERT_GE(points.size(), 3u);
  double worst_sag = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_NEAR(distance_m(centre, points[i]), radius_m, 1e-6);
    if (i + 1 < points.size()) {
      const LatLon mid{(points[i].lat + points[i + 1].lat) / 2, (points[i].lon + points[i + 1].lon) / 2};
      worst_sag = std::max(worst_sag, radius_m - distance_m(centre, mid));
    }
  }
  EXPECT_LE(worst_sag, kMaxChordErrorM + 0.01);
  EXPECT_GT(worst_sag, 0.1);  // the step is not needlessly small either
}

}  // namespace

TEST(OpenAirGeometry, CircleVerticesAtTheRadiusChordsWithinOneMetre) {
  const auto r = read("AC R\nAN Circle\nAL GND\nAH 2000 ft\nV X=47:00:00 N 008:00:00 E\nDC 5\n");
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  ASSERT_EQ(r.file.airspaces.size(), 1u);
  auto ring = r.file.airspaces[0].boundary;
  ring.push_back(ring.front());
  expect_on_circle(ring, {47, 8}, 5 * 1852.0);
  EXPECT_NEAR(azimuth_deg({47, 8}, ring[0]), 0.0, 1e-6);  // starts due north
}

TEST(OpenAirGeometry, ArcStepFollowsTheChordError) {
  EXPECT_DOUBLE_EQ(arc_step_deg(100.0), kMaxArcStepDeg);
  const double step = arc_step_deg(100000.0);
  EXPECT_NEAR(100000.0 * (1 - std::cos(step * std::numbers::pi / 360.0)), kMaxChordErrorM, 1e-6);
}

TEST(OpenAirGeometry, DirectionOfDaArcs) {
  // From the XCSoar edge-case file: V D=- DA 15,185,155 runs counter-clockwise from 185 to 155.
  const auto r =
      read("AC C\nAN Arc-Test\nAL 1000 ft\nAH 2000 ft\nV X=01:00:00 N 001:00:00 E\nV D=-\nDA 15, 185, 155\n");
  ASSERT_TRUE(r.ok());
  const auto& ring = r.file.airspaces[0].boundary;
  const LatLon c{1, 1};
  EXPECT_NEAR(azimuth_deg(c, ring.front()), 185.0, 1e-6);
  EXPECT_NEAR(azimuth_deg(c, ring.back()), 155.0, 1e-6);
  EXPECT_LT(azimuth_deg(c, ring[1]), 185.0);  // counter-clockwise: the azimuth goes down
  expect_on_circle(ring, c, 15 * 1852.0);
  double previous = 186;
  for (const auto& p : ring) {
    const double a = azimuth_deg(c, p);
    EXPECT_LT(a, previous);
    previous = a;
  }

  const auto cw = read("AC C\nAN X\nAL 0\nAH 1000\nV X=01:00:00 N 001:00:00 E\nV D=+\nDA 15, 185, 155\n");
  ASSERT_TRUE(cw.ok());
  // Clockwise from 185 to 155 is the long way round: 330 degrees.
  EXPECT_GT(cw.file.airspaces[0].boundary.size(), 10 * ring.size());
}

TEST(OpenAirGeometry, DaAndDbDescribeTheSameArc) {
  const LatLon c{46.5, 7.5};
  const LatLon a = geodesic_destination(c, 90, 10 * 1852.0), b = geodesic_destination(c, 200, 10 * 1852.0);
  auto dms = [](double v, char pos, char neg) {
    const char h = v >= 0 ? pos : neg;
    v = std::abs(v);
    return std::to_string(int(v)) + ":" + std::to_string((v - int(v)) * 60.0) + " " + h;
  };
  const std::string head = "AC R\nAN X\nAL GND\nAH FL100\nV X=46:30:00 N 007:30:00 E\n";
  const auto da = read(head + "DA 10,90,200\n");
  const auto db = read(head + "DB " + dms(a.lat, 'N', 'S') + " " + dms(a.lon, 'E', 'W') + ", " + dms(b.lat, 'N', 'S') +
                       " " + dms(b.lon, 'E', 'W') + "\n");
  ASSERT_TRUE(da.ok());
  ASSERT_TRUE(db.ok()) << db.error->to_string();
  const auto& x = da.file.airspaces[0].boundary;
  const auto& y = db.file.airspaces[0].boundary;
  ASSERT_EQ(x.size(), y.size());
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_LT(distance_m(x[i], y[i]), 0.01) << i;
}

TEST(OpenAirReader, EdgeCaseFileEveryClass) {
  TRAILRAY_REQUIRE_DATA(path, "airspace/xcsoar_openair.txt");
  const auto r = load_openair_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front().to_string();
  ASSERT_EQ(r.file.airspaces.size(), 26u);
  std::set<std::string> classes;
  for (const auto& a : r.file.airspaces) classes.insert(a.airspace_class);
  for (const char* c : {"A", "B", "C", "D", "E", "F", "G", "CTR", "R", "Q", "P", "GP", "W", "TMZ", "RMZ"})
    EXPECT_TRUE(classes.count(c)) << c;
  int unlimited = 0, ground = 0, std_levels = 0, agl = 0;
  for (const auto& a : r.file.airspaces) {
    for (const auto* l : {&a.floor, &a.ceiling}) {
      unlimited += l->reference == AltitudeReference::Unlimited;
      ground += l->is_ground();
      std_levels += l->reference == AltitudeReference::Std;
      agl += l->reference == AltitudeReference::Agl && !l->is_ground();
    }
  }
  EXPECT_GE(unlimited, 2);   // UNLIM, UNLIMITED
  EXPECT_GE(ground, 1);      // SFC
  EXPECT_GE(std_levels, 2);  // FL 65, 5000 STD
  EXPECT_GE(agl, 3);         // 100 Agl, 100m GND, 50 GND
  const auto& polygon = r.file.airspaces[4];
  EXPECT_EQ(polygon.name, "Polygon-Test");
  EXPECT_EQ(polygon.boundary.size(), 4u);
}

TEST(OpenAirReader, SwissAndGermanFilesReadWithoutErrors) {
  TRAILRAY_REQUIRE_DATA(swiss, "airspace/openairrs_Switzerland.txt");
  TRAILRAY_REQUIRE_DATA(german, "airspace/openairrs_Germany.txt");
  const auto ch = load_openair_file(swiss.string());
  ASSERT_TRUE(ch.ok()) << ch.error->to_string();
  EXPECT_TRUE(ch.warnings.empty()) << ch.warnings.front().to_string();
  EXPECT_EQ(ch.file.airspaces.size(), 334u);
  EXPECT_EQ(ch.file.airspaces.front().name, "ALPNACH CTR 128.475");
  EXPECT_EQ(ch.file.airspaces.front().airspace_class, "D");
  int ground_floors = 0, agl = 0;
  for (const auto& a : ch.file.airspaces) {
    ground_floors += a.floor.is_ground();
    agl += (a.floor.reference == AltitudeReference::Agl && !a.floor.is_ground()) +
           (a.ceiling.reference == AltitudeReference::Agl && !a.ceiling.is_ground());
  }
  EXPECT_EQ(ground_floors, 190);  // "AL GND" lines in the file
  EXPECT_EQ(agl, 9);              // "ft AGL" limits
  const auto de = load_openair_file(german.string());
  ASSERT_TRUE(de.ok()) << de.error->to_string();
  EXPECT_EQ(de.file.airspaces.size(), 677u);
  ASSERT_EQ(de.warnings.size(), 1u);  // only the note that it was read as Latin-1
  EXPECT_NE(de.warnings[0].message.find("Latin-1"), std::string::npos);
  for (const auto& a : de.file.airspaces) EXPECT_GE(a.boundary.size(), 3u) << a.name;
}

TEST(OpenAirReader, Latin1NamesBecomeUtf8AndBomAndCrlfAreAccepted) {
  const auto latin1 = read(
      "AC R\r\nAN M\xFCnchen\r\nAL GND\r\nAH FL100\r\nDP 1:0:0 N 1:0:0 E\r\nDP 1:0:0 N 2:0:0 E\r\nDP 2:0:0 N 2:0:0 "
      "E\r\n");
  ASSERT_TRUE(latin1.ok());
  EXPECT_EQ(latin1.file.airspaces[0].name, "M\xC3\xBCnchen");
  const auto bom = read(
      "\xEF\xBB\xBF"
      "AC R\r\nAN M\xC3\xBCnchen\r\nAL GND\r\nAH FL100\r\nDP 1:0:0 N 1:0:0 E\r\nDP 1:0:0 N 2:0:0 E\r\nDP 2:0:0 N 2:0:0 "
      "E\r\n");
  ASSERT_TRUE(bom.ok());
  EXPECT_TRUE(bom.warnings.empty());
  EXPECT_EQ(bom.file.airspaces[0].name, "M\xC3\xBCnchen");
  EXPECT_EQ(bom.file.airspaces[0].airspace_class, "R");
}

TEST(OpenAirReader, BrokenInputNamesFileAndLine) {
  struct Case {
    const char* text;
    int line;
    const char* words;
  } cases[] = {
      {"AC R\nAN X\nAL GND\nDP 91:00:00 N 001:00:00 E\n", 4, "DP"},
      {"AC R\nAN X\nAL somewhere\n", 3, "AL"},
      {"AC R\nAN X\n\nDC 5\n", 4, "V X="},
      {"AC R\nV X=1:0:0 N 1:0:0 E\nDC -5\n", 3, "radius"},
      {"AC R\nV X=1:0:0 N 1:0:0 E\nDA 5, 10\n", 3, "DA"},
      {"AC R\nV X=1:0:0 N 1:0:0 E\nDB 1:0:0 N 1:1:0 E\n", 3, "DB"},
      {"AC R\nV D=x\n", 2, "direction"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    const auto r = read(c.text);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error->position.line, c.line);
    EXPECT_EQ(r.error->to_string().rfind("test.txt:" + std::to_string(c.line) + ":", 0), 0u) << r.error->to_string();
    EXPECT_NE(r.error->message.find(c.words), std::string::npos) << r.error->message;
  }
}

TEST(OpenAirReader, UnknownRecordsAreWarnedAndCountedKnownOnesAccepted) {
  const std::string text =
      "AC R\nAN X\nAR 130.125 MHz\nAY TMZ\nSP 0,1,0,0,0\nZZ one\nAL GND\nAH 1000 ft\nZZ two\nQQ\n"
      "DP 1:0:0 N 1:0:0 E\nDP 1:0:0 N 2:0:0 E\nDP 2:0:0 N 2:0:0 E\n";
  const auto r = read(text);
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.warnings.size(), 2u);  // ZZ (twice, one line) and QQ
  EXPECT_NE(r.warnings[0].message.find("'ZZ'"), std::string::npos);
  EXPECT_NE(r.warnings[0].message.find("2 times"), std::string::npos) << r.warnings[0].message;
  EXPECT_EQ(r.warnings[0].position.line, 6);
  trailray::track::ReadOptions strict;
  strict.strict = true;
  EXPECT_FALSE(read(text, strict).ok());
}

TEST(OpenAirReader, TwoPointLinesAreKeptOneIsSkipped) {
  const auto r = read(
      "AC Q\nAN Cable\nAL 6627 ft\nAH 6627 ft\nDP 47:14:18 N 009:24:49 E\nDP 47:14:13 N 009:24:42 E\n"
      "AC Q\nAN Dot\nAL GND\nAH 100 ft\nDP 47:14:18 N 009:24:49 E\n");
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.file.airspaces.size(), 1u);
  EXPECT_EQ(r.file.airspaces[0].name, "Cable");
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].position.line, 7);
}

TEST(OpenAirReader, ReadAsLenientlyAsXCSoar) {
  // Seconds and minutes of 60 carry over; lower-case keywords and tabs; limits given twice (the
  // later wins, warned); an airspace that cannot be used is skipped naming its line, the others kept.
  const auto r = read(
      "AC R\nAN Sixty\nAL GND\nAH FL100\nDP 42:00:60 N 001:00:60 W\nDP 42:59:60 N 001:01:00 W\nDP 42:10:00 N 001:10:00 W\n"
      "ac q\n an\tLower\nal\t1000 ft\nah 2000 ft\nAH 3000 ft\ndp 45:00:00 N 006:00:00 E\ndp 45:01:00 N 006:00:00 E\n"
      "dp 45:01:00 N 006:01:00 E\n"
      "AC R\nAN Broken\nAL GND\nAH FL100\nDP 46:00:00 N 007:00:00 E\nDP 96:00:00 N 007:00:00 E\nDP 46:01:00 N 007:01:00 E\n"
      "AC D\nAN After\nAL GND\nAH FL50\nV X=47:00:00 N 008:00:00 E\nDC 2\n");
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  ASSERT_EQ(r.file.airspaces.size(), 3u);
  EXPECT_EQ(r.file.airspaces[0].name, "Sixty");
  EXPECT_NEAR(r.file.airspaces[0].boundary[0].lat, 42 + 1 / 60.0, 1e-12);  // 42:00:60 is 42:01:00
  EXPECT_NEAR(r.file.airspaces[0].boundary[0].lon, -(1 + 1 / 60.0), 1e-12);
  EXPECT_NEAR(r.file.airspaces[0].boundary[1].lat, 43.0, 1e-12);  // 42:59:60 is 43:00:00
  EXPECT_EQ(r.file.airspaces[1].name, "Lower");
  EXPECT_EQ(r.file.airspaces[1].airspace_class, "q");
  EXPECT_NEAR(r.file.airspaces[1].ceiling.metres, 3000 * 0.3048, 1e-9);
  EXPECT_EQ(r.file.airspaces[2].name, "After");
  bool twice = false, skipped = false;
  for (const auto& w : r.warnings) {
    if (w.message.find("AH given twice") != std::string::npos) twice = w.position.line == 12;
    if (w.message.find("Broken (from line 16) skipped") != std::string::npos)
      skipped = w.position.line == 21 && w.message.find("DP") != std::string::npos;
  }
  EXPECT_TRUE(twice);
  EXPECT_TRUE(skipped);
  // Beyond 60 is still no coordinate; a file with nothing usable is an error, and so is one with
  // no airspace at all.
  EXPECT_FALSE(read("AC R\nAL GND\nAH FL1\nDP 42:00:61 N 001:00:00 W\nDP 42:00:00 N 001:00:00 W\n").ok());
  const auto none = read("* only a comment\n");
  ASSERT_FALSE(none.ok());
  EXPECT_NE(none.error->message.find("no airspace"), std::string::npos);
}

TEST(OpenAirReader, TnpFilesAreReadToo) {
  // XCSoar's other format: classes from TYPE= or CLASS=, limits as OpenAir writes them, points,
  // circles and arcs; INCLUDE=NO leaves out what follows.
  const auto r = read(
      "INCLUDE=YES\n# comment\nTITLE=Circle\nTYPE=C\nBASE=1000 ft\nTOPS=FL 65\n"
      "CIRCLE RADIUS=5 CENTRE=N010530 E0000530\n"
      "TYPE=R\nTITLE=Square\nBASE=SFC\nTOPS=UNLIM\nPOINT=N013030 W0013030\nPOINT=N013030 E0013030\n"
      "POINT=S013030 E0013030\nCLOCKWISE RADIUS=10 CENTRE=S013030 W0003030 TO=S013030 W0013030\n"
      "INCLUDE=NO\nTITLE=Left out\nTYPE=C\nCIRCLE RADIUS=5 CENTRE=N010530 E0000530\nINCLUDE=YES\n"
      "TITLE=Class A\nTYPE=\nCLASS=A\nBASE=100m GND\nTOPS=450m\nCIRCLE RADIUS=2 CENTRE=N470000.5 E0080000\nEND\n");
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  ASSERT_EQ(r.file.airspaces.size(), 3u);
  const auto& circle = r.file.airspaces[0];
  EXPECT_EQ(circle.name, "Circle");
  EXPECT_EQ(circle.airspace_class, "CTR");
  EXPECT_NEAR(circle.ceiling.metres, 6500 * 0.3048, 1e-9);
  EXPECT_GT(circle.boundary.size(), 100u);
  const auto& square = r.file.airspaces[1];
  EXPECT_EQ(square.airspace_class, "R");
  EXPECT_EQ(square.ceiling.reference, AltitudeReference::Unlimited);
  EXPECT_NEAR(square.boundary[0].lat, 1 + 30 / 60.0 + 30 / 3600.0, 1e-12);
  EXPECT_NEAR(square.boundary[0].lon, -(1 + 30 / 60.0 + 30 / 3600.0), 1e-12);
  EXPECT_GT(square.boundary.size(), 10u);  // three points and an arc back
  EXPECT_NEAR(square.boundary.back().lon, -(1 + 30 / 60.0 + 30 / 3600.0), 1e-12);
  EXPECT_EQ(r.file.airspaces[2].name, "Class A");
  EXPECT_EQ(r.file.airspaces[2].airspace_class, "A");
  EXPECT_EQ(r.file.airspaces[2].floor.reference, AltitudeReference::Agl);
  const auto bad = read("TITLE=X\nTYPE=C\nPOINT=N01 E002\nPOINT=N013030 E0013030\n");
  ASSERT_FALSE(bad.ok());  // its only airspace has an unreadable point
  EXPECT_EQ(bad.error->position.line, 3);
}
