// `trailray stats --photos`: photos with EXIF written at test time (the exiv2 tool, into copies of
// a shared JPEG) placed on a shared walk (gpx/alpinemaps_husarentempel.gpx): by time, by GPS, with
// --photo-tz and --photo-time-offset, and the ones that cannot be placed or read, each a warning.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "app/run_command.hpp"
#include "test_support.hpp"
#include "track/io/load.hpp"
#include "unique_temp_dir.hpp"

using nlohmann::json;
using trailray::test::run_command;
using trailray::test::shell_quote;

namespace {

namespace fs = std::filesystem;

std::string binary() { return shell_quote(TRAILRAY_BINARY); }

// The walk: 2023-10-14, 11:29:43 to 13:07:55 UTC.
constexpr const char* kWalk = "gpx/alpinemaps_husarentempel.gpx";

class StatsPhotos : public ::testing::Test {
 protected:
  void SetUp() override {
    jpeg_ = trailray::test::shared_data() / "photos/exifsamples_DSCN0010.jpg";
    walk_ = trailray::test::shared_data() / kWalk;
    if (!fs::exists(jpeg_) || !fs::exists(walk_)) GTEST_SKIP() << "shared test data absent: " << jpeg_ << ", " << walk_;
    dir_ = trailray::test::make_unique_temp_dir("trailray-stats-photos-");
    fs::create_directory(dir_ / "photos");
  }
  void TearDown() override {
    std::error_code ec;
    if (!dir_.empty()) fs::remove_all(dir_, ec);
  }

  // A copy of the shared JPEG with all its metadata removed, then `sets` ("Exif.Photo.X Ascii v").
  std::string photo(const std::string& name, const std::vector<std::string>& sets) {
    const fs::path path = dir_ / "photos" / name;
    fs::copy_file(jpeg_, path);
    fs::permissions(path, fs::perms::owner_write, fs::perm_options::add);
    std::string command = "exiv2 -q rm " + shell_quote(path.string());
    EXPECT_EQ(run_command(command).status, 0) << command;
    if (!sets.empty()) {
      command = "exiv2 -q";
      for (const auto& s : sets) command += " -M" + shell_quote("set " + s);
      command += " " + shell_quote(path.string());
      EXPECT_EQ(run_command(command).status, 0) << command;
    }
    return path.string();
  }

  // stats --json on the walk with `options`; standard error into `err`.
  json stats(const std::string& options, std::string& err, int expected_status = 0) {
    const fs::path err_file = dir_ / "err.txt";
    const auto r = run_command(binary() + " stats --json " + shell_quote(walk_.string()) + " " + options + " 2>" +
                               shell_quote(err_file.string()));
    std::ifstream in(err_file);
    std::stringstream ss;
    ss << in.rdbuf();
    err = ss.str();
    EXPECT_EQ(r.status, expected_status) << err;
    return json::parse(r.out);
  }

