#include "terrain/codecs/image_codec.hpp"

#include <png.h>
#include <turbojpeg.h>
#include <webp/decode.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cctype>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <string>

namespace trailray::terrain {

namespace {

std::atomic<bool> png_checksums_ignored{false};  // ignore_png_checksums_for_fuzzing

constexpr unsigned char kPngMagic[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

bool starts_with(std::span<const unsigned char> bytes, std::span<const unsigned char> prefix) {
  return bytes.size() >= prefix.size() && std::equal(prefix.begin(), prefix.end(), bytes.begin());
}

// "starts with 3c 68 74 6d", plus the text when it is text (an HTML or JSON error page served
// in place of a tile is the usual culprit).
std::string describe_start(std::span<const unsigned char> bytes) {
  if (bytes.empty()) return "it is empty";
  std::string hex = "starts with";
  const std::size_t n = std::min<std::size_t>(bytes.size(), 4);
  char buf[4];
  for (std::size_t i = 0; i < n; ++i) {
    std::snprintf(buf, sizeof buf, " %02x", bytes[i]);
    hex += buf;
  }
  const std::size_t text_len = std::min<std::size_t>(bytes.size(), 24);
  const bool printable = std::all_of(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(text_len),
                                     [](unsigned char c) { return std::isprint(c) || std::isspace(c); });
  if (printable) {
    std::string text(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(text_len));
    std::replace_if(
        text.begin(), text.end(), [](unsigned char c) { return std::isspace(c); }, ' ');
    hex += ": text \"" + text + (bytes.size() > text_len ? "...\"" : "\"");
  } else if (bytes.size() >= 2 && bytes[0] == 0x1f && bytes[1] == 0x8b) {
    hex += ": gzip-compressed data";
  }
  return hex;
}

void check_dimensions(std::uint32_t width, std::uint32_t height, std::string_view what) {
  if (width == 0 || height == 0)
    throw TileDecodeError(std::string(what) + " with no pixels (" + std::to_string(width) + " x " +
                          std::to_string(height) + ")");
  if (width > kMaxImageDimension || height > kMaxImageDimension)
    throw TileDecodeError(std::string(what) + " of " + std::to_string(width) + " x " + std::to_string(height) +
                          " pixels is larger than " + std::to_string(kMaxImageDimension) + " x " +
                          std::to_string(kMaxImageDimension));
}

// ---------------------------------------------------------------------------------------------
// PNG (libpng). libpng reports errors by longjmp to the setjmp in PngReader::read(); that
// function keeps no objects with destructors of its own (everything lives in the PngReader or
// the caller's DecodedImage), so the jump skips nothing that needs cleaning up.

struct PngReadState {
  const unsigned char* data = nullptr;
  std::size_t size = 0, offset = 0;
  bool ran_out = false;
};

void png_read_from_memory(png_structp png, png_bytep out, png_size_t length) {
  auto* state = static_cast<PngReadState*>(png_get_io_ptr(png));
  if (length > state->size - state->offset) {
    state->ran_out = true;
    png_error(png, "truncated PNG");
  }
  std::memcpy(out, state->data + state->offset, length);
  state->offset += length;
}

struct PngMessage {
  char text[256] = {};
};

void png_on_error(png_structp png, png_const_charp message) {
  auto* out = static_cast<PngMessage*>(png_get_error_ptr(png));
  std::snprintf(out->text, sizeof out->text, "%s", message);
  png_longjmp(png, 1);
}

// Warnings are about ancillary chunks (a bad gamma, a CRC in a text chunk): the pixels are fine.
void png_on_warning(png_structp, png_const_charp) {}

class PngReader {
 public:
  explicit PngReader(std::span<const unsigned char> bytes) {
    state_.data = bytes.data();
    state_.size = bytes.size();
    png_ = png_create_read_struct(PNG_LIBPNG_VER_STRING, &message_, png_on_error, png_on_warning);
    if (png_) info_ = png_create_info_struct(png_);
  }
  ~PngReader() { png_destroy_read_struct(png_ ? &png_ : nullptr, info_ ? &info_ : nullptr, nullptr); }
  PngReader(const PngReader&) = delete;
  PngReader& operator=(const PngReader&) = delete;

  DecodedImage decode() {
    if (!png_ || !info_) throw std::bad_alloc();
    DecodedImage image;
    image.format = ImageFormat::png;
    if (!read(image)) {
      if (bad_size_) check_dimensions(image.width, image.height, "PNG");
      if (state_.ran_out) throw TileDecodeError("truncated PNG (" + std::to_string(state_.size) + " bytes)");
      throw TileDecodeError(std::string("corrupt PNG: ") + message_.text);
    }
    return image;
  }

 private:
  // False after a libpng error (message_ or state_.ran_out say which) or a size check.
  bool read(DecodedImage& image) {
    if (setjmp(png_jmpbuf(png_))) return false;
    png_set_read_fn(png_, &state_, png_read_from_memory);
    if (png_checksums_ignored.load(std::memory_order_relaxed)) {
      // Let the fuzzer past the checksums, which random mutations would almost never satisfy.
      png_set_crc_action(png_, PNG_CRC_QUIET_USE, PNG_CRC_QUIET_USE);
      png_set_option(png_, PNG_IGNORE_ADLER32, PNG_OPTION_ON);
    }
    png_read_info(png_, info_);
    const png_uint_32 width = png_get_image_width(png_, info_);
    const png_uint_32 height = png_get_image_height(png_, info_);
    if (width == 0 || height == 0 || width > kMaxImageDimension || height > kMaxImageDimension) {
      image.width = width;
      image.height = height;
      bad_size_ = true;  // decode() throws the message: nothing here may need unwinding
      return false;
    }
    const int color_type = png_get_color_type(png_, info_);
    const int file_depth = png_get_bit_depth(png_, info_);
    if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png_);
    if (color_type == PNG_COLOR_TYPE_GRAY && file_depth < 8) png_set_expand_gray_1_2_4_to_8(png_);
    if (png_get_valid(png_, info_, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png_);
    // PNG stores 16-bit samples big-endian; read them straight into uint16_t.
    if (file_depth == 16 && std::endian::native == std::endian::little) png_set_swap(png_);
    png_set_interlace_handling(png_);
    png_read_update_info(png_, info_);

    image.width = width;
    image.height = height;
    image.channels = png_get_channels(png_, info_);
    image.bit_depth = png_get_bit_depth(png_, info_);
    const std::size_t row_bytes = std::size_t{width} * image.channels * (image.bit_depth / 8);
    if (image.channels < 1 || image.channels > 4 || (image.bit_depth != 8 && image.bit_depth != 16) ||
        png_get_rowbytes(png_, info_) != row_bytes)
      png_error(png_, "unexpected pixel layout after expansion");

    unsigned char* pixels = nullptr;
    const std::size_t samples = std::size_t{width} * height * image.channels;
    if (image.bit_depth == 16) {
      image.samples16.resize(samples);
      pixels = reinterpret_cast<unsigned char*>(image.samples16.data());
    } else {
      image.samples8.resize(samples);
      pixels = image.samples8.data();
    }
    rows_.resize(height);
    for (std::size_t r = 0; r < height; ++r) rows_[r] = pixels + r * row_bytes;
    png_read_image(png_, rows_.data());
    // png_read_end() is skipped: it would only check chunks after the pixels, and a tile cut
    // after its last IDAT still has all of them.
    return true;
  }

  PngReadState state_;
  PngMessage message_;
  bool bad_size_ = false;
  std::vector<png_bytep> rows_;
  png_structp png_ = nullptr;
  png_infop info_ = nullptr;
};

// ---------------------------------------------------------------------------------------------
// JPEG (libjpeg-turbo's TurboJPEG API).

struct TjDeleter {
  void operator()(void* handle) const { tjDestroy(handle); }
};
using TjHandle = std::unique_ptr<void, TjDeleter>;

DecodedImage decode_jpeg(std::span<const unsigned char> bytes) {
  TjHandle tj(tjInitDecompress());
  if (!tj) throw std::bad_alloc();
  int width = 0, height = 0, subsampling = 0, colorspace = 0;
  if (tjDecompressHeader3(tj.get(), bytes.data(), bytes.size(), &width, &height, &subsampling, &colorspace) != 0)
    throw TileDecodeError(std::string("corrupt JPEG: ") + tjGetErrorStr2(tj.get()));
  if (width < 0 || height < 0) throw TileDecodeError("corrupt JPEG: negative size");
  check_dimensions(static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), "JPEG");
  if (colorspace == TJCS_CMYK || colorspace == TJCS_YCCK) throw TileDecodeError("CMYK JPEG: tiles must be RGB or gray");

  DecodedImage image;
  image.format = ImageFormat::jpeg;
  image.width = static_cast<std::uint32_t>(width);
  image.height = static_cast<std::uint32_t>(height);
  image.channels = colorspace == TJCS_GRAY ? 1 : 3;
  image.samples8.resize(std::size_t{image.width} * image.height * image.channels);
  // LIMITSCANS: a progressive JPEG with thousands of scans would take minutes to decode.
  if (tjDecompress2(tj.get(), bytes.data(), bytes.size(), image.samples8.data(), width, 0, height,
                    colorspace == TJCS_GRAY ? TJPF_GRAY : TJPF_RGB, TJFLAG_LIMITSCANS) != 0) {
    const std::string message = tjGetErrorStr2(tj.get());
    // A warning leaves a usable picture ("extraneous bytes before marker"), except when the
    // data ran out: then the bottom of the tile is grey filler.
    if (tjGetErrorCode(tj.get()) == TJERR_FATAL) throw TileDecodeError("corrupt JPEG: " + message);
    if (message.find("Premature end") != std::string::npos)
      throw TileDecodeError("truncated JPEG (" + std::to_string(bytes.size()) + " bytes)");
  }
  return image;
}

// ---------------------------------------------------------------------------------------------
// WebP (libwebp).

std::string webp_status_text(VP8StatusCode status) {
  switch (status) {
    case VP8_STATUS_OK:
      return "ok";
    case VP8_STATUS_OUT_OF_MEMORY:
      return "out of memory";
    case VP8_STATUS_INVALID_PARAM:
      return "invalid parameter";
    case VP8_STATUS_BITSTREAM_ERROR:
      return "bitstream error";
    case VP8_STATUS_UNSUPPORTED_FEATURE:
      return "unsupported feature";
    case VP8_STATUS_SUSPENDED:
      return "suspended";
    case VP8_STATUS_USER_ABORT:
      return "aborted";
    case VP8_STATUS_NOT_ENOUGH_DATA:
      return "not enough data";
  }
  return "unknown error";
}

[[noreturn]] void throw_webp_error(VP8StatusCode status, std::size_t size) {
  if (status == VP8_STATUS_NOT_ENOUGH_DATA)
    throw TileDecodeError("truncated WebP (" + std::to_string(size) + " bytes)");
  if (status == VP8_STATUS_OUT_OF_MEMORY) throw std::bad_alloc();
  throw TileDecodeError("corrupt WebP: " + webp_status_text(status));
}

DecodedImage decode_webp(std::span<const unsigned char> bytes) {
  WebPDecoderConfig config;
  if (!WebPInitDecoderConfig(&config)) throw TileDecodeError("WebP decoder version mismatch");
  if (const VP8StatusCode status = WebPGetFeatures(bytes.data(), bytes.size(), &config.input); status != VP8_STATUS_OK)
    throw_webp_error(status, bytes.size());
  if (config.input.has_animation) throw TileDecodeError("animated WebP: tiles must be still images");
  if (config.input.width < 0 || config.input.height < 0) throw TileDecodeError("corrupt WebP: negative size");
  check_dimensions(static_cast<std::uint32_t>(config.input.width), static_cast<std::uint32_t>(config.input.height),
                   "WebP");

  DecodedImage image;
  image.format = ImageFormat::webp;
  image.width = static_cast<std::uint32_t>(config.input.width);
  image.height = static_cast<std::uint32_t>(config.input.height);
  image.channels = config.input.has_alpha ? 4 : 3;
  image.samples8.resize(std::size_t{image.width} * image.height * image.channels);
  config.output.colorspace = config.input.has_alpha ? MODE_RGBA : MODE_RGB;
  config.output.is_external_memory = 1;
  config.output.u.RGBA.rgba = image.samples8.data();
  config.output.u.RGBA.stride = static_cast<int>(image.width * image.channels);
  config.output.u.RGBA.size = image.samples8.size();
  const VP8StatusCode status = WebPDecode(bytes.data(), bytes.size(), &config);
  WebPFreeDecBuffer(&config.output);  // frees nothing of ours (external memory), but is the contract
  if (status != VP8_STATUS_OK) throw_webp_error(status, bytes.size());
  return image;
}

// ---------------------------------------------------------------------------------------------
// Encoding.

void check_encodable(const DecodedImage& image) {
  if (image.width == 0 || image.height == 0 || image.channels < 1 || image.channels > 4 ||
      (image.bit_depth != 8 && image.bit_depth != 16))
    throw std::invalid_argument("encode: an image needs pixels, 1..4 channels and 8 or 16 bits");
  const std::size_t samples = std::size_t{image.width} * image.height * image.channels;
  const std::size_t have = image.bit_depth == 16 ? image.samples16.size() : image.samples8.size();
  if (have != samples)
    throw std::invalid_argument("encode: " + std::to_string(have) + " samples for " + std::to_string(image.width) +
                                " x " + std::to_string(image.height) + " x " + std::to_string(image.channels));
}

void png_write_to_vector(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
  bool no_memory = false;
  try {
    out->insert(out->end(), data, data + length);
  } catch (const std::bad_alloc&) {
    no_memory = true;  // longjmp only outside the handler
  }
  if (no_memory) png_error(png, "out of memory");
}

void png_flush_nothing(png_structp) {}

class PngWriter {
 public:
  PngWriter() {
    png_ = png_create_write_struct(PNG_LIBPNG_VER_STRING, &message_, png_on_error, png_on_warning);
    if (png_) info_ = png_create_info_struct(png_);
  }
  ~PngWriter() { png_destroy_write_struct(png_ ? &png_ : nullptr, info_ ? &info_ : nullptr); }
  PngWriter(const PngWriter&) = delete;
  PngWriter& operator=(const PngWriter&) = delete;

