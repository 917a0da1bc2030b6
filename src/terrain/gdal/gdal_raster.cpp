// GdalHeightSource: a raster's band 1 as height tiles and point heights (gdal_raster.hpp).
#include "terrain/gdal/gdal_raster.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "terrain/gdal/gdal_errors.hpp"
#include "terrain/gdal/gdal_native_grid.hpp"
#include "terrain/gdal/gdal_opened_raster.hpp"
#include "terrain/gdal/gdal_tile_cache.hpp"
#include "terrain/gdal/gdal_warp.hpp"

namespace trailray::terrain {

using gdal_detail::DatasetPool;
using gdal_detail::GdalErrorCapture;

namespace {

struct HeightBand {
  gdal_detail::HeightBandValues values;
  bool floating_point = false;
};

HeightBand describe_height_band(DatasetPool& pool) {
  DatasetPool::Lease dataset = pool.acquire();
  GDALRasterBand* band = dataset->GetRasterBand(1);
  HeightBand result;
  result.values = gdal_detail::read_height_band_values(*band);
  result.floating_point = GDALDataTypeIsFloating(band->GetRasterDataType()) != 0;
  return result;
}

}  // namespace

struct GdalHeightSource::Impl {
  Impl(const std::string& path, const GdalOptions& opts)
      : options(opts),
        raster(path, opts.max_idle_datasets),
        band(describe_height_band(raster.pool())),
        to_raster_crs(raster.georef(), path),
        grid(raster.pool(), raster.georef().width, raster.georef().height, band.values, opts.native_cache_bytes,
             opts.read_whole_raster),
        tiles(opts.tile_cache_bytes) {
    info = raster.basic_info();
    info.encoding = HeightEncoding::float32;
  }

  gdal_detail::WarpSpec warp_spec() const {
    gdal_detail::WarpSpec spec;
    spec.data_type = GDT_Float32;
    spec.source_bands = {1};
    spec.source_nodata = band.values.nodata;
    // A float raster without a nodata value marks holes with NaN: tell the warper, so that it
    // leaves them out of the kernel instead of spreading them to the neighbouring cells.
    if (!spec.source_nodata && band.floating_point) spec.source_nodata = std::numeric_limits<double>::quiet_NaN();
    spec.resampling = options.resampling;
    return spec;
  }

  TileResult<HeightTile> warp(const TileId& id, StopToken stop) {
    TileResult<HeightTile> result;
    try {
      DatasetPool::Lease dataset = raster.pool_for_tile(id).acquire();
      gdal_detail::WarpOutput out = gdal_detail::warp_tile(*dataset, id, warp_spec(), stop);
      if (out.status == gdal_detail::WarpStatus::cancelled) {
        result.status = TileStatus::cancelled;
        return result;
      }
      if (out.status == gdal_detail::WarpStatus::failed) {
        result.status = TileStatus::failed;
        result.error = raster.tile_error(id, out.error);
        return result;
      }
      HeightTile& tile = result.tile;
      tile.id = id;
      tile.width = tile.height = kGdalTileSize;
      tile.layout = SampleLayout::pixel_is_area;
      tile.heights.resize(std::size_t{kGdalTileSize} * kGdalTileSize);
      GdalErrorCapture errors;
      const int size = static_cast<int>(kGdalTileSize);
      if (out.tile->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, size, size, tile.heights.data(), size, size, GDT_Float32,
                                               0, 0, nullptr) != CE_None) {
        result.status = TileStatus::failed;
        result.error = raster.tile_error(id, "cannot read the warped tile: " + errors.message());
        return result;
      }
    } catch (const SourceError& e) {  // the file could not be opened again
      result.status = TileStatus::failed;
      result.error = raster.tile_error(id, e.what());
      return result;
    }
    HeightTile& tile = result.tile;
    // Scale and offset after resampling: both are linear, so the order does not matter.
    if (band.values.scale != 1.0 || band.values.offset != 0.0) {
      for (float& h : tile.heights)
        h = static_cast<float>(h * band.values.scale + band.values.offset);  // NaN stays NaN
    }
    update_height_range(tile);
    result.status = tile.has_data() ? TileStatus::ok : TileStatus::no_data;
    if (result.status != TileStatus::ok) result.tile = {};
    return result;
  }

  const GdalOptions options;
  gdal_detail::OpenedRaster raster;
  const HeightBand band;
  gdal_detail::LonLatToRaster to_raster_crs;
  gdal_detail::NativeHeightGrid grid;
  gdal_detail::WarpedTileCache<HeightTile> tiles;
  SourceInfo info;
};

GdalHeightSource::GdalHeightSource(const std::string& path, GdalOptions options)
    : impl_(std::make_unique<Impl>(path, options)) {}

GdalHeightSource::~GdalHeightSource() = default;

const SourceInfo& GdalHeightSource::info() const { return impl_->info; }

int GdalHeightSource::raster_width() const { return impl_->raster.georef().width; }
int GdalHeightSource::raster_height() const { return impl_->raster.georef().height; }

TileResult<HeightTile> GdalHeightSource::load(const TileId& tile, StopToken stop) {
  return gdal_detail::load_warped_tile<HeightTile>(*impl_, tile, stop);
}

void GdalHeightSource::sample_native(std::span<const geo::LatLon> points, std::span<double> heights) {
  const std::size_t n = std::min(points.size(), heights.size());
  std::vector<double> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = points[i].lon;
    y[i] = points[i].lat;
  }
  impl_->to_raster_crs.transform(x, y);
  // Raster CRS -> continuous pixel coordinates, in place.
  const std::array<double, 6>& gt = impl_->raster.georef().crs_to_pixel;
  for (std::size_t i = 0; i < n; ++i) {
    const double px = gt[0] + x[i] * gt[1] + y[i] * gt[2];
    const double py = gt[3] + x[i] * gt[4] + y[i] * gt[5];
    x[i] = px;
    y[i] = py;
  }
  impl_->grid.sample(x, y, heights.first(n));
}

std::optional<double> GdalHeightSource::sample_native(double lat, double lon) {
  const geo::LatLon point{lat, lon};
  double height = std::numeric_limits<double>::quiet_NaN();
  sample_native(std::span<const geo::LatLon>(&point, 1), std::span<double>(&height, 1));
  return height;
}

std::string GdalHeightSource::native_read_error() const { return impl_->grid.read_error(); }

}  // namespace trailray::terrain
