// UTF-8 decoding, and text drawn with the embedded fonts into an RgbaImage (pure CPU).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "scene/pictures/image_paint.hpp"
#include "scene/text/text_raster.hpp"

namespace trailray::scene {
namespace {

RgbaImage filled(std::uint32_t width, std::uint32_t height, glm::u8vec4 color) {
  RgbaImage image{width, height, std::vector<std::uint8_t>(std::size_t{width} * height * 4)};
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    image.rgba[i] = color.r;
    image.rgba[i + 1] = color.g;
    image.rgba[i + 2] = color.b;
    image.rgba[i + 3] = color.a;
  }
  return image;
}

RgbaImage black(std::uint32_t width, std::uint32_t height) { return filled(width, height, {0, 0, 0, 255}); }

// Pixels with any colour channel above 0 (the ink of white text on black).
std::size_t ink(const RgbaImage& image) {
  std::size_t count = 0;
  for (std::uint32_t y = 0; y < image.height; ++y)
    for (std::uint32_t x = 0; x < image.width; ++x) count += image.pixel(x, y)[0] > 0 ? 1 : 0;
  return count;
}

TEST(DecodeUtf8, DecodesAsciiAndMultiByteSequences) {
  EXPECT_EQ(decode_utf8("Zürich"), U"Zürich");
  EXPECT_EQ(decode_utf8("Škofja Loka"), U"Škofja Loka");
  EXPECT_EQ(decode_utf8("€"), std::u32string(1, U'\u20AC'));
  EXPECT_EQ(decode_utf8("\xF0\x9F\x98\x80"), std::u32string(1, U'\U0001F600'));
  EXPECT_EQ(decode_utf8(""), U"");
}

TEST(DecodeUtf8, MalformedSequencesBecomeReplacementCharacters) {
  EXPECT_EQ(decode_utf8("a\x80z"), U"a\uFFFDz");          // stray continuation byte
  EXPECT_EQ(decode_utf8("a\xE2\x82z"), U"a\uFFFDz");      // truncated, resumes at 'z'
  EXPECT_EQ(decode_utf8("\xC0\xAF"), U"\uFFFD\uFFFD");    // overlong lead, then a stray byte
  EXPECT_EQ(decode_utf8("\xE0\x80\xAF"), U"\uFFFD");      // overlong 3-byte '/'
  EXPECT_EQ(decode_utf8("\xED\xA0\x80"), U"\uFFFD");      // a UTF-16 surrogate
  EXPECT_EQ(decode_utf8("\xF4\x90\x80\x80"), U"\uFFFD");  // above U+10FFFF
  EXPECT_EQ(decode_utf8("\xFF"), U"\uFFFD");
}

TEST(EncodeUtf8, IsTheInverseOfDecoding) {
  for (const std::string text : {"Zürich", "Škofja Loka", "Αθήνα", "Москва", "\xF0\x9F\x98\x80", "a…b"})
    EXPECT_EQ(encode_utf8(decode_utf8(text)), text);
  EXPECT_EQ(encode_utf8(std::u32string(1, char32_t{0xD800})), "\xEF\xBF\xBD");
}

TEST(TextRasterizer, EmbeddedFontsCoverLatinGreekAndCyrillic) {
  TextRasterizer text;
  for (const char32_t c : std::u32string(U"Aaüß ŠšŽžČčŁłŐőΩωЖж…\u2212"))
    EXPECT_TRUE(text.has_glyph(c)) << "U+" << std::hex << static_cast<std::uint32_t>(c);
  EXPECT_TRUE(text.has_glyph(U'Š', FontWeight::bold));
  EXPECT_FALSE(text.has_glyph(char32_t{0xFFFF}));  // a noncharacter: no font has it
}

TEST(TextRasterizer, MeasureGrowsWithTextAndSize) {
  TextRasterizer text;
  const TextExtent short_text = text.measure("Speed", 20), long_text = text.measure("Speed (km/h)", 20);
  EXPECT_GT(short_text.width, 20);
  EXPECT_GT(long_text.width, short_text.width);
  EXPECT_GT(text.measure("Speed", 40).width, short_text.width * 3 / 2);
  EXPECT_GT(text.measure("Speed", 20, FontWeight::bold).width, short_text.width);
  // The font's ascent and descent, whatever the text: lines share a baseline and a height.
  EXPECT_EQ(text.measure("", 20).height(), short_text.height());
  EXPECT_EQ(text.measure("", 20).width, 0);
  EXPECT_NEAR(short_text.height(), 23, 2);  // DejaVu Sans: 1.164 em from ascender to descender
  EXPECT_EQ(text.measure("Speed", 0).width, 0);
  EXPECT_EQ(text.measure("Speed", -3).height(), 0);
}

TEST(TextRasterizer, DrawsInkInsideTheReturnedBox) {
  TextRasterizer text;
  RgbaImage image = black(300, 80);
  const PixelRect box =
      text.draw(image, "Hello, Zürich (gjy)", 10, 50, {24, FontWeight::regular, {255, 255, 255, 255}});
  EXPECT_EQ(box.x, 10);
  EXPECT_EQ(box.width, text.measure("Hello, Zürich (gjy)", 24).width);
  EXPECT_LT(box.y, 50);
  EXPECT_GT(box.bottom(), 50);
  std::size_t bright = 0;
  for (std::uint32_t y = 0; y < image.height; ++y)
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const auto p = image.pixel(x, y);
      if (p[0] == 0) continue;
      // One pixel of slack sideways: a glyph's ink may overhang its advance a little.
      const PixelRect slack{box.x - 1, box.y, box.width + 2, box.height};
      EXPECT_TRUE(slack.contains(int(x), int(y))) << x << "," << y;
      EXPECT_EQ(p[0], p[1]);  // white text stays grey-scale
      bright += p[0] > 200 ? 1 : 0;
    }
  EXPECT_GT(bright, 100u);
}

