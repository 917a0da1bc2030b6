#include "scene/film/film_photos.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace trailray::scene {

std::vector<FilmFrame> film_frames_with_photos(const FilmTiming& timing, const std::vector<double>& photo_times_unix_s,
                                               double seconds) {
  const auto pause_frames =
      seconds > 0.0 && std::isfinite(seconds) ? static_cast<std::size_t>(std::lround(seconds * timing.fps)) : 0u;
  // The photos that pause the film, by time.
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < photo_times_unix_s.size(); ++i) {
    const double t = photo_times_unix_s[i];
    if (pause_frames > 0 && std::isfinite(t) && t >= timing.span.start && t <= timing.span.end) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return photo_times_unix_s[a] < photo_times_unix_s[b]; });
  std::vector<FilmFrame> frames;
  frames.reserve(timing.frames + order.size() * pause_frames);
  auto next = order.begin();
  for (std::size_t f = 0; f < timing.frames; ++f) {
    frames.push_back({f, std::nullopt});
    // The frame that reaches a photo's time holds for it (several photos at once: one after the other).
    const double reached = f + 1 == timing.frames ? timing.span.end : timing.time_of(f);
    for (; next != order.end() && photo_times_unix_s[*next] <= reached; ++next)
      for (std::size_t k = 0; k < pause_frames; ++k) frames.push_back({f, *next});
  }
  return frames;
}

PixelRect film_photo_box(std::uint32_t frame_width, std::uint32_t frame_height, std::uint32_t photo_width,
                         std::uint32_t photo_height) {
  if (photo_width == 0 || photo_height == 0) return {};
  const double room_w = 0.8 * frame_width, room_h = 0.72 * frame_height;
  const double scale = std::min(room_w / photo_width, room_h / photo_height);
  const int w = std::max(1, static_cast<int>(std::lround(photo_width * scale)));
  const int h = std::max(1, static_cast<int>(std::lround(photo_height * scale)));
  // A little above the middle: the caption goes under it.
  return {(static_cast<int>(frame_width) - w) / 2, (static_cast<int>(frame_height) - h) / 2 - static_cast<int>(frame_height) / 30, w, h};
}

PixelRect draw_film_photo(RgbaImage& image, TextRasterizer& text, const RgbaImage& photo, const std::string& caption) {
  const PixelRect box = film_photo_box(image.width, image.height, photo.width, photo.height);
  if (box.empty()) return {};
  const int frame = std::max(3, static_cast<int>(std::lround(std::min(image.width, image.height) / 120.0)));
  const PixelRect framed{box.x - frame, box.y - frame, box.width + 2 * frame, box.height + 2 * frame};
  // A soft shadow: a few widening translucent dark rims.
  for (int rim = 3; rim >= 1; --rim)
    fill_rounded_rect(image, {framed.x - 2 * rim, framed.y - 2 * rim + rim, framed.width + 4 * rim, framed.height + 4 * rim},
                      2 * rim, {0, 0, 0, 40});
  paint_framed_photo(image, framed, photo, frame, {250, 250, 247, 255});
  PixelRect covered = framed;
  if (!caption.empty()) {
    const int size = std::max(10, static_cast<int>(std::lround(image.height / 32.0)));
    const TextExtent extent = text.measure(caption, size);
    const int pad = size / 3;
    const PixelRect band{(static_cast<int>(image.width) - extent.width) / 2 - pad, framed.bottom() + pad,
                         extent.width + 2 * pad, extent.height() + 2 * pad};
    fill_rounded_rect(image, band, pad, {20, 22, 25, 200});
    text.draw(image, caption, band.x + pad, band.y + pad + extent.ascent, {size, FontWeight::regular, {255, 255, 255, 255}});
    covered = {std::min(covered.x, band.x), covered.y, std::max(covered.right(), band.right()) - std::min(covered.x, band.x),
               band.bottom() - covered.y};
  }
  return covered;
}

}  // namespace trailray::scene
