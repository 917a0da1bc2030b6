#pragma once
// A picture on the CPU: 8-bit sRGB RGBA pixels, top-down, as the renderer reads them back and the
// legend paints into them; the sRGB transfer functions; the PNG writer (atomic). The passes work
// in linear light; the compose step encodes once, through linear_to_srgb8 here or srgb.glsl.

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace trailray::scene {

// 8-bit RGBA pixels, row-major from the top-left (the order of image files).
struct RgbaImage {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes

  std::array<std::uint8_t, 4> pixel(std::uint32_t x, std::uint32_t y) const {
    const std::size_t i = (std::size_t{y} * width + x) * 4;
    return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
  }
};

// Reverses the order of the rows of an image in place (bottom-up <-> top-down).
void flip_rows(std::span<std::uint8_t> pixels, std::size_t row_bytes);

// The sRGB encoding (IEC 61966-2-1) of linear light in [0, 1], rounded to 8 bits; values outside
// are clamped, NaN gives 0.
std::uint8_t linear_to_srgb8(float linear);
// The inverse, for tests and for imagery decoded from sRGB files.
float srgb8_to_linear(std::uint8_t encoded);

// The image as an 8-bit RGBA PNG with an sRGB chunk, which tells viewers the pixels are sRGB
// encoded (rendering intent: perceptual). Throws std::invalid_argument for a size mismatch.
std::vector<unsigned char> encode_srgb_png(const RgbaImage& image);

// Writes encode_srgb_png(image) to `path` atomically: into a temporary file in the same folder,
// flushed, then renamed over `path`, so a reader never sees half a picture and a failure leaves
// any earlier file as it was. Throws SceneError naming the path and the reason.
void write_srgb_png(const std::filesystem::path& path, const RgbaImage& image);

}  // namespace trailray::scene