TEST(TextRasterizer, DifferentTextDrawsDifferentPixelsAndTheSameTextTheSame) {
  TextRasterizer text;
  const TextStyle style{16, FontWeight::regular, {255, 255, 255, 255}};
  RgbaImage a = black(120, 30), b = black(120, 30), c = black(120, 30);
  text.draw(a, "12.5", 4, 20, style);
  text.draw(b, "12.6", 4, 20, style);
  text.draw(c, "12.5", 4, 20, style);
  EXPECT_NE(a.rgba, b.rgba);
  EXPECT_EQ(a.rgba, c.rgba);
  RgbaImage bold = black(120, 30);
  text.draw(bold, "12.5", 4, 20, {16, FontWeight::bold, {255, 255, 255, 255}});
  EXPECT_GT(ink(bold), ink(a));
}

TEST(TextRasterizer, NonAsciiLettersDrawTheirOwnGlyphsNotTheMissingGlyphBox) {
  TextRasterizer text;
  const TextStyle style{32, FontWeight::regular, {255, 255, 255, 255}};
  RgbaImage missing = black(60, 50);
  text.draw(missing, encode_utf8(std::u32string(1, char32_t{0xFFFF})), 10, 38, style);
  ASSERT_GT(ink(missing), 0u);  // the box itself is ink
  for (const std::string letter : {"ü", "Š", "ž", "Ж", "Ω"}) {
    RgbaImage image = black(60, 50);
    text.draw(image, letter, 10, 38, style);
    EXPECT_GT(ink(image), 20u) << letter;
    EXPECT_NE(image.rgba, missing.rgba) << letter;
  }
  // The diaeresis is ink of its own: "Zürich" is not "Zurich".
  RgbaImage with = black(200, 50), without = black(200, 50);
  text.draw(with, "Zürich", 10, 38, style);
  text.draw(without, "Zurich", 10, 38, style);
  EXPECT_GT(ink(with), ink(without));
}

TEST(TextRasterizer, ClipsToTheImageExactly) {
  // Text drawn partly outside a small image leaves there exactly the pixels the same text leaves
  // in the same place on a larger canvas.
  TextRasterizer text;
  const TextStyle style{28, FontWeight::regular, {255, 255, 255, 255}};
  const int pad = 100;
  for (const glm::ivec2 at : {glm::ivec2(-15, 20), glm::ivec2(30, 8), glm::ivec2(5, 60), glm::ivec2(-40, 70)}) {
    RgbaImage small = black(60, 40), large = black(60 + 2 * pad, 40 + 2 * pad);
    text.draw(small, "Škofja Loka", at.x, at.y, style);
    text.draw(large, "Škofja Loka", at.x + pad, at.y + pad, style);
    for (std::uint32_t y = 0; y < small.height; ++y)
      for (std::uint32_t x = 0; x < small.width; ++x)
        ASSERT_EQ(small.pixel(x, y), large.pixel(x + pad, y + pad))
            << at.x << "," << at.y << " pixel " << x << "," << y;
  }
  RgbaImage tiny = black(1, 1), empty = black(0, 0);
  text.draw(tiny, "Wide text", -3, 10, style);
  text.draw(empty, "Wide text", 0, 10, style);
  EXPECT_EQ(tiny.rgba.size(), 4u);
  EXPECT_TRUE(empty.rgba.empty());
}

