// Conformance with gpsbabel (a declared dependency, scripts/setup.sh): every FIT file of
// ../shared/data/fit read by trailray and by `gpsbabel -i garmin_fit -o gpx` gives the same
// points in the same order: positions to 1e-7 degree, times to the second, elevations and
// speeds to gpsbabel's printed precision. Also against the expected GPX files that come from
// gpsbabel's own test suite.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "fit_test_support.hpp"
#include "test_support.hpp"
#include "track/io/load.hpp"

namespace trailray::test::fit {
namespace {

struct Flat {
  std::vector<track::TrackPoint> points;
  std::vector<std::size_t> segment_starts;  // index of each segment's first point
};

Flat flatten(const track::TrackFile& f) {
  Flat out;
  for (const auto& t : f.tracks)
    for (const auto& s : t.segments) {
      if (s.points.empty()) continue;
      out.segment_starts.push_back(out.points.size());
      out.points.insert(out.points.end(), s.points.begin(), s.points.end());
    }
  return out;
}

void expect_same_points(const track::TrackFile& ours, const track::TrackFile& theirs) {
  const Flat a = flatten(ours), b = flatten(theirs);
  ASSERT_EQ(a.points.size(), b.points.size());
  // gpsbabel starts a segment where the activity timer restarts after a stop, as we do
  EXPECT_EQ(a.segment_starts, b.segment_starts);
  std::size_t bad = 0;
  for (std::size_t i = 0; i < a.points.size() && bad < 5; ++i) {
    const auto &p = a.points[i], &q = b.points[i];
    const bool same = std::fabs(p.lat - q.lat) <= 1e-7 && std::fabs(p.lon - q.lon) <= 1e-7 &&
                      p.has_time() == q.has_time() && (!p.has_time() || p.time == q.time) &&
                      p.has_ele() == q.has_ele() && (!p.has_ele() || std::fabs(p.ele - q.ele) <= 0.0005) &&
                      std::isnan(p.speed) == std::isnan(q.speed) &&
                      (std::isnan(p.speed) || std::fabs(p.speed - q.speed) <= 0.0005);
    if (!same) {
      ++bad;
      ADD_FAILURE() << "point " << i << ": ours " << p.lat << "," << p.lon << " t=" << std::fixed << p.time
                    << " ele=" << p.ele << " speed=" << p.speed << "; gpsbabel " << q.lat << "," << q.lon
                    << " t=" << q.time << " ele=" << q.ele << " speed=" << q.speed;
    }
  }
}

track::TrackFile read_ok(const std::filesystem::path& p) {
  track::ReadResult r = track::load_track_file(p.string());
  EXPECT_TRUE(r.ok()) << r.error->to_string();
  return r.file;
}

TEST(FitGpsbabel, ExpectedGpxFilesOfGpsbabelsTestSuite) {
  const char* files[] = {"gpsbabel_garmin-edge-800", "gpsbabel_garmin-virb-ultra-30",
                         "gpsbabel_lezyne_super_gps-bad-endian"};
  for (const char* name : files) {
    SCOPED_TRACE(name);
    TRAILRAY_REQUIRE_DATA(fit, std::string("fit/") + name + ".fit");
    TRAILRAY_REQUIRE_DATA(gpx, std::string("fit/") + name + ".expected.gpx");
    expect_same_points(read_ok(fit), read_ok(gpx));
  }
}

TEST(FitGpsbabel, EveryFileReadsLikeGpsbabel) {
  const auto dir = shared_data() / "fit";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "shared test data absent: " << dir.string();
  ASSERT_EQ(std::system("gpsbabel -V >/dev/null 2>&1"), 0)
      << "gpsbabel is missing: it is a declared dependency (scripts/setup.sh installs it)";
  std::size_t files = 0, points = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".fit") continue;
    SCOPED_TRACE(entry.path().filename().string());
    ++files;
    TempFile out("gpsbabel.gpx");
    const std::string base = "gpsbabel -i garmin_fit";
    const std::string rest = " -f '" + entry.path().string() + "' -o gpx -F '" + out.str() + "' 2>/dev/null";
    // gpsbabel refuses a damaged file (the lezyne sample) unless told to recover.
    if (std::system((base + rest).c_str()) != 0) {
      ASSERT_EQ(std::system((base + ",recoverymode" + rest).c_str()), 0);
    }
    const track::TrackFile theirs = read_ok(out.path());
    const track::TrackFile ours = read_ok(entry.path());
    expect_same_points(ours, theirs);
    points += flatten(ours).points.size();
  }
  EXPECT_EQ(files, 7u);
  EXPECT_GT(points, 15000u);
}

}  // namespace
}  // namespace trailray::test::fit
