#pragma once
// Bilinear heights on a tile pyramid's level, across tile seams: the grid that a level's tiles
// share (every tile of a source has the same samples per side and layout), where a point falls
// in it, and the height from the four samples around it. HeightSampler (which loads the tiles it
// needs) and scene::TerrainView::height_in_memory (which uses only the tiles already loaded)
// both sample through here.

#include <array>
#include <cstdint>
#include <functional>

#include "geo/tile_id.hpp"
#include "terrain/tile.hpp"

namespace trailray::terrain {

// The samples per side of a level's tiles and where they sit (edges or cell centres).
struct SampleGrid {
  std::uint32_t width = 0;
  SampleLayout layout = SampleLayout::pixel_is_area;
};

// Where a point falls in a level's global sample grid: the four samples around it and the
// bilinear weights. Sample indices run over the whole world (tile x * step + column).
struct SampleFootprint {
  std::array<std::uint64_t, 2> col{}, row{};
  double tx = 0.0, ty = 0.0;  // fractions between col[0]..col[1] and row[0]..row[1]
};

// The footprint of a point (its fractional tile coordinate at `zoom`); x wraps around the globe,
// y is clamped to the grid. `grid.width` must be at least 2.
SampleFootprint sample_footprint(const geo::TileCoord& c, int zoom, const SampleGrid& grid);

// The tile holding a global sample, and the sample's column/row inside it.
struct TileSample {
  TileId tile;
  std::uint32_t col = 0, row = 0;
};
TileSample locate_sample(std::uint64_t col, std::uint64_t row, int zoom, const SampleGrid& grid);

// The tile holding an id's samples, nullptr where there is none (not loaded, no data).
using TileLookup = std::function<const HeightTile*(const TileId&)>;

// The bilinear height over the footprint's four samples. Samples of missing tiles and nodata
// samples are left out and the others' weights renormalised; NaN when none is left.
double bilinear_height(const SampleFootprint& footprint, int zoom, const SampleGrid& grid, const TileLookup& tile_of);

// The bilinear height inside one tile at a continuous sample position (col, row in the tile's own
// samples), clamped to the tile; nodata samples left out as above, NaN when all four are.
double bilinear_in_tile(const HeightTile& tile, double col, double row);

}  // namespace trailray::terrain
