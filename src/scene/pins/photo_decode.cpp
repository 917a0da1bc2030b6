#include "scene/pins/photo_decode.hpp"

#include <libheif/heif.h>
#include <turbojpeg.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <system_error>
#include <vector>

namespace trailray::scene {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw PhotoDecodeError(path + ": " + what); }

std::vector<unsigned char> read_file(const std::string& path, const PhotoDecodeLimits& limits) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) fail(path, "cannot read the photo (" + ec.message() + ")");
  if (size > limits.max_file_bytes)
    fail(path, "photo of " + std::to_string(size >> 20) + " MiB is larger than the limit of " +
                   std::to_string(limits.max_file_bytes >> 20) + " MiB: not decoded");
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> bytes(static_cast<std::size_t>(size));
  if (!in || !in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
    fail(path, "cannot read the photo");
  return bytes;
}

bool is_jpeg(const std::vector<unsigned char>& b) { return b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF; }

// An ISO base media file whose brand is one of HEIF's ('ftyp' at offset 4).
bool is_heif(const std::vector<unsigned char>& b) {
  return b.size() >= 12 && b[4] == 'f' && b[5] == 't' && b[6] == 'y' && b[7] == 'p';
}

RgbaImage decode_jpeg(const std::string& path, const std::vector<unsigned char>& bytes, int long_side_px,
                      const PhotoDecodeLimits& limits) {
  const std::unique_ptr<void, int (*)(tjhandle)> handle(tjInitDecompress(), tjDestroy);
  if (!handle) fail(path, "cannot start the JPEG decoder");
  int width = 0, height = 0, subsampling = 0, colorspace = 0;
  if (tjDecompressHeader3(handle.get(), bytes.data(), static_cast<unsigned long>(bytes.size()), &width, &height,
                          &subsampling, &colorspace) != 0)
    fail(path, std::string("not a readable JPEG (") + tjGetErrorStr2(handle.get()) + ")");
  if (width <= 0 || height <= 0 || static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) > limits.max_pixels)
    fail(path, "JPEG of " + std::to_string(width) + " x " + std::to_string(height) + " pixels is too large");
  // The smallest of libjpeg-turbo's scales (1/8 .. 2) that still gives the long side we want:
  // the DCT does the shrinking, so most of the photo is never expanded to pixels.
  int count = 0;
  const tjscalingfactor* factors = tjGetScalingFactors(&count);
  tjscalingfactor best{1, 1};
  int best_long = std::max(width, height);
  for (int i = 0; i < count; ++i) {
    const int w = TJSCALED(width, factors[i]), h = TJSCALED(height, factors[i]);
    const int long_side = std::max(w, h);
    if (long_side >= long_side_px && long_side < best_long && factors[i].num <= factors[i].denom) {
      best = factors[i];
      best_long = long_side;
    }
  }
  RgbaImage out;
  out.width = static_cast<std::uint32_t>(TJSCALED(width, best));
  out.height = static_cast<std::uint32_t>(TJSCALED(height, best));
  out.rgba.assign(std::size_t{out.width} * out.height * 4, 0);
  if (tjDecompress2(handle.get(), bytes.data(), static_cast<unsigned long>(bytes.size()), out.rgba.data(),
                    static_cast<int>(out.width), 0, static_cast<int>(out.height), TJPF_RGBA,
                    TJFLAG_FASTDCT | TJFLAG_FASTUPSAMPLE) != 0 &&
      tjGetErrorCode(handle.get()) == TJERR_FATAL)
    fail(path, std::string("corrupt JPEG (") + tjGetErrorStr2(handle.get()) + ")");
  return out;
}

struct HeifFree {
  void operator()(heif_context* c) const { heif_context_free(c); }
  void operator()(heif_image_handle* h) const { heif_image_handle_release(h); }
  void operator()(heif_image* i) const { heif_image_release(i); }
};

