#pragma once
// A placed label's pixels for the labels pass: the text's coverage and a dark halo around it,
// rasterized on the CPU with the program's fonts (scene/text/text_raster.hpp) at the size the layout
// measured, so the pass only copies texels one to one: crisp at any pixel ratio.

#include <cstdint>
#include <vector>

#include "scene/pictures/image_paint.hpp"
#include "scene/text/label_layout.hpp"
#include "scene/text/text_raster.hpp"

namespace trailray::scene {

// Two bytes per pixel, rows top-down: the text's coverage, then the halo's (the text's coverage
// grown by the halo's width, a disc around each pixel). The size of the label's box.
struct LabelBitmap {
  int width = 0, height = 0;
  std::vector<std::uint8_t> text_and_halo;

  std::uint8_t text(int x, int y) const { return text_and_halo[(static_cast<std::size_t>(y) * width + x) * 2]; }
  std::uint8_t halo(int x, int y) const { return text_and_halo[(static_cast<std::size_t>(y) * width + x) * 2 + 1]; }
};

LabelBitmap rasterize_label(TextRasterizer& text, const PlacedLabel& label);

// A photo's placed label (label.image set): its thumbnail resampled into the box inside a white
// frame, opaque sRGB RGBA the size of the box.
RgbaImage rasterize_photo_label(const PlacedLabel& label);
inline constexpr glm::u8vec4 kPhotoFrameColor{250, 250, 247, 255};

}  // namespace trailray::scene