  std::vector<unsigned char> encode(const DecodedImage& image, int zlib_level) {
    if (!png_ || !info_) throw std::bad_alloc();
    const unsigned char* pixels =
        image.bit_depth == 16 ? reinterpret_cast<const unsigned char*>(image.samples16.data()) : image.samples8.data();
    const std::size_t row_bytes = std::size_t{image.width} * image.channels * (image.bit_depth / 8);
    // libpng copies each row before transforming it (the byte swap below), so it never writes
    // through these pointers; its API just predates const.
    rows_.resize(image.height);
    for (std::size_t r = 0; r < image.height; ++r) rows_[r] = const_cast<unsigned char*>(pixels + r * row_bytes);
    out_.reserve(row_bytes * image.height / 2);
    if (!write(image, zlib_level)) throw TileDecodeError(std::string("PNG encoding failed: ") + message_.text);
    return std::move(out_);
  }

 private:
  bool write(const DecodedImage& image, int zlib_level) {
    if (setjmp(png_jmpbuf(png_))) return false;
    static constexpr int kColorTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                          PNG_COLOR_TYPE_RGB_ALPHA};
    png_set_write_fn(png_, &out_, png_write_to_vector, png_flush_nothing);
    png_set_compression_level(png_, std::clamp(zlib_level, 0, 9));
    png_set_IHDR(png_, info_, image.width, image.height, static_cast<int>(image.bit_depth),
                 kColorTypes[image.channels - 1], PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png_, info_);
    if (image.bit_depth == 16 && std::endian::native == std::endian::little) png_set_swap(png_);
    png_write_image(png_, rows_.data());
    png_write_end(png_, nullptr);
    return true;
  }

