#include "terrain/codecs/height_decode.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "terrain/codecs/height_tiff.hpp"

namespace trailray::terrain {

namespace {

constexpr HeightEncoding kRgbEncodings[] = {HeightEncoding::terrarium, HeightEncoding::mapbox,
                                            HeightEncoding::alpinemaps};

bool looks_like_tiff(std::span<const unsigned char> bytes) {
  if (bytes.size() < 4) return false;
  const unsigned char* b = bytes.data();
  const bool little = b[0] == 'I' && b[1] == 'I' && (b[2] == 42 || b[2] == 43) && b[3] == 0;  // TIFF, BigTIFF
  const bool big = b[0] == 'M' && b[1] == 'M' && b[2] == 0 && (b[3] == 42 || b[3] == 43);
  return little || big;
}

bool plausible(float h) { return h >= kPlausibleMinHeightM && h <= kPlausibleMaxHeightM; }

// ---------------------------------------------------------------------------------------------
// Pixels -> metres (height_encoding.hpp). Exact in float: terrarium's largest value needs
// 16 + 8 bits, mapbox's is computed in double.

float terrarium_height(std::uint32_t r, std::uint32_t g, std::uint32_t b) {
  return static_cast<float>(static_cast<std::int32_t>(r * 256 + g) - 32768) + static_cast<float>(b) / 256.0f;
}
float mapbox_height(std::uint32_t r, std::uint32_t g, std::uint32_t b) {
  return static_cast<float>(-10000.0 + static_cast<double>(r * 65536 + g * 256 + b) * 0.1);
}
float alpinemaps_height(std::uint32_t raw16) { return static_cast<float>(raw16) / 8.0f; }

std::uint32_t to_8_bits(std::uint32_t v16) { return (v16 * 255u + 32767u) / 65535u; }

// Applies `formula(r, g, b)` to every pixel (8-bit values; gray spread to r, g and b), NaN
// where alpha is 0.
template <class Formula>
void convert_rgb(const DecodedImage& image, Formula formula, std::vector<float>& out) {
  const std::size_t pixels = std::size_t{image.width} * image.height;
  const std::uint32_t c = image.channels;
  const bool alpha = image.has_alpha();
  const std::uint32_t g_at = c >= 3 ? 1 : 0, b_at = c >= 3 ? 2 : 0;
  out.resize(pixels);
  if (image.bit_depth == 8) {
    const std::uint8_t* s = image.samples8.data();
    for (std::size_t p = 0; p < pixels; ++p, s += c)
      out[p] = alpha && s[c - 1] == 0 ? kNoHeight : formula(s[0], s[g_at], s[b_at]);
  } else {
    const std::uint16_t* s = image.samples16.data();
    for (std::size_t p = 0; p < pixels; ++p, s += c)
      out[p] = alpha && s[c - 1] == 0 ? kNoHeight : formula(to_8_bits(s[0]), to_8_bits(s[g_at]), to_8_bits(s[b_at]));
  }
}

void convert(const DecodedImage& image, HeightEncoding encoding, std::vector<float>& out) {
  switch (encoding) {
    case HeightEncoding::terrarium:
      convert_rgb(image, terrarium_height, out);
      return;
    case HeightEncoding::mapbox:
      convert_rgb(image, mapbox_height, out);
      return;
    case HeightEncoding::alpinemaps:
      if (image.bit_depth == 16) {
        // One 16-bit channel holds what 8-bit tiles split into R (high) and G (low).
        const std::size_t pixels = std::size_t{image.width} * image.height;
        const std::uint32_t c = image.channels;
        const bool alpha = image.has_alpha();
        out.resize(pixels);
        for (std::size_t p = 0; p < pixels; ++p) {
          const std::uint16_t* s = &image.samples16[p * c];
          out[p] = alpha && s[c - 1] == 0 ? kNoHeight : alpinemaps_height(s[0]);
        }
      } else {
        convert_rgb(
            image, [](std::uint32_t r, std::uint32_t g, std::uint32_t) { return alpinemaps_height(r * 256 + g); }, out);
      }
      return;
    case HeightEncoding::float32:
      throw TileDecodeError("the float encoding reads single-band TIFF tiles, not a " +
                            std::string(to_string(image.format)));
  }
}

struct PlausibilityCount {
  std::size_t valid = 0, implausible = 0;
  float first_implausible = kNoHeight;
};

PlausibilityCount count_plausibility(const std::vector<float>& heights) {
  PlausibilityCount count;
  for (float h : heights) {
    if (std::isnan(h)) continue;
    ++count.valid;
    if (!plausible(h)) {
      if (count.implausible++ == 0) count.first_implausible = h;
    }
  }
  return count;
}

bool mostly_implausible(const PlausibilityCount& count) { return count.implausible * 2 > count.valid; }

std::string format_metres(float h) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.1f m", static_cast<double>(h));
  return buf;
}

// Throws when most samples cannot be real heights, naming the encodings that would fit.
void check_plausible(const std::vector<float>& heights, HeightEncoding encoding, const DecodedImage* image) {
  const PlausibilityCount count = count_plausibility(heights);
  if (!mostly_implausible(count)) return;
  std::string message = std::to_string(count.implausible) + " of " + std::to_string(count.valid) +
                        " heights lie outside " + std::to_string(static_cast<int>(kPlausibleMinHeightM)) + ".." +
                        std::to_string(static_cast<int>(kPlausibleMaxHeightM)) + " m with the " +
                        std::string(to_string(encoding)) + " encoding (the first is " +
                        format_metres(count.first_implausible) + ")";
  if (!image) throw TileDecodeError(message + ": these are probably not heights in metres");
  std::string fits;
  std::vector<float> other;
  for (HeightEncoding candidate : kRgbEncodings) {
    if (candidate == encoding) continue;
    convert(*image, candidate, other);
    if (mostly_implausible(count_plausibility(other))) continue;
    fits += (fits.empty() ? "" : " or ") + std::string(to_string(candidate));
  }
  message += ": the encoding is probably wrong; ";
  message += fits.empty() ? "no other encoding gives plausible heights either" : fits + " would give plausible heights";
  throw TileDecodeError(message);
}

// ---------------------------------------------------------------------------------------------
// Metres -> pixels.

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

Rgb split24(double value) {
  const auto v = static_cast<std::uint32_t>(std::llround(std::clamp(value, 0.0, 16777215.0)));
  return {static_cast<std::uint8_t>(v >> 16), static_cast<std::uint8_t>((v >> 8) & 0xff),
          static_cast<std::uint8_t>(v & 0xff)};
}

Rgb encode_rgb(float h, HeightEncoding encoding) {
  switch (encoding) {
    case HeightEncoding::terrarium:
      return split24((static_cast<double>(h) + 32768.0) * 256.0);
    case HeightEncoding::mapbox:
      return split24((static_cast<double>(h) + 10000.0) * 10.0);
    case HeightEncoding::alpinemaps: {
      const auto v = static_cast<std::uint32_t>(std::llround(std::clamp(static_cast<double>(h) * 8.0, 0.0, 65535.0)));
      return {static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v & 0xff), 0};
    }
    case HeightEncoding::float32:
      break;
  }
  throw std::invalid_argument("encode_rgb: not an RGB encoding");
}

}  // namespace

