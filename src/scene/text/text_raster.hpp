#pragma once
// Lines of UTF-8 text drawn into an RgbaImage on the CPU with FreeType, in the fonts compiled
// into the program (render/embedded_fonts.hpp: DejaVu Sans, regular and bold), so the headless
// `render` command and the viewer (which uploads the same pixels) draw identical overlays on any
// machine. Glyphs are rendered as 8-bit coverage (light hinting: crisp vertical stems, shapes
// kept) and blended over the image with render/image_paint.hpp, clipped to it.
//
// One line at a time: no wrapping, no bidirectional text, no shaping beyond the font's kerning
// table; enough for labels and track names in Latin, Greek and Cyrillic. A code point the font
// lacks draws the font's missing-glyph box; malformed UTF-8 decodes to U+FFFD.

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include "scene/pictures/rgba_image.hpp"
#include "scene/pictures/image_paint.hpp"

namespace trailray::scene {

enum class FontWeight { regular, bold };

struct TextStyle {
  int pixel_size = 16;  // the em size in pixels (1..512; anything else draws nothing)
  FontWeight weight = FontWeight::regular;
  glm::u8vec4 color{255, 255, 255, 255};  // sRGB bytes; alpha scales the glyphs' coverage
};

// The size of a line of text: its advance width, and the font's ascent and descent at that size
// (font-wide, not this text's ink: lines of different text then share a baseline and a height).
struct TextExtent {
  int width = 0;
  int ascent = 0;   // pixels above the baseline
  int descent = 0;  // pixels below the baseline (positive)

  int height() const { return ascent + descent; }
};

// Owns one FreeType library and the embedded faces (nothing global: each rasterizer is
// independent; one rasterizer must not be used by two threads at once). Move-only.
class TextRasterizer {
 public:
  // Throws SceneError when FreeType cannot start or cannot read an embedded font.
  TextRasterizer();
  ~TextRasterizer();
  TextRasterizer(TextRasterizer&&) noexcept;
  TextRasterizer& operator=(TextRasterizer&&) noexcept;
  TextRasterizer(const TextRasterizer&) = delete;
  TextRasterizer& operator=(const TextRasterizer&) = delete;

  // The extent `draw` would give `text` at `pixel_size`; all zero for an invalid size.
  TextExtent measure(std::string_view text, int pixel_size, FontWeight weight = FontWeight::regular);

  // Draws `text` with its pen starting at x and its baseline on row `baseline`; returns its box
  // (x, baseline - ascent, width, ascent + descent), not clipped to the image. Pixels outside
  // the image are skipped.
  PixelRect draw(RgbaImage& image, std::string_view text, int x, int baseline, const TextStyle& style);

  // Whether the font has a glyph of its own for `code_point` (not the missing-glyph box).
  bool has_glyph(char32_t code_point, FontWeight weight = FontWeight::regular) const;

  // `text` cut to at most `max_code_points` code points and `max_width` pixels at `pixel_size`,
  // ending in "…" where anything was cut (trailing spaces before it dropped). Empty when not
  // even the ellipsis fits.
  std::string ellipsize(std::string_view text, std::size_t max_code_points, int max_width, int pixel_size,
                        FontWeight weight = FontWeight::regular);

 private:
  struct Fonts;
  std::unique_ptr<Fonts> fonts_;
};

// The code points of UTF-8 text; each malformed sequence (a stray continuation byte, a truncated
// or overlong sequence, a surrogate, a value above U+10FFFF) becomes U+FFFD.
std::u32string decode_utf8(std::string_view text);
// The UTF-8 encoding of code points (invalid ones become U+FFFD).
std::string encode_utf8(std::u32string_view code_points);

}  // namespace trailray::scene
