// The film's stops at photos: the frames the clock gives, and round(seconds * fps) more of the
// frame that reaches each photo's time; a photo outside the span, without a time, or no seconds:
// no stop. The photo shown large fits the frame.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/film/film_photos.hpp"

namespace trailray::scene {
namespace {

FilmTiming ten_frames() {
  FilmTiming t;
  t.span = {1000.0, 1900.0};  // frame i at 1000 + 100 i
  t.frames = 10;
  t.fps = 10.0;
  return t;
}

TEST(FilmPhotos, EachPhotoHoldsTheFrameThatReachesItsTime) {
  const std::vector<double> times{1450.0, 1200.0, 5000.0, std::nan("")};
  const std::vector<FilmFrame> frames = film_frames_with_photos(ten_frames(), times, 0.5);
  ASSERT_EQ(frames.size(), 10u + 2 * 5u) << "two photos in the span, 5 frames each";
  // Frames 0..2 (1200 reached at frame 2), then five of frame 2 with photo 1.
  for (std::size_t i = 0; i <= 2; ++i) EXPECT_EQ(frames[i].clock_frame, i);
  for (std::size_t i = 3; i < 8; ++i) {
    EXPECT_EQ(frames[i].clock_frame, 2u);
    EXPECT_EQ(frames[i].photo, 1u);
  }
  EXPECT_FALSE(frames[8].photo);
  EXPECT_EQ(frames[8].clock_frame, 3u);
  // 1450 reached at frame 5 (1500): after it, five frames of photo 0.
  EXPECT_EQ(frames[10].clock_frame, 5u);
  EXPECT_FALSE(frames[10].photo);
  for (std::size_t i = 11; i < 16; ++i) EXPECT_EQ(frames[i].photo, 0u);
  EXPECT_EQ(frames.back().clock_frame, 9u);
  EXPECT_EQ(film_frames_with_photos(ten_frames(), times, 0.0).size(), 10u);
}

TEST(FilmPhotos, ThePhotoShownLargeFitsTheFrameWithItsAspect) {
  const PixelRect wide = film_photo_box(1280, 720, 4000, 3000);
  EXPECT_EQ(wide.height, std::lround(0.72 * 720));
  EXPECT_NEAR(static_cast<double>(wide.width) / wide.height, 4.0 / 3.0, 0.01);
  EXPECT_NEAR(wide.x + wide.width / 2.0, 640, 1);
  const PixelRect tall = film_photo_box(1280, 720, 3000, 4000);
  EXPECT_LE(tall.height, 720 * 0.72 + 1);
  EXPECT_LT(tall.width, tall.height);
  RgbaImage frame{320, 180, std::vector<std::uint8_t>(320 * 180 * 4, 0)};
  RgbaImage red{40, 30, {}};
  for (int i = 0; i < 40 * 30; ++i) red.rgba.insert(red.rgba.end(), {255, 0, 0, 255});
  TextRasterizer text;
  const PixelRect covered = draw_film_photo(frame, text, red, "red.jpg");
  EXPECT_EQ(frame.pixel(160, 80)[0], 255);
  EXPECT_EQ(frame.pixel(160, 80)[1], 0);
  EXPECT_TRUE(covered.contains(160, 170 - 20)) << "the caption under it";
}

}  // namespace
}  // namespace trailray::scene
