// Photos with EXIF written at test time into copies of a shared JPEG (exiv2), read back by the
// reader and placed on a shared walk (gpx/alpinemaps_husarentempel.gpx, Mödling): the whole path a camera's file
// takes, with figures known exactly.

#include <gtest/gtest.h>

#include <cmath>

#include "exif_writing.hpp"
#include "geo/geodesic.hpp"
#include "test_support.hpp"
#include "track/io/load.hpp"
#include "track/metrics.hpp"
#include "track/photos/exif_reader.hpp"
#include "track/photos/exif_time.hpp"
#include "track/photos/photo_placement.hpp"
#include "unique_temp_dir.hpp"

namespace trailray::track {
namespace {

// "YYYY:MM:DD HH:MM:SS" of a time read as a wall clock.
std::string exif_datetime(double local_s) {
  const auto s = static_cast<long long>(std::floor(local_s));
  long long days = s / 86400, rem = s % 86400;
  // civil_from_days (Howard Hinnant)
  days += 719468;
  const long long era = days / 146097, doe = days - era * 146097;
  const long long yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const long long doy = doe - (365 * yoe + yoe / 4 - yoe / 100), mp = (5 * doy + 2) / 153;
  const long long d = doy - (153 * mp + 2) / 5 + 1, m = mp < 10 ? mp + 3 : mp - 9, y = yoe + era * 400 + (m <= 2);
  char buf[96];
  std::snprintf(buf, sizeof buf, "%04lld:%02lld:%02lld %02lld:%02lld:%02lld", y, m, d, rem / 3600, rem / 60 % 60, rem % 60);
  return buf;
}

class WrittenPhotos : public ::testing::Test {
 protected:
  void SetUp() override {
    jpeg_ = test::shared_data() / "photos/exifsamples_DSCN0010.jpg";
    const auto gpx = test::shared_data() / "gpx/alpinemaps_husarentempel.gpx";
    if (!std::filesystem::exists(jpeg_) || !std::filesystem::exists(gpx))
      GTEST_SKIP() << "shared test data absent: " << jpeg_.string() << " or " << gpx.string();
    const ReadResult r = load_track_file(gpx.string());
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.file.tracks.size(), 1u);
    track_ = r.file.tracks[0];
    metrics_ = compute_metrics(track_);
    dir_ = test::make_unique_temp_dir("trailray-photos-");
  }
  void TearDown() override {
    std::error_code ec;
    if (!dir_.empty()) std::filesystem::remove_all(dir_, ec);
  }

  PhotoMetadata written(const std::string& name, const std::map<std::string, std::string>& values) {
    const auto path = dir_ / name;
    test::write_exif_copy(jpeg_, path, values);
    const PhotoReadResult r = read_photo_file(path.string());
    EXPECT_TRUE(r.ok()) << r.error->to_string();
    return r.photo;
  }

  const TrackPoint& fix(std::size_t i) const { return track_.segments[0].points[i]; }

