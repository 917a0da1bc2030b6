// Photos' pixels for their pins: a JPEG decoded scaled (the long side asked for, the aspect
// kept, its colour), turned upright by its EXIF orientation, a HEIC through libheif, and what
// cannot be decoded (not an image, past the size limit) refused naming the file.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <fstream>

#include "scene/pins/photo_decode.hpp"
#include "scene/pins/photo_pins.hpp"
#include "terrain/codecs/image_codec.hpp"
#include "test_support.hpp"

namespace trailray::scene {
namespace {

// A JPEG of one colour, width x height, written into `path`.
void write_flat_jpeg(const std::string& path, std::uint32_t width, std::uint32_t height, std::array<std::uint8_t, 3> rgb) {
  terrain::DecodedImage image;
  image.format = terrain::ImageFormat::jpeg;
  image.width = width;
  image.height = height;
  image.channels = 3;
  image.samples8.resize(std::size_t{width} * height * 3);
  for (std::size_t i = 0; i < image.samples8.size(); ++i) image.samples8[i] = rgb[i % 3];
  const std::vector<unsigned char> bytes = terrain::encode_jpeg(image, 90);
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

TEST(PhotoDecode, AJpegIsDecodedScaledToTheLongSideWithItsAspectAndColour) {
  const test::TempFile file("red.jpg");
  write_flat_jpeg(file.str(), 2000, 1000, {255, 0, 0});
  const RgbaImage small = decode_photo(file.str(), 128, 1);
  EXPECT_EQ(small.width, 128u);
  EXPECT_EQ(small.height, 64u);
  const auto p = small.pixel(64, 32);
  EXPECT_GT(p[0], 240);
  EXPECT_LT(p[1], 20);
  EXPECT_LT(p[2], 20);
  EXPECT_EQ(p[3], 255);
  // Never enlarged.
  const RgbaImage whole = decode_photo(file.str(), 4000, 1);
  EXPECT_EQ(whole.width, 2000u);
}

TEST(PhotoDecode, TheExifOrientationTurnsThePixelsUpright) {
  // 2 x 1: a red pixel, then a blue one.
  RgbaImage stored{2, 1, {255, 0, 0, 255, 0, 0, 255, 255}};
  const RgbaImage turned = apply_exif_orientation(stored, 6);  // stored turned 90 degrees clockwise
  ASSERT_EQ(turned.width, 1u);
  ASSERT_EQ(turned.height, 2u);
  EXPECT_EQ(turned.pixel(0, 0)[0], 255);  // the left pixel on top
  EXPECT_EQ(turned.pixel(0, 1)[2], 255);
  const RgbaImage back = apply_exif_orientation(stored, 8);
  EXPECT_EQ(back.pixel(0, 0)[2], 255);  // the right pixel on top
  EXPECT_EQ(apply_exif_orientation(stored, 2).pixel(0, 0)[2], 255);  // mirrored
  EXPECT_EQ(apply_exif_orientation(stored, 3).pixel(0, 0)[2], 255);  // half a turn
  EXPECT_EQ(apply_exif_orientation(stored, 9).rgba, stored.rgba);     // not an orientation: as stored
}

TEST(PhotoDecode, WhatIsNotAPhotoOrTooLargeIsRefusedNamingTheFile) {
  const test::TempFile text("notes.jpg", "these are not pixels");
  try {
    decode_photo(text.str(), 128, 1);
    FAIL() << "decoded a text file";
  } catch (const PhotoDecodeError& e) {
    EXPECT_NE(std::string(e.what()).find("notes.jpg"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not a JPEG or HEIF"), std::string::npos) << e.what();
  }
  const test::TempFile big("big.jpg");
  write_flat_jpeg(big.str(), 64, 64, {0, 255, 0});
  PhotoDecodeLimits limits;
  limits.max_file_bytes = 100;
  try {
    decode_photo(big.str(), 128, 1, limits);
    FAIL() << "decoded past the size limit";
  } catch (const PhotoDecodeError& e) {
    EXPECT_NE(std::string(e.what()).find("larger than the limit"), std::string::npos) << e.what();
  }
  const test::TempFile truncated("cut.jpg");
  {
    write_flat_jpeg(truncated.str(), 640, 480, {0, 0, 255});
    std::filesystem::resize_file(truncated.path(), 300);
  }
  // A truncated JPEG either decodes what it has (libjpeg-turbo's warning) or is refused: never a crash.
  try {
    const RgbaImage cut = decode_photo(truncated.str(), 64, 1);
    EXPECT_EQ(cut.width, 64u);
  } catch (const PhotoDecodeError& e) {
    EXPECT_NE(std::string(e.what()).find("cut.jpg"), std::string::npos);
  }
}

TEST(PhotoDecode, ThumbnailsOfAPhotoSetWarnForWhatCannotBeDecodedAndGoOn) {
  const test::TempFile good("good.jpg");
  write_flat_jpeg(good.str(), 300, 200, {255, 0, 0});
  const test::TempFile bad("bad.jpg", "nope");
  std::vector<track::PlacedPhoto> photos(2);
  photos[0].photo.path = bad.str();
  photos[1].photo.path = good.str();
  CollectedDiagnostics diagnostics;
  const auto thumbnails = decode_thumbnails(photos, kThumbnailLongSidePx, diagnostics);
  ASSERT_EQ(thumbnails.size(), 2u);
  EXPECT_EQ(thumbnails[0], nullptr);
  ASSERT_NE(thumbnails[1], nullptr);
  EXPECT_EQ(thumbnails[1]->pixels.width, 128u);
  ASSERT_EQ(diagnostics.warnings.size(), 1u);
  EXPECT_NE(diagnostics.warnings[0].find("bad.jpg"), std::string::npos);
  EXPECT_NE(diagnostics.warnings[0].find("plain pin"), std::string::npos);
}

TEST(PhotoDecode, RealCameraPhotosDecodeSmallAndQuickly) {
  TRAILRAY_REQUIRE_DATA(jpeg, "photos/exifsamples_DSCN0010.jpg");
  TRAILRAY_REQUIRE_DATA(heic, "photos/exifr_heic-iphone7.heic");
  const auto start = std::chrono::steady_clock::now();
  const RgbaImage j = decode_photo(jpeg.string(), 128, 1);
  const auto jpeg_done = std::chrono::steady_clock::now();
  const RgbaImage h = decode_photo(heic.string(), 128, 1);
  const auto heic_done = std::chrono::steady_clock::now();
  // DSCN0010 is 640 x 480; the iPhone's HEIC 4032 x 3024 with a stored thumbnail.
  EXPECT_EQ(j.width, 128u);
  EXPECT_EQ(j.height, 96u);
  EXPECT_EQ(std::max(h.width, h.height), 128u);
  EXPECT_GT(std::min(h.width, h.height), 60u);
  // A photo is not one colour: the pixels vary.
  int distinct = 0;
  for (std::uint32_t x = 1; x < j.width; ++x) distinct += j.pixel(x, 48) != j.pixel(x - 1, 48);
  EXPECT_GT(distinct, 20);
  std::printf("decoded %s in %.1f ms, %s in %.1f ms\n", jpeg.filename().c_str(),
              std::chrono::duration<double, std::milli>(jpeg_done - start).count(), heic.filename().c_str(),
              std::chrono::duration<double, std::milli>(heic_done - jpeg_done).count());
}

TEST(PhotoDecode, ALargeJpegIsDecodedAtAnEighth) {
  const test::TempFile file("large.jpg");
  write_flat_jpeg(file.str(), 4000, 3000, {10, 200, 30});  // 12 MP
  const auto start = std::chrono::steady_clock::now();
  const RgbaImage small = decode_photo(file.str(), 128, 1);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(small.width, 128u);
  EXPECT_EQ(small.height, 96u);
  EXPECT_NEAR(small.pixel(10, 10)[1], 200, 4);
  std::printf("12 MP JPEG (%ju bytes) to a thumbnail in %.1f ms\n", static_cast<std::uintmax_t>(std::filesystem::file_size(file.path())), ms);
  // Decoding every pixel takes ~100 ms on this machine's cores; at 1/8 it is a fraction of that.
  EXPECT_LT(ms, 1000.0);
}

}  // namespace
}  // namespace trailray::scene