void check_heif(const std::string& path, const heif_error& error) {
  if (error.code != heif_error_Ok) fail(path, std::string("not a readable HEIF/HEIC image (") + error.message + ")");
}

RgbaImage decode_heif(const std::string& path, int long_side_px, const PhotoDecodeLimits& limits) {
  const std::unique_ptr<heif_context, HeifFree> context(heif_context_alloc());
  if (!context) fail(path, "cannot start the HEIF decoder");
  heif_context_set_maximum_image_size_limit(context.get(), 65535);
  check_heif(path, heif_context_read_from_file(context.get(), path.c_str(), nullptr));
  heif_image_handle* primary_raw = nullptr;
  check_heif(path, heif_context_get_primary_image_handle(context.get(), &primary_raw));
  const std::unique_ptr<heif_image_handle, HeifFree> primary(primary_raw);
  const auto pixels = [](const heif_image_handle* h) {
    return static_cast<std::uint64_t>(heif_image_handle_get_width(h)) *
           static_cast<std::uint64_t>(heif_image_handle_get_height(h));
  };
  if (pixels(primary.get()) > limits.max_pixels) fail(path, "HEIF image too large");
  // The stored thumbnail (a phone's is 320 or so on its long side) when it is big enough: no
  // need to decode twelve million pixels of HEVC for a pin.
  std::unique_ptr<heif_image_handle, HeifFree> thumbnail;
  if (heif_image_handle_get_number_of_thumbnails(primary.get()) > 0) {
    heif_item_id id = 0;
    heif_image_handle_get_list_of_thumbnail_IDs(primary.get(), &id, 1);
    heif_image_handle* raw = nullptr;
    if (heif_image_handle_get_thumbnail(primary.get(), id, &raw).code == heif_error_Ok) {
      thumbnail.reset(raw);
      if (std::max(heif_image_handle_get_width(raw), heif_image_handle_get_height(raw)) < long_side_px)
        thumbnail.reset();
    }
  }
  const heif_image_handle* source = thumbnail ? thumbnail.get() : primary.get();
  heif_image* image_raw = nullptr;
  // Decoding applies the file's rotation and mirroring (irot, imir): the result is upright.
  check_heif(path, heif_decode_image(source, &image_raw, heif_colorspace_RGB, heif_chroma_interleaved_RGBA, nullptr));
  const std::unique_ptr<heif_image, HeifFree> image(image_raw);
  const int width = heif_image_get_width(image.get(), heif_channel_interleaved);
  const int height = heif_image_get_height(image.get(), heif_channel_interleaved);
  int stride = 0;
  const std::uint8_t* plane = heif_image_get_plane_readonly(image.get(), heif_channel_interleaved, &stride);
  if (plane == nullptr || width <= 0 || height <= 0) fail(path, "HEIF image without pixels");
  RgbaImage out{static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), {}};
  out.rgba.resize(std::size_t{out.width} * out.height * 4);
  for (int y = 0; y < height; ++y)
    std::copy_n(plane + static_cast<std::ptrdiff_t>(y) * stride, static_cast<std::size_t>(width) * 4,
                out.rgba.begin() + static_cast<std::ptrdiff_t>(y) * width * 4);
  for (std::size_t i = 3; i < out.rgba.size(); i += 4) out.rgba[i] = 255;  // a photo is opaque
  return out;
}

}  // namespace

