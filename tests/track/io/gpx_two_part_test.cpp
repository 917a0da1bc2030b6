// A big GPX file is read in two halves on two threads. Whatever the file, the result must be
// the one a single pass gives: same points, same warnings at the same lines, same errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "test_support.hpp"
#include "track/io/load.hpp"
#include "track/io/readers.hpp"

using namespace trailray::track;

namespace {

ReadOptions in_halves() {
  ReadOptions o;
  o.two_part_min_bytes = 1;  // every file big enough
  return o;
}

ReadResult one_pass(const std::string& content, const std::string& name) {
  auto src = ByteSource::from_memory(content, name);  // no random access: one pass
  return read_gpx(*src, ReadOptions{});
}

void expect_same(const ReadResult& a, const ReadResult& b, const std::string& what) {
  ASSERT_EQ(a.ok(), b.ok()) << what;
  if (!a.ok()) {
    EXPECT_EQ(a.error->to_string(), b.error->to_string()) << what;
  }
  ASSERT_EQ(a.warnings.size(), b.warnings.size()) << what;
  for (std::size_t i = 0; i < a.warnings.size(); ++i)
    EXPECT_EQ(a.warnings[i].to_string(), b.warnings[i].to_string()) << what;
  if (!a.ok()) return;
  const TrackFile& x = a.file;
  const TrackFile& y = b.file;
  EXPECT_EQ(x.metadata.name, y.metadata.name) << what;
  EXPECT_EQ(x.metadata.creator, y.metadata.creator) << what;
  ASSERT_EQ(x.tracks.size(), y.tracks.size()) << what;
  for (std::size_t t = 0; t < x.tracks.size(); ++t) {
    EXPECT_EQ(x.tracks[t].name, y.tracks[t].name) << what;
    ASSERT_EQ(x.tracks[t].segments.size(), y.tracks[t].segments.size()) << what << " track " << t;
    for (std::size_t s = 0; s < x.tracks[t].segments.size(); ++s) {
      const auto& p = x.tracks[t].segments[s].points;
      const auto& q = y.tracks[t].segments[s].points;
      ASSERT_EQ(p.size(), q.size()) << what << " track " << t << " segment " << s;
      for (std::size_t i = 0; i < p.size(); ++i) {
        ASSERT_EQ(p[i].lat, q[i].lat) << what << " point " << i;
        ASSERT_EQ(p[i].lon, q[i].lon) << what << " point " << i;
        ASSERT_TRUE(p[i].ele == q[i].ele || (std::isnan(p[i].ele) && std::isnan(q[i].ele))) << what;
        ASSERT_TRUE(p[i].time == q[i].time || (std::isnan(p[i].time) && std::isnan(q[i].time))) << what;
        ASSERT_TRUE(p[i].heart_rate == q[i].heart_rate || (std::isnan(p[i].heart_rate) && std::isnan(q[i].heart_rate)));
      }
    }
  }
  EXPECT_EQ(x.routes.size(), y.routes.size()) << what;
  EXPECT_EQ(x.waypoints.size(), y.waypoints.size()) << what;
}

enum class Path { Halves, OnePass };

// Reads `content` both ways and compares; `expected` says whether the halves must join.
void check(const std::string& content, const std::string& what, Path expected = Path::Halves) {
  trailray::test::TempFile f("t.gpx", content);
  std::string error;
  auto source = ByteSource::open(f.str(), error);
  ASSERT_TRUE(source) << error;
  std::optional<ReadResult> halves = read_gpx_in_halves(*source, in_halves());
  EXPECT_EQ(halves.has_value(), expected == Path::Halves) << what;
  ReadResult whole = one_pass(content, f.str());
  expect_same(halves ? *halves : load_track_file(f.str(), in_halves()), whole, what);
}

std::string points(int from, int to, int lat_base = 46) {
  std::ostringstream s;
  for (int i = from; i < to; ++i)
    s << "      <trkpt lat=\"" << lat_base << "." << (100000 + i) << "\" lon=\"7." << (200000 + i) << "\">\n"
      << "        <ele>" << (1000 + i % 97) << ".5</ele>\n        <time>2024-06-01T10:" << (10 + i / 60 % 50) << ":"
      << (10 + i % 50) << "Z</time>\n        <extensions><gpxtpx:TrackPointExtension><gpxtpx:hr>" << (90 + i % 40)
      << "</gpxtpx:hr></gpxtpx:TrackPointExtension></extensions>\n      </trkpt>\n";
  return s.str();
}

std::string document(const std::string& body) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<gpx version=\"1.1\" creator=\"test\">\n"
         "  <metadata><name>Two parts</name></metadata>\n" +
         body + "</gpx>\n";
}

}  // namespace

