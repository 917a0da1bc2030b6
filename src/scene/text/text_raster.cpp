#include "scene/text/text_raster.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <string>
#include <type_traits>

#include "geo/utf8.hpp"
#include "scene/text/embedded_fonts.hpp"
#include "scene/scene_error.hpp"

namespace trailray::scene {
namespace {

using geo::kReplacementCharacter;
constexpr int kMaxPixelSize = 512;  // far beyond any legend; bounds the glyph bitmaps
// Light hinting: stems snap to whole pixels vertically only, so letters keep their shapes and
// spacing at small sizes (FreeType's recommended mode for anti-aliased UI text).
constexpr FT_Int32 kLoadFlags = FT_LOAD_TARGET_LIGHT;

struct LibraryDeleter {
  void operator()(FT_Library library) const { FT_Done_FreeType(library); }
};
struct FaceDeleter {
  void operator()(FT_Face face) const { FT_Done_Face(face); }
};
using LibraryHandle = std::unique_ptr<std::remove_pointer_t<FT_Library>, LibraryDeleter>;
using FaceHandle = std::unique_ptr<std::remove_pointer_t<FT_Face>, FaceDeleter>;

FaceHandle load_face(FT_Library library, std::span<const unsigned char> bytes, const char* name) {
  FT_Face face = nullptr;
  // FreeType reads the embedded bytes in place: they live as long as the program.
  const FT_Error error = FT_New_Memory_Face(library, bytes.data(), static_cast<FT_Long>(bytes.size()), 0, &face);
  if (error != 0)
    throw SceneError(std::string("FreeType cannot read the embedded font ") + name + " (error " +
                     std::to_string(error) + ")");
  return FaceHandle(face);
}

int round_26_6(FT_Pos value) { return static_cast<int>((value + 32) >> 6); }  // 26.6 fixed point -> pixels
int ceil_26_6(FT_Pos value) { return static_cast<int>((value + 63) >> 6); }

}  // namespace

struct TextRasterizer::Fonts {
  LibraryHandle library;  // declared first, so destroyed after the faces it made
  FaceHandle regular, bold;

  FT_Face face(FontWeight weight) const { return weight == FontWeight::bold ? bold.get() : regular.get(); }

