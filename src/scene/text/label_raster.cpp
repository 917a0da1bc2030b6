#include "scene/text/label_raster.hpp"

#include <algorithm>

namespace trailray::scene {

LabelBitmap rasterize_label(TextRasterizer& text, const PlacedLabel& label) {
  LabelBitmap out;
  out.width = std::max(label.box.width, 0);
  out.height = std::max(label.box.height, 0);
  const auto w = static_cast<std::size_t>(out.width), h = static_cast<std::size_t>(out.height);
  out.text_and_halo.assign(w * h * 2, 0);
  if (w == 0 || h == 0) return out;
  // White text on opaque black: the blended red byte is the glyph coverage.
  RgbaImage canvas{static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(h), {}};
  canvas.rgba.assign(w * h * 4, 0);
  for (std::size_t i = 3; i < canvas.rgba.size(); i += 4) canvas.rgba[i] = 255;
  text.draw(canvas, label.text, label.pen_x - label.box.x, label.baseline_y - label.box.y,
            {label.font_px, label.weight, {255, 255, 255, 255}});
  const int r = label.halo_px;
  const auto coverage = [&](int x, int y) { return canvas.rgba[(static_cast<std::size_t>(y) * w + x) * 4]; };
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      std::uint8_t halo = 0;
      // The disc of radius r + 0.5 around the pixel: a round, even outline.
      for (int dy = -r; dy <= r && halo < 255; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
          const int sx = x + dx, sy = y + dy;
          if (sx < 0 || sy < 0 || sx >= out.width || sy >= out.height) continue;
          if (dx * dx + dy * dy > r * r + r) continue;
          halo = std::max(halo, coverage(sx, sy));
        }
      const std::size_t i = (static_cast<std::size_t>(y) * w + static_cast<std::size_t>(x)) * 2;
      out.text_and_halo[i] = coverage(x, y);
      out.text_and_halo[i + 1] = halo;
    }
  return out;
}

RgbaImage rasterize_photo_label(const PlacedLabel& label) {
  RgbaImage out;
  out.width = static_cast<std::uint32_t>(std::max(label.box.width, 0));
  out.height = static_cast<std::uint32_t>(std::max(label.box.height, 0));
  out.rgba.assign(std::size_t{out.width} * out.height * 4, 0);
  if (label.image == nullptr || out.rgba.empty()) return out;
  paint_framed_photo(out, {0, 0, label.box.width, label.box.height}, label.image->pixels, label.frame_px,
                     kPhotoFrameColor);
  return out;
}

}  // namespace trailray::scene