namespace detail {
void check_tile_size(std::uint32_t width, std::uint32_t height) {
  if (width != height || width < kMinHeightTileSize || width > kMaxHeightTileSize)
    throw TileDecodeError("wrong tile size " + std::to_string(width) + "x" + std::to_string(height) +
                          ": height tiles are square, " + std::to_string(kMinHeightTileSize) + " to " +
                          std::to_string(kMaxHeightTileSize) + " samples a side");
}
}  // namespace detail

SampleLayout layout_for_size(std::uint32_t samples_per_side) {
  const std::uint32_t n = samples_per_side;
  const bool two_to_the_k_plus_one = n >= 3 && ((n - 1) & (n - 2)) == 0;
  return two_to_the_k_plus_one ? SampleLayout::pixel_is_point : SampleLayout::pixel_is_area;
}

HeightTile heights_from_image(const DecodedImage& image, HeightEncoding encoding, const TileId& id) {
  detail::check_tile_size(image.width, image.height);
  HeightTile tile;
  tile.id = id;
  tile.width = image.width;
  tile.height = image.height;
  tile.layout = layout_for_size(image.width);
  convert(image, encoding, tile.heights);
  check_plausible(tile.heights, encoding, &image);
  update_height_range(tile);
  return tile;
}

HeightTile decode_height_tile(std::span<const unsigned char> bytes, HeightEncoding encoding, const TileId& id) {
  if (encoding == HeightEncoding::float32) {
    if (!looks_like_tiff(bytes)) {
      const std::optional<ImageFormat> format = sniff_image_format(bytes);
      throw TileDecodeError(std::string("the float encoding reads single-band TIFF tiles; this is ") +
                            (format ? "a " + std::string(to_string(*format)) : std::string("not a TIFF")));
    }
    HeightTile tile = detail::decode_float_tiff(bytes, id);
    check_plausible(tile.heights, encoding, nullptr);
    update_height_range(tile);
    return tile;
  }
  if (looks_like_tiff(bytes))
    throw TileDecodeError("a TIFF tile: decode it with the float encoding, not " + std::string(to_string(encoding)));
  return heights_from_image(decode_image(bytes), encoding, id);
}

ImageTile decode_image_tile(std::span<const unsigned char> bytes, const TileId& id) {
  const DecodedImage image = decode_image(bytes);
  ImageTile tile;
  tile.id = id;
  tile.width = image.width;
  tile.height = image.height;
  tile.rgba = to_rgba8(image);
  return tile;
}

std::vector<unsigned char> encode_height_tile(const HeightTile& tile, HeightEncoding encoding, int zlib_level) {
  if (tile.width == 0 || tile.height == 0 || tile.heights.size() != std::size_t{tile.width} * tile.height)
    throw std::invalid_argument("encode_height_tile: " + std::to_string(tile.heights.size()) + " samples for " +
                                std::to_string(tile.width) + "x" + std::to_string(tile.height));
  if (encoding == HeightEncoding::float32) return detail::encode_float_tiff(tile);
  const bool holes = std::any_of(tile.heights.begin(), tile.heights.end(), [](float h) { return std::isnan(h); });
  DecodedImage image;
  image.width = tile.width;
  image.height = tile.height;
  image.channels = holes ? 4 : 3;
  image.samples8.resize(tile.heights.size() * image.channels);
  std::uint8_t* out = image.samples8.data();
  for (float h : tile.heights) {
    if (std::isnan(h)) {
      std::memset(out, 0, 4);  // alpha 0: a hole
    } else {
      const Rgb rgb = encode_rgb(h, encoding);
      out[0] = rgb.r;
      out[1] = rgb.g;
      out[2] = rgb.b;
      if (holes) out[3] = 255;
    }
    out += image.channels;
  }
  return encode_png(image, zlib_level);
}

std::vector<unsigned char> encode_terrarium_png(const HeightTile& tile) {
  return encode_height_tile(tile, HeightEncoding::terrarium);
}

}  // namespace trailray::terrain