  fs::path jpeg_, walk_, dir_;
};

const json* photo_named(const json& photos, const std::string& name) {
  for (const auto& p : photos)
    if (fs::path(p["path"].get<std::string>()).filename() == name) return &p;
  return nullptr;
}

TEST_F(StatsPhotos, PlacedByTimeAndGpsWithTheReportedDistances) {
  // The walk's first fix as read, for a photo with that GPS position.
  const auto read = trailray::track::load_track_file(walk_.string());
  ASSERT_TRUE(read.ok());
  const auto& first = read.file.tracks.at(0).segments.at(0).points.at(0);
  const double lat = first.lat, lon = first.lon;
  auto dms = [](double deg) {
    const int d = static_cast<int>(deg);
    const int m = static_cast<int>((deg - d) * 60.0);
    const long s = std::lround(((deg - d) * 60.0 - m) * 60.0 * 1e6);
    return std::to_string(d) + "/1 " + std::to_string(m) + "/1 " + std::to_string(s) + "/1000000";
  };
  // At the last fix's time, in the camera's CEST (+02:00): lands at the track's whole distance.
  photo("end.jpg", {"Exif.Photo.DateTimeOriginal Ascii 2023:10:14 15:07:55", "Exif.Photo.OffsetTimeOriginal Ascii +02:00"});
  // At the first fix's place, with no time: snapped to the track's start.
  photo("start.jpg", {"Exif.GPSInfo.GPSLatitudeRef Ascii N", "Exif.GPSInfo.GPSLatitude Rational " + dms(lat),
                      "Exif.GPSInfo.GPSLongitudeRef Ascii E", "Exif.GPSInfo.GPSLongitude Rational " + dms(lon)});
  // 500 m west of the start (the walk passes a little nearer), no time: not placed.
  const double west = lon - 500.0 / (111320.0 * std::cos(lat * M_PI / 180.0));
  photo("far.jpg", {"Exif.GPSInfo.GPSLatitudeRef Ascii N", "Exif.GPSInfo.GPSLatitude Rational " + dms(lat),
                    "Exif.GPSInfo.GPSLongitudeRef Ascii E", "Exif.GPSInfo.GPSLongitude Rational " + dms(west)});
  // Not a photo: a warning, the others go on.
  std::ofstream(dir_ / "photos" / "notes.JPG") << "not a photo";

  std::string err;
  const json doc = stats("--photos " + shell_quote((dir_ / "photos").string()), err);
  ASSERT_EQ(doc["files"].size(), 1u);
  const json& file = doc["files"][0];
  const double total = file["tracks"][0]["clean"]["distance_2d_m"].get<double>();
  ASSERT_TRUE(file.contains("photos"));
  const json& photos = file["photos"];
  ASSERT_EQ(photos.size(), 2u) << photos.dump(2) << err;

  const json* end = photo_named(photos, "end.jpg");
  ASSERT_NE(end, nullptr);
  for (const char* key : {"path", "lat", "lon", "time", "placed_by", "track", "distance_m"})
    EXPECT_TRUE(end->contains(key)) << key;
  EXPECT_EQ((*end)["placed_by"], "time");
  EXPECT_EQ((*end)["track"], 0);
  EXPECT_EQ((*end)["time"], "2023-10-14T13:07:55Z");
  EXPECT_NEAR((*end)["distance_m"].get<double>(), total, 1e-6);
  EXPECT_TRUE((*end)["gps_offset_m"].is_null());

  const json* start = photo_named(photos, "start.jpg");
  ASSERT_NE(start, nullptr);
  EXPECT_EQ((*start)["placed_by"], "gps");
  EXPECT_LT((*start)["distance_m"].get<double>(), 30.0);  // the cleaned track's start is smoothed a little
  EXPECT_LT((*start)["gps_offset_m"].get<double>(), 10.0);
  EXPECT_NEAR((*start)["lat"].get<double>(), lat, 1e-3);
  EXPECT_FALSE((*start)["time"].is_null());  // the track's time there: the photo has none

  EXPECT_NE(err.find("far.jpg: not placed: its GPS position is "), std::string::npos) << err;
  EXPECT_NE(err.find("from the nearest track (more than 100 m) and no time (no DateTimeOriginal)"), std::string::npos) << err;
  EXPECT_NE(err.find("notes.JPG: not an image"), std::string::npos) << err;
}

TEST_F(StatsPhotos, TimeZoneAndClockOffsetShiftThePlacement) {
  // 12:00:00 on the camera's clock, no zone in the file.
  photo("noon.jpg", {"Exif.Photo.DateTimeOriginal Ascii 2023:10:14 12:00:00"});
  const std::string photos = "--photos " + shell_quote((dir_ / "photos" / "noon.jpg").string());
  std::string err;
  const json none = stats(photos, err);
  EXPECT_TRUE(none["files"][0]["photos"].empty());
  EXPECT_NE(err.find("noon.jpg: not placed: it has no GPS position and its time has no time zone (no "
                     "OffsetTimeOriginal): give it with --photo-tz +HH:MM"),
            std::string::npos)
      << err;
  // CEST: 10:00 UTC, before the walk; UTC+00:30 for the test's sake: 11:30 UTC, on it.
  const json before = stats(photos + " --photo-tz +02:00", err);
  EXPECT_TRUE(before["files"][0]["photos"].empty());
  const json on = stats(photos + " --photo-tz +00:30", err);
  ASSERT_EQ(on["files"][0]["photos"].size(), 1u) << err;
  EXPECT_EQ(on["files"][0]["photos"][0]["time"], "2023-10-14T11:30:00Z");
  // The camera was 20 minutes slow: 11:50 UTC, farther along.
  const json later = stats(photos + " --photo-tz +00:30 --photo-time-offset 1200", err);
  ASSERT_EQ(later["files"][0]["photos"].size(), 1u) << err;
  EXPECT_EQ(later["files"][0]["photos"][0]["time"], "2023-10-14T11:50:00Z");
  EXPECT_GT(later["files"][0]["photos"][0]["distance_m"].get<double>(),
            on["files"][0]["photos"][0]["distance_m"].get<double>() + 100.0);
  // A malformed zone is a usage error naming the option.
  const auto bad = run_command(binary() + " stats " + shell_quote(walk_.string()) + " " + photos +
                               " --photo-tz 2h 2>&1");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("--photo-tz"), std::string::npos) << bad.out;
}

TEST_F(StatsPhotos, MissingPathIsAnErrorNamingIt) {
  const auto r = run_command(binary() + " stats " + shell_quote(walk_.string()) + " --photos " +
                             shell_quote((dir_ / "nowhere").string()) + " 2>&1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find((dir_ / "nowhere").string() + ": no such photo or folder (--photos)"), std::string::npos) << r.out;
}

TEST_F(StatsPhotos, TableListsThePlacedPhotos) {
  photo("end.jpg", {"Exif.Photo.DateTimeOriginal Ascii 2023:10:14 15:07:55", "Exif.Photo.OffsetTimeOriginal Ascii +02:00"});
  const auto r = run_command(binary() + " stats " + shell_quote(walk_.string()) + " --photos " +
                             shell_quote((dir_ / "photos").string()) + " 2>/dev/null");
  ASSERT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("  photos: 1 of 1 placed on this file's tracks\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("end.jpg  Mödling Walking  3.613 km  2023-10-14T13:07:55Z  by time\n"), std::string::npos) << r.out;
}

}  // namespace
