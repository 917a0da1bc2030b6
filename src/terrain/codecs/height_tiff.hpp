#pragma once
// Float32 TIFF height tiles (HeightEncoding::float32), read and written through GDAL's in-memory
// files. Native only: the browser's build has no GDAL, and height_tiff_web.cpp says so.

#include <cstdint>
#include <span>
#include <vector>

#include "terrain/tile.hpp"

namespace trailray::terrain::detail {

HeightTile decode_float_tiff(std::span<const unsigned char> bytes, const TileId& id);
std::vector<unsigned char> encode_float_tiff(const HeightTile& tile);

// Throws TileDecodeError for a tile of no or absurd size (height_decode.cpp).
void check_tile_size(std::uint32_t width, std::uint32_t height);

}  // namespace trailray::terrain::detail
