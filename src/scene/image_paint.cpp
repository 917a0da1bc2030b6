#include "scene/image_paint.hpp"

#include <algorithm>
#include <cmath>

namespace trailray::scene {
namespace {

std::uint8_t mix(std::uint8_t over, std::uint8_t under, float alpha) {
  return static_cast<std::uint8_t>(
      std::lround(static_cast<float>(over) * alpha + static_cast<float>(under) * (1.0f - alpha)));
}

// The part of `rect` inside the image.
PixelRect clip(const RgbaImage& image, const PixelRect& rect) {
  const int x0 = std::max(rect.x, 0), y0 = std::max(rect.y, 0);
  const int x1 = static_cast<int>(std::min<long long>(rect.right(), image.width));
  const int y1 = static_cast<int>(std::min<long long>(rect.bottom(), image.height));
  return {x0, y0, std::max(x1 - x0, 0), std::max(y1 - y0, 0)};
}

}  // namespace

void blend_pixel(RgbaImage& image, int x, int y, glm::u8vec3 color, float alpha) {
  if (x < 0 || y < 0 || static_cast<std::uint32_t>(x) >= image.width || static_cast<std::uint32_t>(y) >= image.height)
    return;
  if (!(alpha > 0.0f)) return;  // also NaN
  alpha = std::min(alpha, 1.0f);
  std::uint8_t* pixel = &image.rgba[(static_cast<std::size_t>(y) * image.width + static_cast<std::size_t>(x)) * 4];
  pixel[0] = mix(color.r, pixel[0], alpha);
  pixel[1] = mix(color.g, pixel[1], alpha);
  pixel[2] = mix(color.b, pixel[2], alpha);
  pixel[3] = mix(255, pixel[3], alpha);
}

void fill_rect(RgbaImage& image, const PixelRect& rect, glm::u8vec4 color) {
  const PixelRect visible = clip(image, rect);
  const float alpha = static_cast<float>(color.a) / 255.0f;
  for (int y = visible.y; y < visible.bottom(); ++y)
    for (int x = visible.x; x < visible.right(); ++x) blend_pixel(image, x, y, glm::u8vec3(color), alpha);
}

void fill_rounded_rect(RgbaImage& image, const PixelRect& rect, int radius, glm::u8vec4 color) {
  radius = std::min({radius, rect.width / 2, rect.height / 2});
  if (radius <= 0) return fill_rect(image, rect, color);
  const PixelRect visible = clip(image, rect);
  const float alpha = static_cast<float>(color.a) / 255.0f;
  const float r = static_cast<float>(radius);
  // The rectangle is the set of points within `radius` of its inner rectangle [x0, x1] x [y0, y1].
  const float x0 = static_cast<float>(rect.x) + r, x1 = static_cast<float>(rect.right()) - r;
  const float y0 = static_cast<float>(rect.y) + r, y1 = static_cast<float>(rect.bottom()) - r;
  for (int y = visible.y; y < visible.bottom(); ++y) {
    for (int x = visible.x; x < visible.right(); ++x) {
      const float cx = static_cast<float>(x) + 0.5f, cy = static_cast<float>(y) + 0.5f;
      const float dx = cx - std::clamp(cx, x0, x1), dy = cy - std::clamp(cy, y0, y1);
      // Coverage of the pixel by the arc, approximated by the distance of its centre to the arc.
      const float coverage = std::clamp(r - std::sqrt(dx * dx + dy * dy) + 0.5f, 0.0f, 1.0f);
      blend_pixel(image, x, y, glm::u8vec3(color), alpha * coverage);
    }
  }
}

}  // namespace trailray::scene
