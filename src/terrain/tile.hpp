#pragma once
// Decoded terrain tiles: a grid of heights, or an RGBA image, for one Web Mercator tile
// (geo/tile_id.hpp, XYZ numbering). What every source produces and every consumer (LOD, the
// height sampler, the renderer) reads. No I/O here.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "geo/tile_id.hpp"

namespace trailray::terrain {

using geo::TileId;

// Where the samples of a grid sit in its tile.
//   pixel_is_area:  sample (i, j) is the centre of cell i of width tile_width / width
//                   (Terrarium, Mapbox and GDAL-warped tiles: 256 x 256 samples);
//   pixel_is_point: sample (i, j) lies at i / (width - 1) of the tile, so the first and last
//                   rows and columns are the tile's edges, shared with the neighbours
//                   (AlpineMaps: 65 x 65 samples).
enum class SampleLayout { pixel_is_area, pixel_is_point };

inline constexpr float kNoHeight = std::numeric_limits<float>::quiet_NaN();

// A tile's own triangles, where the source has them (a quantized-mesh layer): drawn as they are
// instead of a grid over the samples. Vertices at (u, v), fractions of the tile from its
// north-west corner (v downwards, in the tile's Mercator rows), with their heights in metres.
struct TileTriangles {
  std::vector<float> u, v, height_m;
  std::vector<std::uint32_t> indices;  // three a triangle
  std::size_t byte_size() const {
    return sizeof(TileTriangles) + (u.size() + v.size() + height_m.size()) * sizeof(float) +
           indices.size() * sizeof(std::uint32_t);
  }
};

struct HeightTile {
  TileId id;
  std::uint32_t width = 0, height = 0;
  SampleLayout layout = SampleLayout::pixel_is_area;
  // Row-major from the north-west corner, metres above sea level; NaN where there is no data
  // (a hole, never a -32768 spike).
  std::vector<float> heights;
  // Over the valid samples; NaN when the tile has none.
  float min_m = kNoHeight, max_m = kNoHeight;
  // The source's own triangles over the tile (null: draw a grid over the samples). The samples
  // stay what sampling and the level of detail read.
  std::shared_ptr<const TileTriangles> triangles;

  float at(std::uint32_t col, std::uint32_t row) const { return heights[std::size_t{row} * width + col]; }
  bool has_data() const { return !std::isnan(min_m); }
  std::size_t byte_size() const {
    return sizeof(HeightTile) + heights.size() * sizeof(float) + (triangles ? triangles->byte_size() : 0);
  }
};

// Recomputes min_m and max_m from the samples.
void update_height_range(HeightTile& tile);

struct ImageTile {
  TileId id;
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // row-major from the north-west, 4 bytes a pixel

  std::size_t byte_size() const { return sizeof(ImageTile) + rgba.size(); }
};

// What became of one tile request.
enum class TileStatus {
  ok,         // the tile is there
  no_data,    // the source has nothing here (HTTP 404, a missing file, outside a DEM): not an error
  failed,     // something went wrong (corrupt bytes, a timeout, 5xx after the retries): `error` says what
  cancelled,  // the request was cancelled before it finished
};

std::string_view to_string(TileStatus status);

template <class Tile>
struct TileResult {
  TileStatus status = TileStatus::no_data;
  Tile tile{};        // valid when status == ok
  std::string error;  // when status == failed: "<source> <z/x/y>: what happened"
};

}  // namespace trailray::terrain
