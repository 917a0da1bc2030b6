#pragma once
// The film stops at each photo (`trailray video --photos ... --photo-seconds S`): at the first
// frame whose replay time reaches the photo's time, the clock holds for S seconds of film (that
// frame's camera and trail held) while the photo is shown large over the picture, painted on
// the CPU like the legend. GL-free.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "scene/film/film_timing.hpp"
#include "scene/pictures/image_paint.hpp"
#include "scene/pictures/rgba_image.hpp"
#include "scene/text/text_raster.hpp"

namespace trailray::scene {

// One frame of the film: which frame of the clock it shows (its time and camera) and which
// photo it shows over it (nullopt: none).
struct FilmFrame {
  std::size_t clock_frame = 0;
  std::optional<std::size_t> photo;
};

// The film's frames: each of the clock's in order, and after the first one whose time is at or
// past a photo's, round(seconds * fps) more frames of it showing that photo (photos in the order
// of their times; a photo outside the clock's span, without a time, or seconds <= 0: no pause).
// `photo_times_unix_s[i]` is photo i's time on the film's clock.
std::vector<FilmFrame> film_frames_with_photos(const FilmTiming& timing, const std::vector<double>& photo_times_unix_s,
                                               double seconds);

// Where a photo of `photo_width` x `photo_height` is shown on a frame: centred, as large as fits
// in 80 % of the frame's width and 72 % of its height, aspect kept, inside its frame.
PixelRect film_photo_box(std::uint32_t frame_width, std::uint32_t frame_height, std::uint32_t photo_width,
                         std::uint32_t photo_height);

// Paints the photo large over `image` (a white frame and a soft dark backdrop around it) with
// `caption` (its name and time) on a dark band under it; returns the rectangle covered.
PixelRect draw_film_photo(RgbaImage& image, TextRasterizer& text, const RgbaImage& photo, const std::string& caption);

}  // namespace trailray::scene
