#pragma once
// Warps part of a raster into one Web Mercator tile with GDAL's warper: the shared core of the
// height and imagery sources. Internal to the terrain library.

#include <gdal_priv.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "terrain/gdal/gdal_raster.hpp"
#include "terrain/loading/stop_token.hpp"
#include "terrain/tile.hpp"

namespace trailray::terrain::gdal_detail {

struct WarpSpec {
  GDALDataType data_type = GDT_Float32;  // of the tile's bands and of the warper's working buffers
  std::vector<int> source_bands;         // warped into the tile's bands 1..n, in this order
  // Source pixels equal to this (in every warped band, for more than one) are missing: the kernel
  // leaves them out. NaN means the NaN pixels.
  std::optional<double> source_nodata;
  int source_alpha_band = 0;  // 0: none; else the source's alpha band (0 = transparent)
  // Set: the tile gets one more band, 255 where it has data and 0 where it has none, and its other
  // bands are 0 there. Unset: the tile's bands hold NaN where there is no data (float types only).
  bool destination_alpha = false;
  GdalResampling resampling = GdalResampling::bilinear;
  std::uint32_t tile_size = kGdalTileSize;
};

enum class WarpStatus { ok, cancelled, failed };

struct WarpOutput {
  WarpStatus status = WarpStatus::failed;
  GDALDatasetUniquePtr tile;  // when ok: an in-memory dataset in EPSG:3857, tile_size square
  std::string error;          // when failed: GDAL's message
};

// `tile` must be valid. Stops early (cancelled) once `stop` is requested.
WarpOutput warp_tile(GDALDataset& source, const TileId& tile, const WarpSpec& spec, StopToken stop);

}  // namespace trailray::terrain::gdal_detail
