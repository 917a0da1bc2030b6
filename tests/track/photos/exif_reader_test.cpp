// The EXIF reader against the shared real photos (their figures from ../shared/data/MANIFEST.md,
// read there with exiftool) and against files that are not photos.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <thread>
#include <vector>

#include "test_support.hpp"
#include "track/io/parse_util.hpp"
#include "track/photos/exif_reader.hpp"
#include "track/photos/exif_time.hpp"

namespace trailray::track {
namespace {

double utc(int y, unsigned mo, unsigned d, int h, int mi, double s) {
  return static_cast<double>(days_from_civil(y, mo, d)) * 86400.0 + h * 3600.0 + mi * 60.0 + s;
}

std::string joined_warnings(const PhotoReadResult& r) {
  std::string out;
  for (const auto& w : r.warnings) out += w.to_string() + "\n";
  return out;
}

TEST(ExifReader, NikonWalkPhotoHasPositionAndLocalTime) {
  TRAILRAY_REQUIRE_DATA(path, "photos/exifsamples_DSCN0010.jpg");
  const PhotoReadResult r = read_photo_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_EQ(r.photo.path, path.string());
  EXPECT_TRUE(r.photo.has_exif);
  EXPECT_NEAR(r.photo.lat_deg, 43.467448, 1e-6);
  EXPECT_NEAR(r.photo.lon_deg, 11.885127, 1e-6);
  EXPECT_TRUE(std::isnan(r.photo.alt_m));  // the DSCN photos have no altitude
  EXPECT_DOUBLE_EQ(r.photo.taken_local_s, utc(2008, 10, 22, 16, 28, 39));
  EXPECT_FALSE(r.photo.offset_s.has_value());
  // The GPS date is a day ahead (MANIFEST): 2008:10:23 14:27:07 UTC.
  EXPECT_NEAR(r.photo.gps_time_utc_s, utc(2008, 10, 23, 14, 27, 7.24), 1e-6);  // 724/100 seconds
  EXPECT_EQ(r.photo.width, 640);
  EXPECT_EQ(r.photo.height, 480);
  EXPECT_TRUE(r.warnings.empty()) << joined_warnings(r);
}

TEST(ExifReader, IphoneHeicHasOffsetAndSubseconds) {
  TRAILRAY_REQUIRE_DATA(path, "photos/exifr_heic-iphone7.heic");
  const PhotoReadResult r = read_photo_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_NEAR(r.photo.lat_deg, 38.046642, 1e-6);
  EXPECT_NEAR(r.photo.lon_deg, 12.994411, 1e-6);
  EXPECT_NEAR(r.photo.alt_m, 1.4, 0.05);  // exiftool rounds it to 1 m
  EXPECT_NEAR(r.photo.taken_local_s, utc(2019, 10, 20, 18, 34, 30.130), 1e-6);
  ASSERT_TRUE(r.photo.offset_s.has_value());
  EXPECT_EQ(*r.photo.offset_s, 2 * 3600);
  EXPECT_EQ(r.photo.width, 4032);
  EXPECT_EQ(r.photo.height, 3024);
}

TEST(ExifReader, WesternHemisphereHeicIsNegativeLongitudeWithNegativeOffset) {
  TRAILRAY_REQUIRE_DATA(path, "photos/exifsamples_IMG_5195.HEIC");
  const PhotoReadResult r = read_photo_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_NEAR(r.photo.lat_deg, 39.051344, 1e-6);
  EXPECT_NEAR(r.photo.lon_deg, -94.288772, 1e-6);
  EXPECT_NEAR(r.photo.alt_m, 261, 1.0);
  EXPECT_NEAR(r.photo.taken_local_s, utc(2021, 4, 11, 15, 47, 53), 1.0);
  ASSERT_TRUE(r.photo.offset_s.has_value());
  EXPECT_EQ(*r.photo.offset_s, -5 * 3600);
}

TEST(ExifReader, SouthernHemisphereIsNegativeLatitude) {
  TRAILRAY_REQUIRE_DATA(path, "photos/exifsamples_Kodak_CX7530.jpg");
  const PhotoReadResult r = read_photo_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_NEAR(r.photo.lat_deg, -0.371300, 1e-6);
  EXPECT_NEAR(r.photo.lon_deg, 36.056417, 1e-6);
  EXPECT_DOUBLE_EQ(r.photo.taken_local_s, utc(2005, 8, 13, 9, 47, 23));
}

TEST(ExifReader, AltitudeBelowSeaLevelIsNegative) {
  TRAILRAY_REQUIRE_DATA(path, "photos/exifr_issue-exifr-3.jpg");
  const PhotoReadResult r = read_photo_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_DOUBLE_EQ(r.photo.alt_m, -8.5);  // GPSAltitudeRef = 1
  EXPECT_NEAR(r.photo.lat_deg, 40.377501, 1e-6);
  EXPECT_NEAR(r.photo.lon_deg, -74.489913, 1e-6);
  // exiv2 sees a standard DateTimeOriginal with SubSecTimeOriginal 606.
  EXPECT_NEAR(r.photo.taken_local_s, utc(2019, 4, 30, 15, 56, 18.606), 1e-6);
  // Its XMP is broken (exiv2 complains), but XMP is not read: no warning about it.
  for (const auto& w : r.warnings) EXPECT_EQ(w.message.find("XMP"), std::string::npos) << w.to_string();
}

TEST(ExifReader, SubSecondsAddToTheTime) {
  TRAILRAY_REQUIRE_DATA(path, "photos/exifr_issue-exifr-59.jpg");
  const PhotoReadResult r = read_photo_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_NEAR(r.photo.taken_local_s, utc(2015, 6, 12, 13, 40, 32.41), 1e-6);
  EXPECT_NEAR(r.photo.lat_deg, 37.746765, 1e-6);
  EXPECT_NEAR(r.photo.lon_deg, -119.529883, 1e-6);
  EXPECT_NEAR(r.photo.alt_m, 1960, 1.0);
  EXPECT_TRUE(std::isnan(r.photo.gps_time_utc_s));
}

TEST(ExifReader, PhotoWithoutDateTimeOriginalHasPositionButNoTime) {
  TRAILRAY_REQUIRE_DATA(path, "photos/exifsamples_67-0_length_string.jpg");
  const PhotoReadResult r = read_photo_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_NEAR(r.photo.lat_deg, 51.025000, 1e-6);
  EXPECT_NEAR(r.photo.lon_deg, 7.591944, 1e-6);
  EXPECT_NEAR(r.photo.alt_m, 340, 1e-9);
  // Image.DateTime (when the file was last changed) is there but never taken for the photo's time.
  EXPECT_TRUE(std::isnan(r.photo.taken_local_s));
}

TEST(ExifReader, PixelGpsTimeIsUtc) {
  TRAILRAY_REQUIRE_DATA(path, "photos/exifr_IMG_20180725_163423-tiny.jpg");
  const PhotoReadResult r = read_photo_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_NEAR(r.photo.lat_deg, 50.299603, 1e-6);
  EXPECT_NEAR(r.photo.lon_deg, 14.820294, 1e-6);
  EXPECT_DOUBLE_EQ(std::floor(r.photo.taken_local_s), utc(2018, 7, 25, 16, 34, 23));
  EXPECT_NEAR(r.photo.gps_time_utc_s, utc(2018, 7, 25, 14, 34, 23), 1.0);
}

TEST(ExifReader, BrokenExifBlockWarnsNamingTheFileAndKeepsWhatIsReadable) {
  TRAILRAY_REQUIRE_DATA(path, "photos/exifr_broken1.jpg");
  const PhotoReadResult r = read_photo_file(path.string());
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_FALSE(r.photo.has_position());  // latitude and longitude are 0/0 rationals
  EXPECT_DOUBLE_EQ(r.photo.taken_local_s, utc(2007, 8, 15, 10, 13, 13));
  ASSERT_FALSE(r.warnings.empty());
  const std::string all = joined_warnings(r);
  EXPECT_NE(all.find(path.string() + ": EXIF block: "), std::string::npos) << all;  // exiv2's complaint, ours now
  EXPECT_NE(all.find("GPSLatitude is not a valid angle"), std::string::npos) << all;
}

TEST(ExifReader, TextIsNotAnImage) {
  test::TempFile f("notes.jpg", "these are my notes, not a photo\n");
  const PhotoReadResult r = read_photo_file(f.str());
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->file, f.str());
  EXPECT_NE(r.error->message.find("not an image"), std::string::npos) << r.error->to_string();
  EXPECT_EQ(r.photo.path, f.str());
}

TEST(ExifReader, EmptyAndMissingFilesAreErrors) {
  test::TempFile f("empty.jpg", "");
  EXPECT_FALSE(read_photo_file(f.str()).ok());
  const PhotoReadResult missing = read_photo_file(f.str() + ".nope");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error->to_string().find("no such file"), std::string::npos);
}

