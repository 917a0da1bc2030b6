#pragma once
// Image files in memory <-> pixels: PNG (libpng), JPEG (libjpeg-turbo) and WebP (libwebp), the
// formats tile pyramids are stored in. The format is told by the file's magic bytes, never by a
// name. Decoding keeps what the file holds (channels, 16-bit samples: height tiles may carry a
// 16-bit value, and scaling it to 8 bits would lose it); height_decode.hpp gives it meaning.
// Every function is thread-safe; decoding never modifies its input.

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace trailray::terrain {

// Bytes that are not a tile image we can decode: not a PNG/JPEG/WebP, truncated, corrupt, too
// big. The message says what is wrong (the caller adds the source and the tile).
class TileDecodeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class ImageFormat { png, jpeg, webp };
std::string_view to_string(ImageFormat format);

// The format of an image from its first bytes; nullopt when it is none of the three.
std::optional<ImageFormat> sniff_image_format(std::span<const unsigned char> bytes);

// Larger images are refused: no tile is bigger, and the limit bounds the memory a hostile or
// corrupt file can make a decoder allocate (4096^2 RGBA 16-bit = 128 MiB).
inline constexpr std::uint32_t kMaxImageDimension = 4096;

struct DecodedImage {
  ImageFormat format = ImageFormat::png;  // what it was decoded from
  std::uint32_t width = 0, height = 0;
  // 1 gray, 2 gray + alpha, 3 RGB, 4 RGBA. Palettes are expanded to RGB, a tRNS chunk to an
  // alpha channel, gray below 8 bits to 8 bits.
  std::uint32_t channels = 0;
  // 8 or 16 (16 only from a 16-bit PNG). The samples are in samples8 or samples16, row-major
  // from the north-west corner, interleaved; the other vector is empty.
  std::uint32_t bit_depth = 8;
  std::vector<std::uint8_t> samples8;
  std::vector<std::uint16_t> samples16;

  bool has_alpha() const { return channels == 2 || channels == 4; }
  std::uint32_t max_sample() const { return bit_depth == 16 ? 65535u : 255u; }
  // Sample `channel` of pixel (col, row), at the image's bit depth. No bounds check.
  std::uint32_t sample(std::uint32_t col, std::uint32_t row, std::uint32_t channel) const {
    const std::size_t i = (std::size_t{row} * width + col) * channels + channel;
    return bit_depth == 16 ? samples16[i] : samples8[i];
  }
};

// Decodes a PNG (8 or 16 bit; gray, gray + alpha, RGB, RGBA, palette; tRNS; interlaced or not),
// a JPEG (to RGB; CMYK is refused) or a WebP (to RGB, or RGBA when it has alpha; not animated).
// Throws TileDecodeError for anything else: "not a PNG, JPEG or WebP image (starts with 3c 68 74
// 6d)", "truncated PNG", "corrupt JPEG: ...", "image of 5000 x 5000 pixels is larger than
// 4096 x 4096", ...
DecodedImage decode_image(std::span<const unsigned char> bytes);

// Converts any decoded image to 8-bit RGBA: gray is spread to R, G and B, a missing alpha is
// opaque, 16-bit samples are scaled to 8 bits (rounded).
std::vector<std::uint8_t> to_rgba8(const DecodedImage& image);

// Encodes pixels as a PNG: any `channels` (1..4) at bit_depth 8 (samples8) or 16 (samples16);
// `format` is ignored. zlib_level 0..9 (6: libpng's default; 1 is much faster for fixtures).
// Throws std::invalid_argument when the sizes do not agree, TileDecodeError if libpng fails.
std::vector<unsigned char> encode_png(const DecodedImage& image, int zlib_level = 6);

// Encodes an 8-bit gray or RGB image as a baseline JPEG (quality 1..100), for imagery fixtures
// and benchmarks. Same errors as encode_png.
std::vector<unsigned char> encode_jpeg(const DecodedImage& image, int quality = 85);

// For the tile fuzz target only (fuzz/fuzz_tile_decode.cpp): decode PNGs whose CRC and Adler-32
// checksums are wrong, so that mutated inputs reach the pixel code (random mutations almost
// never keep a checksum right). Off unless a fuzz target turns it on. A switch at run time rather
// than a compile definition, so the sanitizer tree builds the fuzzers and the test suite from the
// same library, and the suite still sees checksums enforced.
void ignore_png_checksums_for_fuzzing(bool ignore);

}  // namespace trailray::terrain