TEST(GpxTwoPart, SeveralTracksAndSegmentsJoinAsOnePass) {
  std::string body = "  <trk><name>A</name>\n    <trkseg>\n" + points(0, 300) + "    </trkseg>\n    <trkseg>\n" +
                     points(300, 700) + "    </trkseg>\n  </trk>\n  <trk><name>B</name><trkseg>\n" + points(700, 900) +
                     "  </trkseg></trk>\n  <wpt lat=\"46\" lon=\"7\"><name>end</name></wpt>\n";
  check(document(body), "tracks and segments");
}

TEST(GpxTwoPart, WarningsInBothHalvesKeepTheirLinesAndCounts) {
  std::string second = points(500, 1000);
  second.replace(second.find("lat=\"46.100800\""), 15, "lat=\"96.100800\"");
  std::string first = points(0, 500);
  first.replace(first.find("lat=\"46.100010\""), 15, "lat=\"NaN\"");
  check(document("  <trk><trkseg>\n" + first + second + "  </trkseg></trk>\n"), "bad coordinates");
  trailray::test::TempFile f("w.gpx", document("  <trk><trkseg>\n" + first + second + "  </trkseg></trk>\n"));
  ReadResult r = load_track_file(f.str(), in_halves());
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].message.find("2 times"), std::string::npos) << r.warnings[0].message;
}

TEST(GpxTwoPart, AnErrorInTheSecondHalfIsNamedAtItsLine) {
  std::string second = points(500, 1000);
  second.replace(second.find("</ele>", second.size() / 2), 6, "</elf>");
  check(document("  <trk><trkseg>\n" + points(0, 500) + second + "  </trkseg></trk>\n"), "mismatched tag");
}

TEST(GpxTwoPart, ACutFileKeepsTheSamePointsAndWarning) {
  std::string doc = document("  <trk><trkseg>\n" + points(0, 1000) + "  </trkseg></trk>\n");
  doc.resize(doc.size() * 3 / 4);
  check(doc, "cut");
}

TEST(GpxTwoPart, AFalseSplitFallsBackToOnePass) {
  // "<trkpt " inside a comment and inside CDATA right after the middle, and prefixed names.
  std::string tricky;
  for (int i = 0; i < 3000; ++i)
    tricky += "  <!-- <trkpt lat=\"1\" lon=\"2\"> -->\n  <desc><![CDATA[ <trkpt > ]]></desc>\n";
  check(document("  <trk><trkseg>\n" + points(0, 200) + "  </trkseg></trk>\n  <rte>\n" + tricky + "  </rte>\n"),
        "comment and CDATA", Path::OnePass);
  std::string prefixed = document("  <trk><trkseg>\n" + points(0, 600) + "  </trkseg></trk>\n");
  for (const char* tag : {"gpx", "trk", "trkseg", "trkpt", "ele", "time"}) {
    for (std::size_t at = 0; (at = prefixed.find(std::string("<") + tag, at)) != std::string::npos; at += 3)
      prefixed.insert(at + 1, "g:");
    for (std::size_t at = 0; (at = prefixed.find(std::string("</") + tag, at)) != std::string::npos; at += 4)
      prefixed.insert(at + 2, "g:");
  }
  check(prefixed, "prefixed names", Path::OnePass);
}

TEST(GpxTwoPartRealData, EveryGpxFileReadsAsInOnePass) {
  TRAILRAY_REQUIRE_DATA(dir, "gpx");
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    std::ifstream in(e.path(), std::ios::binary);
    std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ReadResult halves = load_track_file(e.path().string(), in_halves());
    if (!halves.ok() && !one_pass(content, e.path().string()).ok()) continue;  // both refuse it alike
    expect_same(halves, one_pass(content, e.path().string()), e.path().filename().string());
  }
}
