// The real FIT files of ../shared/data/fit against what their MANIFEST.md states and what
// fitparse's record dumps (*-records.csv) hold, row by row.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "fit_test_support.hpp"
#include "test_support.hpp"
#include "track/io/fit_decoder.hpp"
#include "track/io/load.hpp"
#include "track/io/parse_util.hpp"

namespace trailray::test::fit {
namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, sep)) out.push_back(std::string(track::trim(cell)));
  if (!line.empty() && line.back() == sep) out.emplace_back();
  return out;
}

std::pair<double, double> elevation_range(const track::TrackFile& f) {
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& p : all_points(f))
    if (p.has_ele()) lo = std::min(lo, p.ele), hi = std::max(hi, p.ele);
  return {lo, hi};
}

double iso(const char* text) { return track::parse_iso8601(text).value(); }

struct ManifestEntry {
  const char* file;
  std::size_t points;
  double lon_min, lat_min, lon_max, lat_max;  // MANIFEST.md, 4 decimals
  const char* first_time;
  const char* last_time;
};

TEST(FitFiles, MatchTheManifest) {
  const ManifestEntry entries[] = {
      {"fitparse_developer-types-sample.fit", 3424, -9.2638, 38.7480, -9.2591, 38.7574, "2017-01-17T17:06:47Z",
       "2017-01-17T18:03:50Z"},
      {"fitparse_garmin-fenix-5-bike.fit", 19, -122.0691, 37.4112, -122.0689, 37.4153, "2017-06-12T16:09:22Z",
       "2017-06-12T16:10:23Z"},
      // the MANIFEST's first time (11:10:19) is a record without a position: see below
      {"fitparse_coros-pace-2-cycling-misaligned-fields.fit", 10305, -73.9712, 4.6095, -73.8648, 4.7232, nullptr,
       "2020-10-25T14:42:17Z"},
      // gpsbabel's expected GPX has the same 804 points (see fit_gpsbabel_test.cpp); its
      // records end before the MANIFEST's last time, which comes from later messages.
      {"gpsbabel_lezyne_super_gps-bad-endian.fit", 804, 144.9496, -37.7361, 144.9653, -37.7202, "2019-08-18T03:50:17Z",
       nullptr},
  };
  for (const ManifestEntry& e : entries) {
    SCOPED_TRACE(e.file);
    TRAILRAY_REQUIRE_DATA(path, std::string("fit/") + e.file);
    track::ReadResult r = track::load_track_file(path.string());
    ASSERT_TRUE(r.ok()) << r.error->to_string();
    EXPECT_EQ(r.file.format, track::Format::Fit);
    auto pts = all_points(r.file);
    ASSERT_EQ(pts.size(), e.points);
    double lat0 = 90, lat1 = -90, lon0 = 180, lon1 = -180, t0 = INFINITY, t1 = -INFINITY;
    for (const auto& p : pts) {
      lat0 = std::min(lat0, p.lat), lat1 = std::max(lat1, p.lat);
      lon0 = std::min(lon0, p.lon), lon1 = std::max(lon1, p.lon);
      ASSERT_TRUE(p.has_time());
      t0 = std::min(t0, p.time), t1 = std::max(t1, p.time);
    }
    EXPECT_NEAR(lon0, e.lon_min, 0.6e-4);
    EXPECT_NEAR(lat0, e.lat_min, 0.6e-4);
    EXPECT_NEAR(lon1, e.lon_max, 0.6e-4);
    EXPECT_NEAR(lat1, e.lat_max, 0.6e-4);
    if (e.first_time) {
      EXPECT_EQ(t0, iso(e.first_time)) << std::fixed << t0 - iso(e.first_time);
    }
    if (e.last_time) {
      EXPECT_EQ(t1, iso(e.last_time)) << std::fixed << t1 - iso(e.last_time);
    }
  }
}

TEST(FitFiles, DeveloperFieldsAreCounted) {
  TRAILRAY_REQUIRE_DATA(path, "fit/fitparse_developer-types-sample.fit");
  track::ReadResult r = track::load_track_file(path.string());
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front().to_string();
  EXPECT_GT(std::stoul(metadata_field(r.file, "developer_fields_skipped")), 0u);
  EXPECT_EQ(metadata_field(r.file, "manufacturer"), "95");
  auto [lo, hi] = elevation_range(r.file);
  EXPECT_NEAR(lo, 91, 1.0);  // MANIFEST: alt 91..109 m
  EXPECT_NEAR(hi, 109, 1.0);
}