  PngMessage message_;
  std::vector<unsigned char> out_;
  std::vector<png_bytep> rows_;
  png_structp png_ = nullptr;
  png_infop info_ = nullptr;
};

std::uint8_t scale_16_to_8(std::uint32_t v) { return static_cast<std::uint8_t>((v * 255u + 32767u) / 65535u); }

}  // namespace

void ignore_png_checksums_for_fuzzing(bool ignore) { png_checksums_ignored.store(ignore, std::memory_order_relaxed); }

std::string_view to_string(ImageFormat format) {
  switch (format) {
    case ImageFormat::png:
      return "PNG";
    case ImageFormat::jpeg:
      return "JPEG";
    case ImageFormat::webp:
      return "WebP";
  }
  return "?";
}

std::optional<ImageFormat> sniff_image_format(std::span<const unsigned char> bytes) {
  static constexpr unsigned char kJpegMagic[] = {0xff, 0xd8, 0xff};
  if (starts_with(bytes, kPngMagic)) return ImageFormat::png;
  if (starts_with(bytes, kJpegMagic)) return ImageFormat::jpeg;
  if (bytes.size() >= 12 && std::memcmp(bytes.data(), "RIFF", 4) == 0 && std::memcmp(bytes.data() + 8, "WEBP", 4) == 0)
    return ImageFormat::webp;
  return std::nullopt;
}

