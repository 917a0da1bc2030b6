// libFuzzer target: arbitrary bytes as a tile, through decode_height_tile in one of the four
// encodings (PNG/JPEG/WebP through our codecs, TIFF through GDAL for float) and decode_image_tile. Each
// must either throw TileDecodeError with a message or return a tile that keeps the documented
// contract (height_decode.hpp, tile.hpp); anything else aborts.
//
// The target turns on ignore_png_checksums_for_fuzzing (image_codec.hpp): libpng ignores CRCs and
// Adler-32 checksums, so mutated PNGs reach the pixel code. The switch is the target's own, so
// its regression inputs (tests/fuzz/regressions/tile/) replay in every build exactly as found.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>

#include "terrain/codecs/height_decode.hpp"
#include "terrain/codecs/image_codec.hpp"

namespace {

using namespace trailray::terrain;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz: contract violated: %s\n", what);
    std::abort();
  }
}

void check_height_tile(const HeightTile& t, const TileId& id) {
  check(t.id == id, "height tile with another id");
  check(t.width == t.height, "height tile not square");
  check(t.width >= kMinHeightTileSize && t.width <= kMaxHeightTileSize, "height tile of an insane size");
  check(t.heights.size() == std::size_t{t.width} * t.height, "height count differs from width x height");
  check(t.layout == layout_for_size(t.width), "layout does not follow the size");
  std::size_t valid = 0, plausible = 0;
  for (float h : t.heights) {
    if (std::isnan(h)) continue;
    check(std::isfinite(h), "an infinite height");
    check(h >= t.min_m && h <= t.max_m, "a height outside [min_m, max_m]");
    ++valid;
    if (h >= kPlausibleMinHeightM && h <= kPlausibleMaxHeightM) ++plausible;
  }
  check(t.has_data() == (valid > 0), "has_data() disagrees with the samples");
  check(plausible * 2 >= valid, "mostly implausible heights were accepted");
}

void check_image_tile(const ImageTile& t, const TileId& id) {
  check(t.id == id, "image tile with another id");
  check(t.width >= 1 && t.width <= kMaxImageDimension && t.height >= 1 && t.height <= kMaxImageDimension,
        "image tile of an insane size");
  check(t.rgba.size() == std::size_t{t.width} * t.height * 4, "rgba size differs from width x height x 4");
}

// A PNG whose header asks for more than a megapixel within the size limit. Small files inflate to
// such images cheaply (runs of zeros), and the per-pixel loops, instrumented for coverage, then
// take most of the time while exploring nothing a smaller image would not: they are skipped.
// Beyond the limit they still run (the size check is cheap and must hold).
bool is_costly_png(std::span<const unsigned char> bytes) {
  if (bytes.size() < 24 || sniff_image_format(bytes) != ImageFormat::png) return false;
  const auto be32 = [&](std::size_t at) {
    return std::uint64_t{bytes[at]} << 24 | std::uint64_t{bytes[at + 1]} << 16 | std::uint64_t{bytes[at + 2]} << 8 |
           bytes[at + 3];
  };
  const std::uint64_t width = be32(16), height = be32(20);
  return width <= kMaxImageDimension && height <= kMaxImageDimension && width * height > (std::uint64_t{1} << 20);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool checksums_ignored = (ignore_png_checksums_for_fuzzing(true), true);
  (void)checksums_ignored;
  const std::span<const unsigned char> bytes(data, size);
  if (is_costly_png(bytes)) return 0;
  const TileId id{5, 17, 11};
  // One encoding per input, chosen by its length (every byte stays tile content): decoding all
  // four would run the same image decoder four times for little more coverage.
  constexpr HeightEncoding kEncodings[] = {HeightEncoding::terrarium, HeightEncoding::mapbox,
                                           HeightEncoding::alpinemaps, HeightEncoding::float32};
  try {
    check_height_tile(decode_height_tile(bytes, kEncodings[size % 4], id), id);
  } catch (const TileDecodeError& e) {
    check(e.what()[0] != '\0', "a decode error without a message");
  }
  try {
    check_image_tile(decode_image_tile(bytes, id), id);
  } catch (const TileDecodeError& e) {
    check(e.what()[0] != '\0', "a decode error without a message");
  }
  return 0;
}
