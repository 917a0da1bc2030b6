#pragma once
// Flat shapes blended into an RgbaImage on the CPU, for overlays drawn onto the read-back picture
// (the legend): rectangles, rounded rectangles, single pixels. Every write is clipped to the
// image, so a shape partly or wholly outside it is drawn where it overlaps and nowhere else.
//
// Blending is "over" on the sRGB-encoded bytes, as browsers and UI toolkits composite: a
// translucent dark panel then darkens snow as much as a viewer expects from such a panel, and
// anti-aliased text edges look as in any other UI. (The renderer's passes work in linear light;
// these overlays are drawn after the picture is encoded.)

#include <glm/glm.hpp>

#include "scene/pictures/rgba_image.hpp"

namespace trailray::scene {

// A rectangle of pixels: (x, y) is its top-left pixel in image coordinates (y grows down); it
// covers columns [x, x + width) and rows [y, y + height).
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;

  int right() const { return x + width; }    // one past the last column
  int bottom() const { return y + height; }  // one past the last row
  bool empty() const { return width <= 0 || height <= 0; }
  bool contains(int px, int py) const { return px >= x && px < right() && py >= y && py < bottom(); }
  bool contains(const PixelRect& other) const {
    return other.x >= x && other.y >= y && other.right() <= right() && other.bottom() <= bottom();
  }
  bool intersects(const PixelRect& other) const {
    return x < other.right() && other.x < right() && y < other.bottom() && other.y < bottom();
  }
};

// Colour `color` (sRGB bytes) over pixel (x, y) with opacity `alpha` (0..1, clamped). Outside
// the image: nothing.
void blend_pixel(RgbaImage& image, int x, int y, glm::u8vec3 color, float alpha);

// A rectangle of colour `color` (sRGB bytes, alpha 255 = opaque), clipped to the image.
void fill_rect(RgbaImage& image, const PixelRect& rect, glm::u8vec4 color);

// The same with corners rounded to `radius` pixels, anti-aliased (each corner pixel blended by
// how much of it the arc covers); radius 0 is fill_rect.
void fill_rounded_rect(RgbaImage& image, const PixelRect& rect, int radius, glm::u8vec4 color);

// `image` resampled to width x height: each output pixel the average of the source pixels under
// its footprint when shrinking, bilinear between the nearest four when enlarging.
RgbaImage resampled(const RgbaImage& image, int width, int height);

// A photo in a frame: `photo` resampled into `rect` less `frame` pixels on each side, the frame
// filled with `frame_color`; clipped to the image.
void paint_framed_photo(RgbaImage& image, const PixelRect& rect, const RgbaImage& photo, int frame,
                        glm::u8vec4 frame_color);

}  // namespace trailray::scene