TEST(ExifReader, EnormousFileIsRefusedUnread) {
  TRAILRAY_REQUIRE_DATA(path, "photos/exifsamples_DSCN0010.jpg");
  PhotoReadOptions small;
  small.max_bytes = 100000;  // the photo has 161713 bytes
  const PhotoReadResult r = read_photo_file(path.string(), small);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error->message.find("over the 100000 bytes a photo may have"), std::string::npos) << r.error->message;
}

TEST(ExifReader, PngIsAnImageButNotAPhoto) {
  // An 8-byte PNG signature and an IHDR chunk: exiv2 knows it as PNG.
  const std::string png("\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\0\1\0\0\0\1\x08\x02\0\0\0\x90wS\xde\0\0\0\0IEND\xae\x42\x60\x82", 45);
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(png.data());
  const PhotoReadResult r = read_photo_bytes(bytes, png.size(), "pixel.png");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error->message.find("not JPEG or HEIC"), std::string::npos) << r.error->message;
}

TEST(ExifReader, TruncatedPhotosGiveAResultOrAnErrorNeverACrash) {
  TRAILRAY_REQUIRE_DATA(path, "photos/exifsamples_DSCN0010.jpg");
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t errors = 0;
  for (std::size_t n : {2u, 20u, 200u, 2000u, 8000u, 20000u}) {
    const PhotoReadResult r =
        read_photo_bytes(reinterpret_cast<const std::uint8_t*>(bytes.data()), n, "truncated.jpg");
    if (!r.ok()) {
      ++errors;
      EXPECT_EQ(r.error->file, "truncated.jpg");
      EXPECT_FALSE(r.error->message.empty());
    }
  }
  EXPECT_GE(errors, 1u);  // at least the 2 bytes are no photo
}