DecodedImage decode_image(std::span<const unsigned char> bytes) {
  const std::optional<ImageFormat> format = sniff_image_format(bytes);
  if (!format) throw TileDecodeError("not a PNG, JPEG or WebP image (" + describe_start(bytes) + ")");
  switch (*format) {
    case ImageFormat::png:
      return PngReader(bytes).decode();
    case ImageFormat::jpeg:
      return decode_jpeg(bytes);
    case ImageFormat::webp:
      return decode_webp(bytes);
  }
  throw TileDecodeError("unknown image format");
}

std::vector<std::uint8_t> to_rgba8(const DecodedImage& image) {
  const std::size_t pixels = std::size_t{image.width} * image.height;
  std::vector<std::uint8_t> rgba(pixels * 4);
  const std::uint32_t c = image.channels;
  for (std::size_t p = 0; p < pixels; ++p) {
    std::uint8_t px[4] = {0, 0, 0, 255};
    for (std::uint32_t k = 0; k < c; ++k) {
      const std::size_t i = p * c + k;
      px[k] = image.bit_depth == 16 ? scale_16_to_8(image.samples16[i]) : image.samples8[i];
    }
    std::uint8_t* out = &rgba[p * 4];
    if (c <= 2) {  // gray (+ alpha)
      out[0] = out[1] = out[2] = px[0];
      out[3] = c == 2 ? px[1] : 255;
    } else {
      out[0] = px[0];
      out[1] = px[1];
      out[2] = px[2];
      out[3] = c == 4 ? px[3] : 255;
    }
  }
  return rgba;
}

