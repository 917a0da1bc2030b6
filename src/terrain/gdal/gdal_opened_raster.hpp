#pragma once
// What both GDAL sources hold for one raster file: its pool of read-only handles and its
// georeferencing, with what follows from them (the SourceInfo basics, whether a tile can meet
// the raster). Internal to the terrain library.

#include <cstddef>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "terrain/gdal/gdal_dataset_pool.hpp"
#include "terrain/gdal/gdal_georef.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain::gdal_detail {

class OpenedRaster {
 public:
  // Throws SourceError naming the path (cannot open, no band, no georeferencing).
  OpenedRaster(const std::string& path, std::size_t max_idle_datasets);

  const std::string& path() const { return pool_.path(); }
  // Handles on the full-resolution raster.
  DatasetPool& pool() { return pool_; }

  // Handles to warp `tile` from: the coarsest overview of the raster whose pixels are still no
  // larger than the tile's cells (the choice gdalwarp makes), or the full raster when there is
  // none. Without overviews a zoomed-out tile of a large raster would read all of it. Throws
  // SourceError when an overview cannot be opened.
  DatasetPool& pool_for_tile(const TileId& tile);
  const RasterGeoref& georef() const { return georef_; }

  // name, zooms, bounds and format ("gdal:<driver>").
  SourceInfo basic_info() const;

  // False when the tile lies clearly outside the raster's extent (then warping it would only
  // produce nodata); true when it may overlap, or when the extent is unknown.
  bool may_cover(const TileId& tile) const;

  // "<path> <z/x/y>: <what>", the form of TileResult::error.
  std::string tile_error(const TileId& tile, const std::string& what) const;

 private:
  const std::size_t max_idle_datasets_;
  DatasetPool pool_;
  RasterGeoref georef_;
  std::vector<double> overview_factors_;  // raster width / overview width, by overview level
  std::mutex overview_mutex_;
  std::vector<std::unique_ptr<DatasetPool>> overview_pools_;  // by level, opened on first use
};

}  // namespace trailray::terrain::gdal_detail
