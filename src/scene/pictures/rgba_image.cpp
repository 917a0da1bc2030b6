#include "scene/pictures/rgba_image.hpp"

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "scene/scene_error.hpp"
#include "terrain/codecs/image_codec.hpp"

namespace trailray::scene {
namespace {

void put_u32_big_endian(unsigned char* out, std::uint32_t value) {
  out[0] = static_cast<unsigned char>(value >> 24);
  out[1] = static_cast<unsigned char>(value >> 16);
  out[2] = static_cast<unsigned char>(value >> 8);
  out[3] = static_cast<unsigned char>(value);
}

// An sRGB chunk (PNG 1.2, 11.3.3.5): one byte of rendering intent, 0 = perceptual.
std::array<unsigned char, 13> srgb_chunk() {
  std::array<unsigned char, 13> chunk{};
  put_u32_big_endian(chunk.data(), 1);
  std::memcpy(chunk.data() + 4, "sRGB", 4);
  chunk[8] = 0;
  // The CRC covers the chunk type and data, not the length.
  const uLong crc = crc32(crc32(0L, Z_NULL, 0), chunk.data() + 4, 5);
  put_u32_big_endian(chunk.data() + 9, static_cast<std::uint32_t>(crc));
  return chunk;
}

bool write_all(int fd, std::span<const unsigned char> bytes) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    bytes = bytes.subspan(static_cast<std::size_t>(written));
  }
  return true;
}

// A name for the temporary file no other writer (thread or process) picks at the same time.
std::filesystem::path temporary_path(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  return path.parent_path() / ("." + path.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                               std::to_string(counter.fetch_add(1)));
}

}  // namespace

void flip_rows(std::span<std::uint8_t> pixels, std::size_t row_bytes) {
  if (row_bytes == 0) return;
  const std::size_t rows = pixels.size() / row_bytes;
  for (std::size_t top = 0, bottom = rows; top + 1 < bottom; ++top, --bottom)
    std::swap_ranges(pixels.begin() + static_cast<std::ptrdiff_t>(top * row_bytes),
                     pixels.begin() + static_cast<std::ptrdiff_t>((top + 1) * row_bytes),
                     pixels.begin() + static_cast<std::ptrdiff_t>((bottom - 1) * row_bytes));
}

std::uint8_t linear_to_srgb8(float linear) {
  if (!(linear > 0.0f)) return 0;  // also NaN
  if (linear >= 1.0f) return 255;
  const float encoded = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
  return static_cast<std::uint8_t>(std::lround(encoded * 255.0f));
}

float srgb8_to_linear(std::uint8_t encoded) {
  const float c = static_cast<float>(encoded) / 255.0f;
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

std::vector<unsigned char> encode_srgb_png(const RgbaImage& image) {
  if (image.width == 0 || image.height == 0 || image.rgba.size() != std::size_t{image.width} * image.height * 4)
    throw std::invalid_argument("encode_srgb_png: " + std::to_string(image.rgba.size()) + " bytes for " +
                                std::to_string(image.width) + " x " + std::to_string(image.height) + " RGBA pixels");
  terrain::DecodedImage pixels;
  pixels.width = image.width;
  pixels.height = image.height;
  pixels.channels = 4;
  pixels.bit_depth = 8;
  pixels.samples8 = image.rgba;
  std::vector<unsigned char> png = terrain::encode_png(pixels);
  // libpng writes the signature (8 bytes) and IHDR (25 bytes) first; sRGB must come before the
  // image data, so right after IHDR is its place.
  constexpr std::size_t kAfterHeader = 8 + 25;
  if (png.size() < kAfterHeader || std::memcmp(png.data() + 12, "IHDR", 4) != 0)
    throw SceneError("the PNG encoder wrote no IHDR chunk first");
  const std::array<unsigned char, 13> chunk = srgb_chunk();
  png.insert(png.begin() + kAfterHeader, chunk.begin(), chunk.end());
  return png;
}

void write_srgb_png(const std::filesystem::path& path, const RgbaImage& image) {
  const std::vector<unsigned char> png = encode_srgb_png(image);
  const std::filesystem::path temporary = temporary_path(path);
  auto failure = [&path](const std::string& why, int error) {
    return SceneError("cannot write " + path.string() + ": " + why + ": " + std::strerror(error));
  };
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) throw failure("cannot create a temporary file in its folder", errno);
  // errno stays 0 when write() wrote nothing, which only a full device does.
  errno = 0;
  bool written = write_all(fd, png) && ::fsync(fd) == 0;
  int error = written ? 0 : (errno != 0 ? errno : ENOSPC);
  if (::close(fd) != 0 && written) {
    written = false;
    error = errno;
  }
  if (!written) {
    ::unlink(temporary.c_str());
    throw failure("cannot write the temporary file", error);
  }
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    error = errno;
    ::unlink(temporary.c_str());
    throw failure("cannot rename the temporary file over it", error);
  }
}

}  // namespace trailray::scene
