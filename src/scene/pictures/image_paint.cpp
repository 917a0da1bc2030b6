#include "scene/pictures/image_paint.hpp"

#include <algorithm>
#include <array>
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

RgbaImage resampled(const RgbaImage& image, int width, int height) {
  RgbaImage out;
  if (width <= 0 || height <= 0 || image.width == 0 || image.height == 0) return out;
  out.width = static_cast<std::uint32_t>(width);
  out.height = static_cast<std::uint32_t>(height);
  out.rgba.assign(std::size_t{out.width} * out.height * 4, 0);
  const double fx = static_cast<double>(image.width) / width, fy = static_cast<double>(image.height) / height;
  const auto at = [&](int x, int y, int c) {
    x = std::clamp(x, 0, static_cast<int>(image.width) - 1);
    y = std::clamp(y, 0, static_cast<int>(image.height) - 1);
    return static_cast<double>(image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4 + c]);
  };
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::array<double, 4> value{};
      if (fx > 1.0 || fy > 1.0) {  // the footprint's pixels, averaged
        const int x0 = static_cast<int>(x * fx), y0 = static_cast<int>(y * fy);
        const int x1 = std::max(x0 + 1, static_cast<int>(std::ceil((x + 1) * fx)));
        const int y1 = std::max(y0 + 1, static_cast<int>(std::ceil((y + 1) * fy)));
        for (int sy = y0; sy < y1; ++sy)
          for (int sx = x0; sx < x1; ++sx)
            for (int c = 0; c < 4; ++c) value[c] += at(sx, sy, c);
        for (double& v : value) v /= static_cast<double>((x1 - x0) * (y1 - y0));
      } else {  // bilinear
        const double sx = (x + 0.5) * fx - 0.5, sy = (y + 0.5) * fy - 0.5;
        const int ix = static_cast<int>(std::floor(sx)), iy = static_cast<int>(std::floor(sy));
        const double tx = sx - ix, ty = sy - iy;
        for (int c = 0; c < 4; ++c)
          value[c] = (at(ix, iy, c) * (1 - tx) + at(ix + 1, iy, c) * tx) * (1 - ty) +
                     (at(ix, iy + 1, c) * (1 - tx) + at(ix + 1, iy + 1, c) * tx) * ty;
      }
      for (int c = 0; c < 4; ++c)
        out.rgba[(static_cast<std::size_t>(y) * out.width + x) * 4 + c] =
            static_cast<std::uint8_t>(std::clamp(std::lround(value[c]), 0L, 255L));
    }
  return out;
}

void paint_framed_photo(RgbaImage& image, const PixelRect& rect, const RgbaImage& photo, int frame,
                        glm::u8vec4 frame_color) {
  fill_rect(image, rect, frame_color);
  const PixelRect inner{rect.x + frame, rect.y + frame, rect.width - 2 * frame, rect.height - 2 * frame};
  if (inner.empty()) return;
  const RgbaImage scaled = resampled(photo, inner.width, inner.height);
  for (int y = 0; y < inner.height; ++y)
    for (int x = 0; x < inner.width; ++x) {
      const auto p = scaled.pixel(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
      blend_pixel(image, inner.x + x, inner.y + y, {p[0], p[1], p[2]}, p[3] / 255.0f);
    }
}

}  // namespace trailray::scene
