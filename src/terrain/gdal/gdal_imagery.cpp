// GdalImagerySource: an 8-bit gray / RGB raster (with or without alpha) as RGBA tiles
// (gdal_raster.hpp).
#include <algorithm>
#include <vector>

#include "terrain/gdal/gdal_errors.hpp"
#include "terrain/gdal/gdal_opened_raster.hpp"
#include "terrain/gdal/gdal_raster.hpp"
#include "terrain/gdal/gdal_tile_cache.hpp"
#include "terrain/gdal/gdal_warp.hpp"

namespace trailray::terrain {

using gdal_detail::DatasetPool;
using gdal_detail::GdalErrorCapture;

namespace {

// Which source bands hold the colour and which the alpha.
struct ImageLayout {
  std::vector<int> colour_bands;  // 1 (gray) or 3 (RGB)
  int alpha_band = 0;             // 0: none
  std::optional<double> nodata;   // of the colour bands
};

ImageLayout describe_image_bands(DatasetPool& pool) {
  DatasetPool::Lease dataset = pool.acquire();
  GdalErrorCapture errors;
  const int count = dataset->GetRasterCount();
  if (count < 1 || count > 4)
    throw SourceError(pool.path() + ": imagery needs 1 (gray), 2 (gray + alpha), 3 (RGB) or 4 (RGBA) bands, not " +
                      std::to_string(count));
  for (int b = 1; b <= count; ++b) {
    if (dataset->GetRasterBand(b)->GetRasterDataType() != GDT_Byte)
      throw SourceError(pool.path() + ": imagery needs 8-bit bands; band " + std::to_string(b) + " is " +
                        GDALGetDataTypeName(dataset->GetRasterBand(b)->GetRasterDataType()));
  }
  GDALRasterBand* first = dataset->GetRasterBand(1);
  if (first->GetColorInterpretation() == GCI_PaletteIndex)
    throw SourceError(pool.path() +
                      ": paletted rasters are not supported (expand them first: gdal_translate -expand rgba)");
  ImageLayout layout;
  layout.colour_bands = count >= 3 ? std::vector<int>{1, 2, 3} : std::vector<int>{1};
  if (count == 2 || count == 4) layout.alpha_band = count;
  int has_nodata = 0;
  const double nodata = first->GetNoDataValue(&has_nodata);
  if (has_nodata) layout.nodata = nodata;
  return layout;
}

}  // namespace

struct GdalImagerySource::Impl {
  Impl(const std::string& path, const GdalOptions& opts)
      : options(opts),
        raster(path, opts.max_idle_datasets),
        layout(describe_image_bands(raster.pool())),
        tiles(opts.tile_cache_bytes) {
    info = raster.basic_info();
  }

  TileResult<ImageTile> warp(const TileId& id, StopToken stop) {
    gdal_detail::WarpSpec spec;
    spec.data_type = GDT_Byte;
    spec.source_bands = layout.colour_bands;
    spec.source_nodata = layout.nodata;
    spec.source_alpha_band = layout.alpha_band;
    spec.destination_alpha = true;
    spec.resampling = options.resampling;

    TileResult<ImageTile> result;
    ImageTile& tile = result.tile;
    tile.id = id;
    tile.width = tile.height = kGdalTileSize;
    tile.rgba.assign(std::size_t{kGdalTileSize} * kGdalTileSize * 4, 0);
    try {
      DatasetPool::Lease dataset = raster.pool_for_tile(id).acquire();
      gdal_detail::WarpOutput out = gdal_detail::warp_tile(*dataset, id, spec, stop);
      if (out.status == gdal_detail::WarpStatus::cancelled) {
        result = {};
        result.status = TileStatus::cancelled;
        return result;
      }
      if (out.status == gdal_detail::WarpStatus::failed) {
        result = {};
        result.status = TileStatus::failed;
        result.error = raster.tile_error(id, out.error);
        return result;
      }
      // Tile band b goes to byte b of each pixel; a gray band fills red, green and blue.
      const int size = static_cast<int>(kGdalTileSize);
      const int colour_count = static_cast<int>(layout.colour_bands.size());
      GdalErrorCapture errors;
      for (int channel = 0; channel < 4; ++channel) {
        const int band = channel == 3 ? colour_count + 1 : std::min(channel + 1, colour_count);
        if (out.tile->GetRasterBand(band)->RasterIO(GF_Read, 0, 0, size, size, tile.rgba.data() + channel, size, size,
                                                    GDT_Byte, 4, 4 * size, nullptr) != CE_None) {
          result = {};
          result.status = TileStatus::failed;
          result.error = raster.tile_error(id, "cannot read the warped tile: " + errors.message());
          return result;
        }
      }
    } catch (const SourceError& e) {  // the file could not be opened again
      result = {};
      result.status = TileStatus::failed;
      result.error = raster.tile_error(id, e.what());
      return result;
    }
    bool any = false;
    for (std::size_t i = 3; i < tile.rgba.size() && !any; i += 4) any = tile.rgba[i] != 0;
    if (!any) {
      result = {};
      result.status = TileStatus::no_data;
      return result;
    }
    result.status = TileStatus::ok;
    return result;
  }

  const GdalOptions options;
  gdal_detail::OpenedRaster raster;
  const ImageLayout layout;
  gdal_detail::WarpedTileCache<ImageTile> tiles;
  SourceInfo info;
};

GdalImagerySource::GdalImagerySource(const std::string& path, GdalOptions options)
    : impl_(std::make_unique<Impl>(path, options)) {}

GdalImagerySource::~GdalImagerySource() = default;

const SourceInfo& GdalImagerySource::info() const { return impl_->info; }

TileResult<ImageTile> GdalImagerySource::load(const TileId& tile, StopToken stop) {
  return gdal_detail::load_warped_tile<ImageTile>(*impl_, tile, stop);
}

}  // namespace trailray::terrain