// A Locations file (Garmin's saved places): each location message is a waypoint, as gpsbabel's
// own expected output for the file has them (corpus/gpx/gpsbabel_track_fitlocations-sample.gpx).
TEST(FitFiles, SavedLocationsAreWaypoints) {
  TRAILRAY_REQUIRE_DATA(path, "corpus/fit/gpsbabel_track_fitlocations-sample.fit");
  track::ReadResult r = track::load_track_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_TRUE(r.file.tracks.empty());
  ASSERT_EQ(r.file.waypoints.size(), 2u);
  const track::Waypoint &a = r.file.waypoints[0], &b = r.file.waypoints[1];
  EXPECT_EQ(a.name, "Posizione 008");
  EXPECT_NEAR(a.point.lat, 52.178867133, 1e-8);
  EXPECT_NEAR(a.point.lon, 5.179891856, 1e-8);
  EXPECT_FALSE(a.point.has_ele());
  EXPECT_FALSE(a.point.has_time());  // when it was saved is not when anyone was there
  EXPECT_EQ(b.name, "Via Sebastiano ");
  EXPECT_EQ(b.description, "Some random position in the centre of a small tow");
  EXPECT_NEAR(b.point.lat, 40.321111679, 1e-8);
  EXPECT_NEAR(b.point.lon, 9.332499504, 1e-8);
  EXPECT_NEAR(b.point.ele, 531.2, 1e-9);
}

TEST(FitFiles, CorosMisalignedFieldsWarnAndTheRestReads) {
  TRAILRAY_REQUIRE_DATA(path, "fit/fitparse_coros-pace-2-cycling-misaligned-fields.fit");
  track::ReadResult r = track::load_track_file(path.string());
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].message.find("no multiple of its base type"), std::string::npos);
  EXPECT_GT(r.warnings[0].position.byte_offset, 0);
  EXPECT_EQ(metadata_field(r.file, "manufacturer"), "294");
  EXPECT_EQ(r.file.metadata.activity_type, "cycling");
  // fitparse decodes 11,293 messages in this file
  track::WarningCollector w("coros");
  track::fit::DecodeStats stats;
  std::optional<std::uint32_t> first_record_time;
  ASSERT_FALSE(track::fit::decode(slurp(path), w, stats, [&](const track::fit::Message& m) {
    if (m.global == kRecordMsg && !first_record_time) first_record_time = m.timestamp;
  }));
  EXPECT_EQ(stats.messages, 11293u);
  // The MANIFEST's time range starts at the first record; the first 31 s have no position.
  ASSERT_TRUE(first_record_time.has_value());
  EXPECT_EQ(*first_record_time + 631065600.0, iso("2020-10-25T11:10:19Z"));
  EXPECT_EQ(all_points(r.file).front().time, iso("2020-10-25T11:10:50Z"));
  EXPECT_EQ(metadata_field(r.file, "records_without_position"), std::to_string(11272 - 10305));
  EXPECT_FALSE(stats.cut);
  auto [lo, hi] = elevation_range(r.file);
  EXPECT_NEAR(lo, 2025, 1.0);  // MANIFEST: alt 2025..3005 m
  EXPECT_NEAR(hi, 3005, 1.0);
}

