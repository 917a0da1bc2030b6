#include "web/page_legend.hpp"

#include <algorithm>
#include <cmath>

#include "scene/text/legend_content.hpp"
#include "scene/pictures/rgba_image.hpp"

namespace trailray::web {
namespace {

scene::RgbaImage filled(std::uint32_t width, std::uint32_t height, std::uint8_t value) {
  scene::RgbaImage image;
  image.width = width;
  image.height = height;
  image.rgba.assign(std::size_t{width} * height * 4, value);
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
  return image;
}

}  // namespace

PageLegend page_legend(const scene::Scene& scene, std::uint32_t width, std::uint32_t height) {
  PageLegend out;
  out.rect = scene::scene_legend_panel(width, height, scene);
  const scene::PixelRect image_rect{0, 0, static_cast<int>(width), static_cast<int>(height)};
  out.rect.width = std::min(out.rect.right(), image_rect.right()) - std::max(out.rect.x, 0);
  out.rect.height = std::min(out.rect.bottom(), image_rect.bottom()) - std::max(out.rect.y, 0);
  out.rect.x = std::max(out.rect.x, 0);
  out.rect.y = std::max(out.rect.y, 0);
  if (out.rect.empty()) return {};
  scene::RgbaImage black = filled(width, height, 0), white = filled(width, height, 255);
  scene::draw_scene_legend(black, scene);
  scene::draw_scene_legend(white, scene);
  out.rgba.resize(std::size_t(out.rect.width) * out.rect.height * 4);
  for (int y = 0; y < out.rect.height; ++y) {
    for (int x = 0; x < out.rect.width; ++x) {
      const std::size_t from = (std::size_t(out.rect.y + y) * width + std::size_t(out.rect.x + x)) * 4;
      const std::size_t to = (std::size_t(y) * out.rect.width + std::size_t(x)) * 4;
      // The most a channel gained over white's: 1 - alpha (all three agree up to rounding).
      int through = 0;
      for (int c = 0; c < 3; ++c) through = std::max(through, white.rgba[from + c] - black.rgba[from + c]);
      const int alpha = 255 - std::clamp(through, 0, 255);
      for (int c = 0; c < 3; ++c)
        out.rgba[to + c] =
            alpha == 0 ? 0 : static_cast<std::uint8_t>(std::min(255, (black.rgba[from + c] * 255 + alpha / 2) / alpha));
      out.rgba[to + 3] = static_cast<std::uint8_t>(alpha);
    }
  }
  return out;
}

}  // namespace trailray::web
