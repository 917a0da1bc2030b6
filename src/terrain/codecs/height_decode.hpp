#pragma once
// Tile files -> HeightTile / ImageTile, and back (height tiles -> PNG or float TIFF) for fixtures,
// tools and benchmarks. The pixel formulas are those of height_encoding.hpp. Thread-safe.

#include <cstdint>
#include <span>
#include <vector>

#include "terrain/codecs/height_encoding.hpp"
#include "terrain/codecs/image_codec.hpp"
#include "terrain/tile.hpp"

namespace trailray::terrain {

// Where the samples of an n x n height tile sit: pixel_is_point for 2^k + 1 samples a side
// (AlpineMaps' 65 x 65: the edges are shared with the neighbours), pixel_is_area otherwise
// (Terrarium's and Mapbox's 256 or 512).
SampleLayout layout_for_size(std::uint32_t samples_per_side);

// Height tiles are square, this many samples a side.
inline constexpr std::uint32_t kMinHeightTileSize = 2;
inline constexpr std::uint32_t kMaxHeightTileSize = kMaxImageDimension;

// Decodes one height tile. terrarium, mapbox and alpinemaps read a PNG, WebP or (lossy, so
// rarely right) JPEG; float32 reads a single-band TIFF (any GDAL-readable sample type; its
// nodata value becomes NaN). A pixel with alpha 0 is a hole (NaN). 16-bit PNGs keep their
// precision: alpinemaps reads the first channel's 16-bit value as its raw R*256 + G, the
// RGB encodings scale each channel to 8 bits.
// Throws TileDecodeError: undecodable bytes (image_codec.hpp), "wrong tile size 300x200 ...",
// or, when most valid samples fall outside [kPlausibleMinHeightM, kPlausibleMaxHeightM],
// "... the encoding is probably wrong; mapbox would give plausible heights".
HeightTile decode_height_tile(std::span<const unsigned char> bytes, HeightEncoding encoding, const TileId& id);

// The second half of decode_height_tile for an image already decoded (terrarium, mapbox,
// alpinemaps; float32 needs a TIFF and throws here).
HeightTile heights_from_image(const DecodedImage& image, HeightEncoding encoding, const TileId& id);

// Decodes an imagery tile of any size (up to kMaxImageDimension) to 8-bit RGBA.
ImageTile decode_image_tile(std::span<const unsigned char> bytes, const TileId& id);

// Encodes heights so that decode_height_tile(..., encoding, id) gives them back, quantised to
// the encoding's step (terrarium 1/256 m, mapbox 0.1 m, alpinemaps 1/8 m; float32 exact) and
// clamped to its range. terrarium, mapbox, alpinemaps -> an 8-bit RGB PNG, or RGBA with alpha
// 0 at the NaN samples when there are any (Terrarium itself has no nodata; alpha 0 is how
// this code, and MapLibre, read a hole). float32 -> a single-band Float32 TIFF, NaN kept.
// zlib_level as for encode_png. Throws std::invalid_argument for a malformed tile.
std::vector<unsigned char> encode_height_tile(const HeightTile& tile, HeightEncoding encoding, int zlib_level = 6);

// encode_height_tile(tile, HeightEncoding::terrarium).
std::vector<unsigned char> encode_terrarium_png(const HeightTile& tile);

}  // namespace trailray::terrain
