#include "terrain/codecs/image_codec.hpp"

#include <gtest/gtest.h>
#include <webp/encode.h>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "test_support.hpp"

namespace trailray::terrain {
namespace {

using Bytes = std::vector<unsigned char>;

Bytes read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return Bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

Bytes text_bytes(std::string_view text) { return Bytes(text.begin(), text.end()); }

// PNG files built chunk by chunk with zlib, independently of libpng's writer, so the decoder is
// checked against the format rather than against our own encoder.
class PngBuilder {
 public:
  PngBuilder() : out_{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'} {}

  PngBuilder& chunk(std::string_view type, const Bytes& data) {
    put32(static_cast<std::uint32_t>(data.size()));
    const std::size_t start = out_.size();
    out_.insert(out_.end(), type.begin(), type.end());
    out_.insert(out_.end(), data.begin(), data.end());
    put32(static_cast<std::uint32_t>(crc32(0, out_.data() + start, static_cast<uInt>(out_.size() - start))));
    return *this;
  }
  PngBuilder& ihdr(std::uint32_t w, std::uint32_t h, int depth, int color_type, int interlace = 0) {
    Bytes d;
    append32(d, w);
    append32(d, h);
    d.insert(d.end(), {static_cast<unsigned char>(depth), static_cast<unsigned char>(color_type), 0, 0,
                       static_cast<unsigned char>(interlace)});
    return chunk("IHDR", d);
  }
  // `scanlines`: each row already prefixed with its filter byte.
  PngBuilder& idat(const Bytes& scanlines) {
    uLongf size = compressBound(static_cast<uLong>(scanlines.size()));
    Bytes z(size);
    EXPECT_EQ(compress(z.data(), &size, scanlines.data(), static_cast<uLong>(scanlines.size())), Z_OK);
    z.resize(size);
    return chunk("IDAT", z);
  }
  Bytes end() {
    chunk("IEND", {});
    return out_;
  }

  static void append32(Bytes& b, std::uint32_t v) {
    b.insert(b.end(), {static_cast<unsigned char>(v >> 24), static_cast<unsigned char>(v >> 16),
                       static_cast<unsigned char>(v >> 8), static_cast<unsigned char>(v)});
  }

 private:
  void put32(std::uint32_t v) { append32(out_, v); }
  Bytes out_;
};

// Rows of `bytes_per_row` bytes each, filter type 0 (none) prepended.
Bytes unfiltered(const Bytes& pixels, std::size_t bytes_per_row) {
  Bytes out;
  for (std::size_t i = 0; i < pixels.size(); i += bytes_per_row) {
    out.push_back(0);
    out.insert(out.end(), pixels.begin() + static_cast<std::ptrdiff_t>(i),
               pixels.begin() + static_cast<std::ptrdiff_t>(i + bytes_per_row));
  }
  return out;
}

// 16-bit samples as PNG stores them: big-endian.
Bytes big_endian(const std::vector<std::uint16_t>& samples) {
  Bytes out;
  for (std::uint16_t s : samples)
    out.insert(out.end(), {static_cast<unsigned char>(s >> 8), static_cast<unsigned char>(s)});
  return out;
}

DecodedImage rgb8(std::uint32_t w, std::uint32_t h, std::uint32_t channels) {
  DecodedImage image;
  image.width = w;
  image.height = h;
  image.channels = channels;
  image.samples8.resize(std::size_t{w} * h * channels);
  for (std::size_t i = 0; i < image.samples8.size(); ++i)
    image.samples8[i] = static_cast<std::uint8_t>((i * 37 + i / 7) % 256);
  return image;
}

// A smooth picture: lossy codecs keep it close.
DecodedImage gradient(std::uint32_t w, std::uint32_t h, std::uint32_t channels) {
  DecodedImage image;
  image.width = w;
  image.height = h;
  image.channels = channels;
  for (std::uint32_t r = 0; r < h; ++r)
    for (std::uint32_t c = 0; c < w; ++c)
      for (std::uint32_t k = 0; k < channels; ++k)
        image.samples8.push_back(static_cast<std::uint8_t>((c * 2 + r + k * 30) % 256));
  return image;
}

std::string decode_error(const Bytes& bytes) {
  try {
    decode_image(bytes);
  } catch (const TileDecodeError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ImageCodec, SniffsFormatsByMagicBytes) {
  EXPECT_EQ(sniff_image_format(encode_png(rgb8(2, 2, 3))), ImageFormat::png);
  EXPECT_EQ(sniff_image_format(encode_jpeg(gradient(8, 8, 3))), ImageFormat::jpeg);
  using namespace std::string_view_literals;
  EXPECT_EQ(sniff_image_format(text_bytes("RIFF\x10\0\0\0WEBPVP8 "sv)), ImageFormat::webp);
  EXPECT_EQ(sniff_image_format(text_bytes("RIFF\x10\0\0\0WAVEfmt "sv)), std::nullopt);
  EXPECT_EQ(sniff_image_format(text_bytes("\x89PN")), std::nullopt);
  EXPECT_EQ(sniff_image_format({}), std::nullopt);
}

TEST(ImageCodec, NamesWhatTheBytesAreWhenTheyAreNoImage) {
  const std::string html = decode_error(text_bytes("<html><body>Not found</body></html>"));
  EXPECT_NE(html.find("not a PNG, JPEG or WebP image (starts with 3c 68 74 6d"), std::string::npos) << html;
  EXPECT_NE(html.find("<html><body>"), std::string::npos) << html;
  EXPECT_NE(decode_error({}).find("empty"), std::string::npos);
  EXPECT_NE(decode_error({0x1f, 0x8b, 8, 0, 1, 2}).find("gzip"), std::string::npos);
  EXPECT_NE(decode_error({'I', 'I', 42, 0, 1}).find("starts with 49 49 2a 00"), std::string::npos);
}

TEST(ImageCodec, DecodesAnRgbPng) {
  const Bytes pixels = {10, 20, 30, 40, 50, 60, 70, 80, 90,  // row 0
                        1,  2,  3,  4,  5,  6,  7,  8,  9};  // row 1
  const DecodedImage image = decode_image(PngBuilder().ihdr(3, 2, 8, 2).idat(unfiltered(pixels, 9)).end());
  EXPECT_EQ(image.format, ImageFormat::png);
  EXPECT_EQ(image.width, 3u);
  EXPECT_EQ(image.height, 2u);
  EXPECT_EQ(image.channels, 3u);
  EXPECT_EQ(image.bit_depth, 8u);
  EXPECT_FALSE(image.has_alpha());
  EXPECT_EQ(image.samples8, std::vector<std::uint8_t>(pixels.begin(), pixels.end()));
  EXPECT_EQ(image.sample(1, 1, 2), 6u);
  EXPECT_TRUE(image.samples16.empty());
}

TEST(ImageCodec, Keeps16BitSamplesOfGrayAndRgbaPngs) {
  const std::vector<std::uint16_t> gray = {0x1234, 0xffff, 0x0001, 0xabcd};
  const DecodedImage g = decode_image(PngBuilder().ihdr(2, 2, 16, 0).idat(unfiltered(big_endian(gray), 4)).end());
  EXPECT_EQ(g.bit_depth, 16u);
  EXPECT_EQ(g.channels, 1u);
  EXPECT_EQ(g.samples16, gray);
  EXPECT_EQ(g.max_sample(), 65535u);

  const std::vector<std::uint16_t> rgba = {1, 2, 3, 0xfffe, 0x8000, 0x7fff, 300, 0};
  const DecodedImage c = decode_image(PngBuilder().ihdr(2, 1, 16, 6).idat(unfiltered(big_endian(rgba), 16)).end());
  EXPECT_EQ(c.channels, 4u);
  EXPECT_TRUE(c.has_alpha());
  EXPECT_EQ(c.samples16, rgba);
}

TEST(ImageCodec, ExpandsPalettesAndTransparency) {
  const Bytes palette = {255, 0, 0, 0, 255, 0, 0, 0, 255};
  const Bytes indices = {0, 1, 2, 1};
  // No tRNS: RGB.
  const DecodedImage rgb =
      decode_image(PngBuilder().ihdr(2, 2, 8, 3).chunk("PLTE", palette).idat(unfiltered(indices, 2)).end());
  EXPECT_EQ(rgb.channels, 3u);
  EXPECT_EQ(rgb.samples8, (std::vector<std::uint8_t>{255, 0, 0, 0, 255, 0, 0, 0, 255, 0, 255, 0}));
  // tRNS for the first two entries: RGBA, the third entry opaque.
  const DecodedImage rgba = decode_image(
      PngBuilder().ihdr(2, 2, 8, 3).chunk("PLTE", palette).chunk("tRNS", {128, 0}).idat(unfiltered(indices, 2)).end());
  EXPECT_EQ(rgba.channels, 4u);
  EXPECT_EQ(rgba.samples8, (std::vector<std::uint8_t>{255, 0, 0, 128, 0, 255, 0, 0, 0, 0, 255, 255, 0, 255, 0, 0}));
  // A 2-bit palette: four pixels in one byte, 0b00'01'10'01.
  const DecodedImage packed =
      decode_image(PngBuilder().ihdr(4, 1, 2, 3).chunk("PLTE", palette).idat(unfiltered({0b00011001}, 1)).end());
  EXPECT_EQ(packed.samples8, (std::vector<std::uint8_t>{255, 0, 0, 0, 255, 0, 0, 0, 255, 0, 255, 0}));
}

TEST(ImageCodec, ExpandsLowBitGrayAndGrayTransparencyKeys) {
  // 1-bit gray, 8 pixels in one byte: 1 -> 255.
  const DecodedImage bits = decode_image(PngBuilder().ihdr(8, 1, 1, 0).idat(unfiltered({0b10110000}, 1)).end());
  EXPECT_EQ(bits.bit_depth, 8u);
  EXPECT_EQ(bits.samples8, (std::vector<std::uint8_t>{255, 0, 255, 255, 0, 0, 0, 0}));
  // 8-bit gray whose tRNS key is 7: gray + alpha, alpha 0 exactly where the gray is 7.
  const DecodedImage keyed =
      decode_image(PngBuilder().ihdr(3, 1, 8, 0).chunk("tRNS", {0, 7}).idat(unfiltered({7, 8, 7}, 3)).end());
  EXPECT_EQ(keyed.channels, 2u);
  EXPECT_EQ(keyed.samples8, (std::vector<std::uint8_t>{7, 0, 8, 255, 7, 0}));
  // 16-bit gray + alpha stays 16-bit.
  const DecodedImage ga16 =
      decode_image(PngBuilder().ihdr(1, 1, 16, 4).idat(unfiltered(big_endian({0x0102, 0x0304}), 4)).end());
  EXPECT_EQ(ga16.channels, 2u);
  EXPECT_EQ(ga16.samples16, (std::vector<std::uint16_t>{0x0102, 0x0304}));
}

TEST(ImageCodec, DecodesInterlacedPngs) {
  // 8x8 gray, Adam7: seven passes of sub-images, each row with its filter byte.
  constexpr std::uint32_t kSize = 8;
  auto value = [](std::uint32_t x, std::uint32_t y) { return static_cast<unsigned char>(y * 16 + x * 3 + 1); };
  struct Pass {
    std::uint32_t x0, y0, dx, dy;
  };
  constexpr Pass kPasses[] = {{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4},
                              {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}};
  Bytes scanlines, plain;
  for (const Pass& p : kPasses)
    for (std::uint32_t y = p.y0; y < kSize; y += p.dy) {
      scanlines.push_back(0);
      for (std::uint32_t x = p.x0; x < kSize; x += p.dx) scanlines.push_back(value(x, y));
    }
  for (std::uint32_t y = 0; y < kSize; ++y)
    for (std::uint32_t x = 0; x < kSize; ++x) plain.push_back(value(x, y));
  const DecodedImage image = decode_image(PngBuilder().ihdr(kSize, kSize, 8, 0, 1).idat(scanlines).end());
  EXPECT_EQ(image.samples8, std::vector<std::uint8_t>(plain.begin(), plain.end()));
}

TEST(ImageCodec, RejectsTruncatedCorruptAndOversizedPngs) {
  Bytes pixels(64 * 64 * 3);
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<unsigned char>(i * 7919 % 251);
  const Bytes png = PngBuilder().ihdr(64, 64, 8, 2).idat(unfiltered(pixels, 64 * 3)).end();
  ASSERT_NO_THROW(decode_image(png));

  const Bytes half(png.begin(), png.begin() + static_cast<std::ptrdiff_t>(png.size() / 2));
  EXPECT_NE(decode_error(half).find("truncated PNG"), std::string::npos) << decode_error(half);
  const Bytes signature_only(png.begin(), png.begin() + 8);
  EXPECT_NE(decode_error(signature_only).find("truncated PNG"), std::string::npos);

  Bytes bad_crc = png;
  bad_crc[8 + 8 + 13] ^= 0xff;  // the IHDR's CRC
  EXPECT_NE(decode_error(bad_crc).find("corrupt PNG"), std::string::npos) << decode_error(bad_crc);

  Bytes bad_data = png;
  for (std::size_t i = 60; i < 90; ++i) bad_data[i] ^= 0x5a;  // inside the compressed IDAT
  EXPECT_THROW(decode_image(bad_data), TileDecodeError);

  const Bytes huge = PngBuilder().ihdr(5000, 10, 8, 2).idat({0}).end();
  EXPECT_NE(decode_error(huge).find("5000 x 10 pixels is larger than 4096 x 4096"), std::string::npos)
      << decode_error(huge);
  const Bytes zero_width = PngBuilder().ihdr(0, 10, 8, 2).idat({0}).end();
  EXPECT_NE(decode_error(zero_width).find("PNG"), std::string::npos) << decode_error(zero_width);
  const Bytes bad_depth = PngBuilder().ihdr(2, 2, 7, 2).idat({0}).end();
  EXPECT_NE(decode_error(bad_depth).find("corrupt PNG"), std::string::npos) << decode_error(bad_depth);
}

TEST(ImageCodec, EncodesPngsThatDecodeToTheSameSamples) {
  for (std::uint32_t channels = 1; channels <= 4; ++channels) {
    const DecodedImage eight = rgb8(5, 3, channels);
    const DecodedImage back8 = decode_image(encode_png(eight));
    EXPECT_EQ(back8.channels, channels);
    EXPECT_EQ(back8.samples8, eight.samples8) << channels << " channels";

    DecodedImage sixteen;
    sixteen.width = 4;
    sixteen.height = 2;
    sixteen.channels = channels;
    sixteen.bit_depth = 16;
    for (std::uint32_t i = 0; i < 8 * channels; ++i)
      sixteen.samples16.push_back(static_cast<std::uint16_t>(i * 4099 + 1));
    const DecodedImage back16 = decode_image(encode_png(sixteen, 1));
    EXPECT_EQ(back16.bit_depth, 16u);
    EXPECT_EQ(back16.samples16, sixteen.samples16) << channels << " channels";
  }
  DecodedImage wrong = rgb8(4, 4, 3);
  wrong.samples8.pop_back();
  EXPECT_THROW(encode_png(wrong), std::invalid_argument);
  wrong = rgb8(4, 4, 3);
  wrong.channels = 5;
  EXPECT_THROW(encode_png(wrong), std::invalid_argument);
}

TEST(ImageCodec, DecodesJpegsCloseToWhatWasEncoded) {
  for (std::uint32_t channels : {1u, 3u}) {
    const DecodedImage original = gradient(64, 48, channels);
    const DecodedImage image = decode_image(encode_jpeg(original, 95));
    EXPECT_EQ(image.format, ImageFormat::jpeg);
    EXPECT_EQ(image.width, 64u);
    EXPECT_EQ(image.height, 48u);
    EXPECT_EQ(image.channels, channels);
    ASSERT_EQ(image.samples8.size(), original.samples8.size());
    double error = 0;
    for (std::size_t i = 0; i < image.samples8.size(); ++i) error += std::abs(image.samples8[i] - original.samples8[i]);
    EXPECT_LT(error / static_cast<double>(image.samples8.size()), 4.0) << channels << " channels";
  }
  EXPECT_THROW(encode_jpeg(rgb8(4, 4, 4)), std::invalid_argument);
}

TEST(ImageCodec, RejectsTruncatedAndCorruptJpegs) {
  const Bytes jpeg = encode_jpeg(gradient(128, 128, 3), 90);
  const Bytes half(jpeg.begin(), jpeg.begin() + static_cast<std::ptrdiff_t>(jpeg.size() / 2));
  EXPECT_NE(decode_error(half).find("truncated JPEG"), std::string::npos) << decode_error(half);
  Bytes garbage = {0xff, 0xd8, 0xff};
  for (int i = 0; i < 100; ++i) garbage.push_back(static_cast<unsigned char>(i * 31));
  EXPECT_NE(decode_error(garbage).find("corrupt JPEG"), std::string::npos) << decode_error(garbage);
}

TEST(ImageCodec, DecodesLosslessWebpExactlyAndRejectsTruncatedOnes) {
  const DecodedImage rgba = rgb8(16, 8, 4);
  std::uint8_t* encoded = nullptr;
  const std::size_t size = WebPEncodeLosslessRGBA(rgba.samples8.data(), 16, 8, 16 * 4, &encoded);
  ASSERT_GT(size, 0u);
  const Bytes webp(encoded, encoded + size);
  WebPFree(encoded);
  const DecodedImage image = decode_image(webp);
  EXPECT_EQ(image.format, ImageFormat::webp);
  EXPECT_EQ(image.channels, 4u);
  EXPECT_EQ(image.samples8, rgba.samples8);

  const DecodedImage rgb = gradient(32, 32, 3);
  const std::size_t rgb_size = WebPEncodeLosslessRGB(rgb.samples8.data(), 32, 32, 32 * 3, &encoded);
  ASSERT_GT(rgb_size, 0u);
  const Bytes opaque(encoded, encoded + rgb_size);
  WebPFree(encoded);
  const DecodedImage rgb_back = decode_image(opaque);
  EXPECT_EQ(rgb_back.channels, 3u);
  EXPECT_EQ(rgb_back.samples8, rgb.samples8);

  const Bytes half(webp.begin(), webp.begin() + static_cast<std::ptrdiff_t>(webp.size() * 2 / 3));
  EXPECT_NE(decode_error(half).find("WebP"), std::string::npos) << decode_error(half);
  EXPECT_THROW(decode_image(half), TileDecodeError);
}

TEST(ImageCodec, ConvertsAnyImageToRgba8) {
  DecodedImage gray_alpha;
  gray_alpha.width = 2;
  gray_alpha.height = 1;
  gray_alpha.channels = 2;
  gray_alpha.samples8 = {10, 0, 200, 255};
  EXPECT_EQ(to_rgba8(gray_alpha), (std::vector<std::uint8_t>{10, 10, 10, 0, 200, 200, 200, 255}));

  DecodedImage rgb16;
  rgb16.width = 1;
  rgb16.height = 1;
  rgb16.channels = 3;
  rgb16.bit_depth = 16;
  rgb16.samples16 = {65535, 0, 32896};  // 32896 = 128 * 257
  EXPECT_EQ(to_rgba8(rgb16), (std::vector<std::uint8_t>{255, 0, 128, 255}));
}

TEST(ImageCodec, DecodesTheRealAlpineMapsTiles) {
  TRAILRAY_REQUIRE_DATA(height_tile, "tiles/alpinemaps/test-tile.png");
  const DecodedImage heights = decode_image(read_bytes(height_tile));
  EXPECT_EQ(heights.width, 65u);
  EXPECT_EQ(heights.height, 65u);
  EXPECT_EQ(heights.channels, 3u);
  EXPECT_EQ(heights.bit_depth, 8u);
  // The AlpineMaps renderer's own unit test reads raw values 3744 and 3718 from its first pixels.
  EXPECT_EQ(heights.sample(0, 0, 0) * 256 + heights.sample(0, 0, 1), 3744u);
  EXPECT_EQ(heights.sample(1, 0, 0) * 256 + heights.sample(1, 0, 1), 3718u);

  TRAILRAY_REQUIRE_DATA(ortho, "tiles/alpinemaps/test-tile_ortho.jpeg");
  const DecodedImage picture = decode_image(read_bytes(ortho));
  EXPECT_EQ(picture.format, ImageFormat::jpeg);
  EXPECT_EQ(picture.width, 256u);
  EXPECT_EQ(picture.height, 256u);
  EXPECT_EQ(picture.channels, 3u);
}

TEST(ImageCodec, DecodesConcurrently) {
  const Bytes png = encode_png(rgb8(64, 64, 4));
  const Bytes jpeg = encode_jpeg(gradient(64, 64, 3));
  const DecodedImage png_ref = decode_image(png), jpeg_ref = decode_image(jpeg);
  std::vector<std::thread> threads;
  std::vector<int> mismatches(8, 0);
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < 50; ++i) {
        if (decode_image(png).samples8 != png_ref.samples8) ++mismatches[t];
        if (decode_image(jpeg).samples8 != jpeg_ref.samples8) ++mismatches[t];
      }
    });
  for (auto& t : threads) t.join();
  for (int m : mismatches) EXPECT_EQ(m, 0);
}

}  // namespace
}  // namespace trailray::terrain