  // The face sized to `pixel_size`; nullptr for a size out of range or one FreeType refuses.
  FT_Face sized(FontWeight weight, int pixel_size) const {
    if (pixel_size < 1 || pixel_size > kMaxPixelSize) return nullptr;
    FT_Face f = face(weight);
    if (FT_Set_Pixel_Sizes(f, 0, static_cast<FT_UInt>(pixel_size)) != 0) return nullptr;
    return f;
  }
};

TextRasterizer::TextRasterizer() : fonts_(std::make_unique<Fonts>()) {
  FT_Library library = nullptr;
  if (const FT_Error error = FT_Init_FreeType(&library); error != 0)
    throw SceneError("FreeType cannot start (error " + std::to_string(error) + ")");
  fonts_->library.reset(library);
  fonts_->regular = load_face(library, detail::dejavu_sans_font(), "DejaVuSans.ttf");
  fonts_->bold = load_face(library, detail::dejavu_sans_bold_font(), "DejaVuSans-Bold.ttf");
}

TextRasterizer::~TextRasterizer() = default;
TextRasterizer::TextRasterizer(TextRasterizer&&) noexcept = default;
TextRasterizer& TextRasterizer::operator=(TextRasterizer&&) noexcept = default;

namespace {

// Walks the glyphs of `text` along the pen, calling visit(glyph slot, pen x in pixels) for each
// glyph FreeType could load (with the bitmap rendered when `render` is set); returns the advance
// width in 26.6 pixels. `measure` and `draw` share it, so they cannot disagree on positions.
template <class Visit>
FT_Pos walk_glyphs(FT_Face face, std::string_view text, bool render, Visit&& visit) {
  const bool kerning = FT_HAS_KERNING(face);
  FT_Pos pen = 0;
  FT_UInt previous = 0;
  for (const char32_t code_point : decode_utf8(text)) {
    const FT_UInt index = FT_Get_Char_Index(face, code_point);  // 0: the missing-glyph box
    if (kerning && previous != 0 && index != 0) {
      FT_Vector delta{};
      if (FT_Get_Kerning(face, previous, index, FT_KERNING_DEFAULT, &delta) == 0) pen += delta.x;
    }
    if (FT_Load_Glyph(face, index, kLoadFlags | (render ? FT_LOAD_RENDER : 0)) != 0) continue;
    visit(face->glyph, round_26_6(pen));
    pen += face->glyph->advance.x;
    previous = index;
  }
  return pen;
}

TextExtent font_extent(FT_Face face, FT_Pos advance) {
  return {ceil_26_6(advance), round_26_6(face->size->metrics.ascender), round_26_6(-face->size->metrics.descender)};
}

void blend_glyph(RgbaImage& image, const FT_Bitmap& bitmap, int left, int top, const TextStyle& style) {
  if (bitmap.pixel_mode != FT_PIXEL_MODE_GRAY || bitmap.buffer == nullptr) return;
  const float alpha = static_cast<float>(style.color.a) / 255.0f;
  const float levels = static_cast<float>(std::max(bitmap.num_grays - 1, 1));
  const int rows = static_cast<int>(bitmap.rows), columns = static_cast<int>(bitmap.width);
  const int pitch = bitmap.pitch;
  for (int row = 0; row < rows; ++row) {
    // A negative pitch stores the rows bottom-up (FreeType's FT_Bitmap).
    const unsigned char* line = bitmap.buffer + static_cast<std::ptrdiff_t>(pitch >= 0 ? row : rows - 1 - row) *
                                                    static_cast<std::ptrdiff_t>(pitch >= 0 ? pitch : -pitch);
    for (int column = 0; column < columns; ++column) {
      if (line[column] == 0) continue;
      blend_pixel(image, left + column, top + row, glm::u8vec3(style.color),
                  alpha * static_cast<float>(line[column]) / levels);
    }
  }
}

}  // namespace

TextExtent TextRasterizer::measure(std::string_view text, int pixel_size, FontWeight weight) {
  FT_Face face = fonts_->sized(weight, pixel_size);
  if (face == nullptr) return {};
  return font_extent(face, walk_glyphs(face, text, false, [](FT_GlyphSlot, int) {}));
}

PixelRect TextRasterizer::draw(RgbaImage& image, std::string_view text, int x, int baseline, const TextStyle& style) {
  FT_Face face = fonts_->sized(style.weight, style.pixel_size);
  if (face == nullptr) return {x, baseline, 0, 0};
  const FT_Pos advance = walk_glyphs(face, text, true, [&](FT_GlyphSlot glyph, int pen_x) {
    blend_glyph(image, glyph->bitmap, x + pen_x + glyph->bitmap_left, baseline - glyph->bitmap_top, style);
  });
  const TextExtent extent = font_extent(face, advance);
  return {x, baseline - extent.ascent, extent.width, extent.height()};
}

bool TextRasterizer::has_glyph(char32_t code_point, FontWeight weight) const {
  return FT_Get_Char_Index(fonts_->face(weight), code_point) != 0;
}

std::string TextRasterizer::ellipsize(std::string_view text, std::size_t max_code_points, int max_width, int pixel_size,
                                      FontWeight weight) {
  std::u32string kept = decode_utf8(text);
  if (kept.size() <= max_code_points && measure(text, pixel_size, weight).width <= max_width) return encode_utf8(kept);
  const std::u32string ellipsis = U"\u2026";
  kept.resize(max_code_points > 0 ? std::min(kept.size(), max_code_points - 1) : 0);
  for (;;) {
    while (!kept.empty() && kept.back() == U' ') kept.pop_back();
    const std::string candidate = encode_utf8(kept + ellipsis);
    if (measure(candidate, pixel_size, weight).width <= max_width) return candidate;
    if (kept.empty()) return {};
    kept.pop_back();
  }
}

std::u32string decode_utf8(std::string_view text) {
  std::u32string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const geo::Utf8Step step = geo::next_utf8(text.substr(i));
    out.push_back(step.code_point);  // U+FFFD for a broken sequence, which resumes at the byte that broke it
    i += step.length;
  }
  return out;
}

std::string encode_utf8(std::u32string_view code_points) {
  std::string out;
  out.reserve(code_points.size());
  for (char32_t c : code_points) geo::append_utf8(out, c);
  return out;
}

}  // namespace trailray::scene