TEST(TextRasterizer, TransparentColourDrawsNothing) {
  TextRasterizer text;
  RgbaImage image = black(100, 40);
  text.draw(image, "Invisible", 2, 30, {20, FontWeight::regular, {255, 255, 255, 0}});
  EXPECT_EQ(ink(image), 0u);
}

TEST(TextRasterizer, EllipsizeCutsLongTextByCodePointsAndWidth) {
  TextRasterizer text;
  EXPECT_EQ(text.ellipsize("Zürich", 40, 1000, 16), "Zürich");
  const std::string long_name = "Hochtour über den Großvenediger-Nordgrat mit Abstieg zur Kürsinger Hütte";
  const std::string cut = text.ellipsize(long_name, 40, 10000, 16);
  const std::u32string cut_points = decode_utf8(cut);
  EXPECT_EQ(cut_points.size(), 40u);
  EXPECT_EQ(cut_points.back(), U'…');
  EXPECT_EQ(cut_points.find(U'\uFFFD'), std::u32string::npos);  // never splits a code point
  EXPECT_EQ(cut.substr(0, cut.size() - 3), long_name.substr(0, cut.size() - 3));
  // Narrow: as much as fits, then the ellipsis.
  const std::string narrow = text.ellipsize(long_name, 40, 120, 16);
  EXPECT_LE(text.measure(narrow, 16).width, 120);
  EXPECT_GT(text.measure(narrow, 16).width, 80);
  EXPECT_EQ(decode_utf8(narrow).back(), U'…');
  // A space before the cut is dropped: "Hochtour …" reads as "Hochtour…".
  EXPECT_EQ(text.ellipsize("Hochtour über", 10, 1000, 16), "Hochtour…");
  EXPECT_EQ(text.ellipsize(long_name, 40, 3, 16), "");
}

TEST(TextRasterizer, KeepsWorkingAfterAMove) {
  TextRasterizer first;
  TextRasterizer second = std::move(first);
  RgbaImage image = black(100, 40);
  second.draw(image, "moved", 2, 30, {20, FontWeight::regular, {255, 255, 255, 255}});
  EXPECT_GT(ink(image), 0u);
  // Two rasterizers are independent: each has its own FreeType library.
  TextRasterizer third;
  EXPECT_EQ(third.measure("moved", 20).width, second.measure("moved", 20).width);
}

TEST(ImagePaint, BlendsOverAndClips) {
  RgbaImage image = black(4, 3);
  fill_rect(image, {-2, -2, 4, 4}, {255, 255, 255, 128});  // covers (0..1, 0..1)
  EXPECT_EQ(image.pixel(0, 0)[0], 128);
  EXPECT_EQ(image.pixel(1, 1)[0], 128);
  EXPECT_EQ(image.pixel(2, 0)[0], 0);
  EXPECT_EQ(image.pixel(0, 2)[0], 0);
  fill_rect(image, {3, 2, 100, 100}, {10, 20, 30, 255});
  EXPECT_EQ(image.pixel(3, 2), (std::array<std::uint8_t, 4>{10, 20, 30, 255}));
  blend_pixel(image, 4, 0, {255, 0, 0}, 1.0f);  // outside: nothing, no crash
  blend_pixel(image, -1, 0, {255, 0, 0}, 1.0f);
  EXPECT_EQ(image.rgba.size(), 4u * 3u * 4u);
}

TEST(ImagePaint, RoundedRectangleLeavesCornersOpen) {
  RgbaImage image = black(40, 30);
  fill_rounded_rect(image, {5, 5, 30, 20}, 8, {255, 255, 255, 255});
  EXPECT_EQ(image.pixel(5, 5)[0], 0);  // the corner itself stays outside the arc
  EXPECT_EQ(image.pixel(34, 24)[0], 0);
  EXPECT_EQ(image.pixel(20, 15)[0], 255);  // the middle is filled
  EXPECT_EQ(image.pixel(5, 15)[0], 255);   // so is the middle of an edge
  EXPECT_EQ(image.pixel(4, 15)[0], 0);     // and nothing outside
  const auto arc = image.pixel(7, 7)[0];   // on the arc: partly covered
  EXPECT_GT(arc, 0);
  EXPECT_LT(arc, 255);
}

}  // namespace
}  // namespace trailray::scene