std::vector<unsigned char> encode_png(const DecodedImage& image, int zlib_level) {
  check_encodable(image);
  return PngWriter().encode(image, zlib_level);
}

std::vector<unsigned char> encode_jpeg(const DecodedImage& image, int quality) {
  check_encodable(image);
  if (image.bit_depth != 8 || (image.channels != 1 && image.channels != 3))
    throw std::invalid_argument("encode_jpeg: needs 8-bit gray or RGB");
  TjHandle tj(tjInitCompress());
  if (!tj) throw std::bad_alloc();
  unsigned char* jpeg = nullptr;
  unsigned long size = 0;
  const bool gray = image.channels == 1;
  if (tjCompress2(tj.get(), image.samples8.data(), static_cast<int>(image.width), 0, static_cast<int>(image.height),
                  gray ? TJPF_GRAY : TJPF_RGB, &jpeg, &size, gray ? TJSAMP_GRAY : TJSAMP_420,
                  std::clamp(quality, 1, 100), 0) != 0) {
    tjFree(jpeg);
    throw TileDecodeError(std::string("JPEG encoding failed: ") + tjGetErrorStr2(tj.get()));
  }
  std::vector<unsigned char> out(jpeg, jpeg + size);
  tjFree(jpeg);
  return out;
}

}  // namespace trailray::terrain