RgbaImage shrink_to_long_side(const RgbaImage& image, int long_side_px) {
  const std::uint32_t long_side = std::max(image.width, image.height);
  if (long_side_px <= 0 || long_side <= static_cast<std::uint32_t>(long_side_px)) return image;
  const double scale = static_cast<double>(long_side_px) / long_side;
  RgbaImage out;
  out.width = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::lround(image.width * scale)));
  out.height = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::lround(image.height * scale)));
  out.rgba.assign(std::size_t{out.width} * out.height * 4, 0);
  const double fx = static_cast<double>(image.width) / out.width, fy = static_cast<double>(image.height) / out.height;
  for (std::uint32_t y = 0; y < out.height; ++y) {
    const auto y0 = static_cast<std::uint32_t>(y * fy);
    const auto y1 = std::max(y0 + 1, std::min(image.height, static_cast<std::uint32_t>(std::ceil((y + 1) * fy))));
    for (std::uint32_t x = 0; x < out.width; ++x) {
      const auto x0 = static_cast<std::uint32_t>(x * fx);
      const auto x1 = std::max(x0 + 1, std::min(image.width, static_cast<std::uint32_t>(std::ceil((x + 1) * fx))));
      std::array<std::uint32_t, 4> sum{};
      for (std::uint32_t sy = y0; sy < y1; ++sy)
        for (std::uint32_t sx = x0; sx < x1; ++sx)
          for (int c = 0; c < 4; ++c) sum[c] += image.rgba[(std::size_t{sy} * image.width + sx) * 4 + c];
      const std::uint32_t n = (y1 - y0) * (x1 - x0);
      for (int c = 0; c < 4; ++c)
        out.rgba[(std::size_t{y} * out.width + x) * 4 + c] = static_cast<std::uint8_t>((sum[c] + n / 2) / n);
    }
  }
  return out;
}

RgbaImage apply_exif_orientation(const RgbaImage& image, int exif_orientation) {
  if (exif_orientation < 2 || exif_orientation > 8) return image;
  const std::uint32_t w = image.width, h = image.height;
  const bool swap = exif_orientation >= 5;
  RgbaImage out{swap ? h : w, swap ? w : h, {}};
  out.rgba.resize(image.rgba.size());
  for (std::uint32_t y = 0; y < out.height; ++y)
    for (std::uint32_t x = 0; x < out.width; ++x) {
      // The stored pixel shown at (x, y), for each of EXIF's eight orientations.
      std::uint32_t sx = x, sy = y;
      switch (exif_orientation) {
        case 2: sx = w - 1 - x; break;
        case 3: sx = w - 1 - x, sy = h - 1 - y; break;
        case 4: sy = h - 1 - y; break;
        case 5: sx = y, sy = x; break;
        case 6: sx = y, sy = h - 1 - x; break;
        case 7: sx = w - 1 - y, sy = h - 1 - x; break;
        case 8: sx = w - 1 - y, sy = x; break;
        default: break;
      }
      std::copy_n(image.rgba.begin() + static_cast<std::ptrdiff_t>((std::size_t{sy} * w + sx) * 4), 4,
                  out.rgba.begin() + static_cast<std::ptrdiff_t>((std::size_t{y} * out.width + x) * 4));
    }
  return out;
}

RgbaImage decode_photo(const std::string& path, int long_side_px, int exif_orientation,
                       const PhotoDecodeLimits& limits) {
  const std::vector<unsigned char> bytes = read_file(path, limits);
  if (is_jpeg(bytes))
    return apply_exif_orientation(shrink_to_long_side(decode_jpeg(path, bytes, long_side_px, limits), long_side_px),
                                  exif_orientation);
  if (is_heif(bytes)) return shrink_to_long_side(decode_heif(path, long_side_px, limits), long_side_px);
  fail(path, "not a JPEG or HEIF/HEIC photo");
}

std::vector<std::shared_ptr<const PhotoImage>> decode_thumbnails(const std::vector<track::PlacedPhoto>& photos,
                                                                 int long_side_px, Diagnostics& diagnostics,
                                                                 const PhotoDecodeLimits& limits) {
  std::vector<std::shared_ptr<const PhotoImage>> out;
  out.reserve(photos.size());
  for (const track::PlacedPhoto& p : photos) {
    try {
      out.push_back(make_photo_image(decode_photo(p.photo.path, long_side_px, p.photo.orientation, limits)));
    } catch (const PhotoDecodeError& e) {
      diagnostics.warning(std::string(e.what()) + ": drawn as a plain pin");
      out.push_back(nullptr);
    }
  }
  return out;
}

}  // namespace trailray::scene