// compressed-speed-distance: every record has a compressed-timestamp header and no position.
TEST(FitFiles, CompressedRecordsMatchFitparseRowByRow) {
  TRAILRAY_REQUIRE_DATA(path, "fit/fitparse_compressed-speed-distance.fit");
  TRAILRAY_REQUIRE_DATA(csv, "fit/fitparse_compressed-speed-distance-records.csv");
  std::vector<track::fit::Message> records;
  track::WarningCollector w("csd");
  track::fit::DecodeStats stats;
  const std::string bytes = slurp(path);
  ASSERT_FALSE(track::fit::decode(bytes, w, stats, [&](const track::fit::Message& m) {
    if (m.global == kRecordMsg) records.push_back(m);
  }));
  EXPECT_EQ(w.total(), 0u);
  EXPECT_EQ(stats.compressed_headers, 755u);
  ASSERT_EQ(records.size(), 755u);
  EXPECT_EQ(records[0].timestamp, 17217864u);  // MANIFEST: first record
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  std::size_t row = 1;     // fitparse skips the first, empty record
  std::size_t compared = 0;
  while (std::getline(in, line)) {
    if (track::trim(line).empty()) continue;
    SCOPED_TRACE("csv row " + std::to_string(row) + ": " + line);
    ASSERT_LT(row, records.size());
    const auto cells = split(line, ',');
    ASSERT_EQ(cells.size(), 5u);
    const auto& m = records[row];
    ASSERT_TRUE(m.timestamp.has_value());
    EXPECT_EQ(*m.timestamp, std::stoul(cells[0]));
    auto hr = m.integer(3), cadence = m.integer(4);
    if (cells[1] == "null")
      EXPECT_FALSE(hr.has_value());
    else
      EXPECT_EQ(hr.value_or(-1), std::stol(cells[1]));
    if (cells[4] == "null")
      EXPECT_FALSE(cadence.has_value());
    else
      EXPECT_EQ(cadence.value_or(-1), std::stol(cells[4]));
    const track::fit::Field* csd = m.find(8);
    ASSERT_NE(csd, nullptr);
    ASSERT_EQ(csd->bytes.size(), 3u);
    const int speed = static_cast<std::uint8_t>(csd->bytes[0]) | (static_cast<std::uint8_t>(csd->bytes[1]) & 0x0F) << 8;
    EXPECT_NEAR(speed / 100.0, std::stod(cells[2]), 1e-9);
    ++row, ++compared;
  }
  EXPECT_EQ(compared, 754u);  // every row: records 1..754
  // No positions: an empty file, every record counted; the times are device-relative with no
  // UTC offset in the file, which the reader says.
  track::ReadResult r = track::load_track_file(path.string());
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.file.tracks.empty());
  EXPECT_EQ(metadata_field(r.file, "records_without_position"), "755");
}

TEST(FitFiles, Fenix5MatchesItsRecordDumpRowByRow) {
  TRAILRAY_REQUIRE_DATA(path, "fit/fitparse_garmin-fenix-5-bike.fit");
  TRAILRAY_REQUIRE_DATA(csv, "fit/fitparse_garmin-fenix-5-bike-records.csv");
  track::ReadResult r = track::load_track_file(path.string());
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.file.metadata.creator, "garmin 2697");
  auto pts = all_points(r.file);
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  ASSERT_EQ(split(line, ',').size(), 9u) << line;
  std::size_t row = 0;
  while (std::getline(in, line)) {
    if (track::trim(line).empty()) continue;
    SCOPED_TRACE("csv row " + std::to_string(row) + ": " + line);
    ASSERT_LT(row, pts.size());
    const auto c = split(line, ',');
    ASSERT_EQ(c.size(), 9u);
    const auto& p = pts[row];
    // "Mon Jun 12 09:09:22 PDT 2017": PDT is UTC-7
    const std::string hms = c[0].substr(11, 8);
    EXPECT_EQ(p.time, iso(("2017-06-12T" + hms + "-07:00").c_str()));
    EXPECT_EQ(p.heart_rate, std::stof(c[1]));
    if (c[2].empty())
      EXPECT_TRUE(std::isnan(p.cadence));
    else
      EXPECT_EQ(p.cadence, std::stof(c[2]));
    EXPECT_NEAR(p.speed, std::stod(c[3]), 1e-6);
    EXPECT_NEAR(p.lat, std::stod(c[5]) * 180.0 / 2147483648.0, 1e-12);
    EXPECT_NEAR(p.lon, std::stod(c[6]) * 180.0 / 2147483648.0, 1e-12);
    EXPECT_NEAR(p.ele, std::stod(c[7]), 1e-9);
    EXPECT_EQ(p.temperature, std::stof(c[8]));
    ++row;
  }
  EXPECT_EQ(row, pts.size());
}

TEST(FitFiles, EveryFileSurvivesBeingCutAnywhere) {
  TRAILRAY_REQUIRE_DATA(path, "fit/fitparse_garmin-fenix-5-bike.fit");
  const std::string whole = slurp(path);
  const std::size_t full = all_points(read_fit_bytes(whole).file).size();
  std::size_t previous = 0;
  for (std::size_t len = 14; len < whole.size(); len += 7) {
    SCOPED_TRACE("cut at " + std::to_string(len));
    auto r = read_fit_bytes(whole.substr(0, len));
    ASSERT_TRUE(r.ok());
    ASSERT_FALSE(r.warnings.empty());
    const std::size_t n = all_points(r.file).size();
    EXPECT_GE(n, previous);  // a longer prefix never loses a record
    EXPECT_LE(n, full);
    previous = n;
  }
  EXPECT_EQ(previous, full);
}

}  // namespace
}  // namespace trailray::test::fit