TEST(ExifReader, ThreadsReadingAtOnceGetTheSameAsOne) {
  TRAILRAY_REQUIRE_DATA(dir, "photos");
  std::vector<std::string> paths;
  for (const auto& e : std::filesystem::directory_iterator(dir)) paths.push_back(e.path().string());
  std::sort(paths.begin(), paths.end());
  std::vector<PhotoReadResult> alone;
  for (const auto& p : paths) alone.push_back(read_photo_file(p));
  std::vector<std::vector<PhotoReadResult>> together(4);
  std::vector<std::thread> threads;
  for (auto& out : together)
    threads.emplace_back([&paths, &out] {
      for (const auto& p : paths) out.push_back(read_photo_file(p));
    });
  for (auto& t : threads) t.join();
  for (const auto& out : together) {
    ASSERT_EQ(out.size(), alone.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
      EXPECT_EQ(out[i].ok(), alone[i].ok()) << paths[i];
      EXPECT_EQ(out[i].warnings.size(), alone[i].warnings.size()) << paths[i];
      EXPECT_TRUE(out[i].photo.lat_deg == alone[i].photo.lat_deg ||
                  (std::isnan(out[i].photo.lat_deg) && std::isnan(alone[i].photo.lat_deg)))
          << paths[i];
    }
  }
}

TEST(ExifTime, ParsesStandardAndNonStandardFields) {
  const auto plain = parse_exif_datetime("2019:04:30 15:56:18");
  ASSERT_TRUE(plain);
  EXPECT_DOUBLE_EQ(plain->local_s, utc(2019, 4, 30, 15, 56, 18));
  EXPECT_FALSE(plain->has_fraction);
  EXPECT_FALSE(plain->offset_s);
  const auto odd = parse_exif_datetime("2019:04:30 15:56:18.605+00:00");
  ASSERT_TRUE(odd);
  EXPECT_NEAR(odd->local_s, utc(2019, 4, 30, 15, 56, 18.605), 1e-6);
  EXPECT_TRUE(odd->has_fraction);
  EXPECT_EQ(odd->offset_s, 0);
  const auto iso = parse_exif_datetime("2021-04-11T15:47:53-05:00");
  ASSERT_TRUE(iso);
  EXPECT_EQ(iso->offset_s, -5 * 3600);
  for (const char* bad : {"", "    :  :     :  :  ", "0000:00:00 00:00:00", "2019:13:01 00:00:00",
                          "2019:02:29 10:00:00", "2019:04:30 25:00:00", "2019:04:30 15:56:18 junk", "2019:04:30"})
    EXPECT_FALSE(parse_exif_datetime(bad)) << bad;
  EXPECT_TRUE(parse_exif_datetime("2020:02:29 10:00:00"));  // a leap year
}

TEST(ExifTime, OffsetsAndSubseconds) {
  EXPECT_EQ(parse_utc_offset("+02:00"), 7200);
  EXPECT_EQ(parse_utc_offset("-05:30"), -19800);
  EXPECT_EQ(parse_utc_offset("+0545"), 20700);
  EXPECT_EQ(parse_utc_offset("+01"), 3600);
  EXPECT_EQ(parse_utc_offset("Z"), 0);
  EXPECT_FALSE(parse_utc_offset("+15:00"));
  EXPECT_FALSE(parse_utc_offset("02:00"));
  EXPECT_FALSE(parse_utc_offset("+02:60"));
  EXPECT_EQ(format_utc_offset(-19800), "-05:30");
  EXPECT_EQ(format_utc_offset(7200), "+02:00");
  EXPECT_DOUBLE_EQ(*parse_exif_subseconds("606"), 0.606);
  EXPECT_DOUBLE_EQ(*parse_exif_subseconds(" 41 "), 0.41);
  EXPECT_FALSE(parse_exif_subseconds(""));
  EXPECT_FALSE(parse_exif_subseconds("4a"));
}

}  // namespace
}  // namespace trailray::track