  std::filesystem::path jpeg_, dir_;
  Track track_;
  TrackMetrics metrics_;
};

TEST_F(WrittenPhotos, TakenAtAFixTimeLandsAtThatFixDistance) {
  for (std::size_t k : {3u, 90u, 150u}) {
    const double t = fix(k).time;
    ASSERT_EQ(t, std::floor(t));  // whole seconds in this file
    const PhotoMetadata photo = written("fix.jpg", {{"Exif.Photo.DateTimeOriginal", exif_datetime(t + 7200)},
                                                    {"Exif.Photo.OffsetTimeOriginal", "+02:00"}});
    EXPECT_EQ(photo.offset_s, 7200);
    const PhotoPlacement r = place_photos({photo}, {&track_});
    ASSERT_EQ(r.placed.size(), 1u) << (r.unplaced.empty() ? "" : r.unplaced[0].reason.to_string());
    EXPECT_EQ(r.placed[0].placed_by, PhotoPlacedBy::time);
    EXPECT_NEAR(r.placed[0].distance_m, metrics_.segments[0].distance_m[k], 1e-6) << k;
    EXPECT_EQ(r.placed[0].lat_deg, fix(k).lat);
    EXPECT_EQ(r.placed[0].lon_deg, fix(k).lon);
  }
}

TEST_F(WrittenPhotos, NonStandardFieldWithMillisecondsAndZoneInside) {
  const double t = fix(40).time;
  const PhotoMetadata photo =
      written("odd.jpg", {{"Exif.Photo.DateTimeOriginal", exif_datetime(t) + ".000+00:00"}});
  ASSERT_EQ(photo.offset_s, 0);
  EXPECT_DOUBLE_EQ(photo.taken_local_s, t);
  const PhotoPlacement r = place_photos({photo}, {&track_});
  ASSERT_EQ(r.placed.size(), 1u);
  EXPECT_NEAR(r.placed[0].distance_m, metrics_.segments[0].distance_m[40], 1e-6);
}

TEST_F(WrittenPhotos, GpsThirtyMetresOffSnapsAndFiveHundredWithoutTimeIsNotPlaced) {
  // A fix the walk passes only once: every fix more than 200 m along the track from it is over
  // 120 m away, so the nearest point of the polyline to a place 30 m from it is on those 400 m.
  const auto& pts = track_.segments[0].points;
  const auto& dist = metrics_.segments[0].distance_m;
  auto lonely = [&](std::size_t c) {
    for (std::size_t i = 0; i < pts.size(); ++i)
      if (std::abs(dist[i] - dist[c]) > 200.0 &&
          geo::geodesic_distance_m(pts[i].lat, pts[i].lon, pts[c].lat, pts[c].lon) < 120.0)
        return false;
    return true;
  };
  std::size_t k = pts.size() / 3;
  while (k < pts.size() && !lonely(k)) ++k;
  ASSERT_LT(k, pts.size()) << "no fix the walk passes only once";
  const TrackPoint& p = fix(k);
  // Due west of the fix, 30 m and 500 m (the nearest point of the polyline may be closer than
  // 30 m, never farther).
  auto west = [&](double m) { return p.lon - m / (111320.0 * std::cos(p.lat * M_PI / 180.0)); };
  auto gps = [&](double lon) {
    return std::map<std::string, std::string>{{"Exif.GPSInfo.GPSLatitudeRef", "N"},
                                              {"Exif.GPSInfo.GPSLatitude", test::exif_dms(p.lat)},
                                              {"Exif.GPSInfo.GPSLongitudeRef", "E"},
                                              {"Exif.GPSInfo.GPSLongitude", test::exif_dms(lon)}};
  };
  const PhotoMetadata near = written("near.jpg", gps(west(30.0)));
  EXPECT_NEAR(geo::geodesic_distance_m(near.lat_deg, near.lon_deg, p.lat, p.lon), 30.0, 0.2);
  const PhotoMetadata far = written("far.jpg", gps(west(500.0)));
  const PhotoPlacement r = place_photos({near, far}, {&track_});
  ASSERT_EQ(r.placed.size(), 1u);
  EXPECT_EQ(r.placed[0].placed_by, PhotoPlacedBy::gps);
  EXPECT_LE(r.placed[0].gps_offset_m, 30.0 + 0.2);
  // On the stretch around the fix, and as far from the photo as the nearest of its fixes at most.
  EXPECT_NEAR(r.placed[0].distance_m, dist[k], 200.0);
  double nearest_fix = 1e9;
  for (std::size_t i = 0; i < pts.size(); ++i)
    nearest_fix = std::min(nearest_fix, geo::geodesic_distance_m(near.lat_deg, near.lon_deg, pts[i].lat, pts[i].lon));
  EXPECT_LE(r.placed[0].gps_offset_m, nearest_fix + 1e-6);
  EXPECT_NEAR(geo::geodesic_distance_m(near.lat_deg, near.lon_deg, r.placed[0].lat_deg, r.placed[0].lon_deg),
              r.placed[0].gps_offset_m, 1e-9);
  ASSERT_EQ(r.unplaced.size(), 1u);
  EXPECT_EQ(r.unplaced[0].photo, 1u);
  EXPECT_NE(r.unplaced[0].reason.to_string().find("far.jpg: not placed: its GPS position is"), std::string::npos);
  EXPECT_NE(r.unplaced[0].reason.message.find("and no time"), std::string::npos) << r.unplaced[0].reason.message;
}

TEST_F(WrittenPhotos, TimeZoneAndClockOptionsShiftThePlacement) {
  const std::size_t k = 60;
  // No zone in the file: the camera's local clock 1 h ahead of UTC (CET), and 30 s slow.
  const PhotoMetadata photo = written("clock.jpg", {{"Exif.Photo.DateTimeOriginal", exif_datetime(fix(k).time + 3600 - 30)}});
  EXPECT_FALSE(photo.offset_s);
  PhotoPlacementOptions options;
  EXPECT_TRUE(place_photos({photo}, {&track_}, options).placed.empty());
  options.default_offset_s = 3600;
  const PhotoPlacement slow = place_photos({photo}, {&track_}, options);
  ASSERT_EQ(slow.placed.size(), 1u);
  EXPECT_EQ(slow.placed[0].time_unix_s, fix(k).time - 30);
  options.clock_offset_s = 30;
  const PhotoPlacement fixed = place_photos({photo}, {&track_}, options);
  ASSERT_EQ(fixed.placed.size(), 1u);
  EXPECT_NEAR(fixed.placed[0].distance_m, metrics_.segments[0].distance_m[k], 1e-6);
  EXPECT_LT(slow.placed[0].distance_m, fixed.placed[0].distance_m);
}

TEST_F(WrittenPhotos, JpegWithoutExifIsReadAndNotPlaced) {
  const PhotoMetadata photo = written("bare.jpg", {});
  EXPECT_FALSE(photo.has_exif);
  const PhotoPlacement r = place_photos({photo}, {&track_});
  ASSERT_EQ(r.unplaced.size(), 1u);
  EXPECT_NE(r.unplaced[0].reason.message.find("no EXIF block"), std::string::npos);
}

TEST_F(WrittenPhotos, EmptyDateTimeOriginalWarns) {
  const auto path = dir_ / "blank.jpg";
  test::write_exif_copy(jpeg_, path, {{"Exif.Photo.DateTimeOriginal", "    :  :     :  :  "}});
  const PhotoReadResult r = read_photo_file(path.string());
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(std::isnan(r.photo.taken_local_s));
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].to_string(), path.string() + ": DateTimeOriginal is empty: no time");
}

}  // namespace
}  // namespace trailray::track
