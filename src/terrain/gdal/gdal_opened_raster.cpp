#include "terrain/gdal/gdal_opened_raster.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geo/web_mercator.hpp"
#include "terrain/gdal/gdal_errors.hpp"
#include "terrain/gdal/gdal_raster.hpp"

namespace trailray::terrain::gdal_detail {
namespace {

RasterGeoref georef_of(DatasetPool& pool) {
  DatasetPool::Lease dataset = pool.acquire();
  return read_georef(*dataset, pool.path());
}

// How much coarser each overview level is than the raster (levels every band has).
std::vector<double> overview_factors_of(DatasetPool& pool) {
  DatasetPool::Lease dataset = pool.acquire();
  GdalErrorCapture errors;
  int levels = dataset->GetRasterBand(1)->GetOverviewCount();
  for (int b = 2; b <= dataset->GetRasterCount(); ++b)
    levels = std::min(levels, dataset->GetRasterBand(b)->GetOverviewCount());
  std::vector<double> factors;
  for (int level = 0; level < levels; ++level) {
    GDALRasterBand* overview = dataset->GetRasterBand(1)->GetOverview(level);
    const int width = overview != nullptr ? overview->GetXSize() : 0;
    // A level GDAL cannot describe is never chosen.
    factors.push_back(width > 0 ? static_cast<double>(dataset->GetRasterXSize()) / width : 0.0);
  }
  return factors;
}

}  // namespace

OpenedRaster::OpenedRaster(const std::string& path, std::size_t max_idle_datasets)
    : max_idle_datasets_(max_idle_datasets),
      pool_(path, max_idle_datasets),
      georef_(georef_of(pool_)),
      overview_factors_(overview_factors_of(pool_)),
      overview_pools_(overview_factors_.size()) {}

DatasetPool& OpenedRaster::pool_for_tile(const TileId& tile) {
  if (overview_factors_.empty() || !georef_.pixel_ground_size_m) return pool_;
  const std::optional<geo::LatLonBounds> bounds = geo::tile_bounds_latlon(tile);
  if (!bounds) return pool_;
  // Ground size of the tile's cells at its centre latitude, in raster pixels.
  const double lat = 0.5 * (bounds->min_lat + bounds->max_lat);
  const double cell_m = 2.0 * geo::kMercatorHalfExtentM * std::cos(lat * std::numbers::pi / 180.0) /
                        (static_cast<double>(kGdalTileSize) * std::ldexp(1.0, tile.zoom));
  const double wanted = cell_m / *georef_.pixel_ground_size_m;
  int best = -1;
  for (std::size_t level = 0; level < overview_factors_.size(); ++level) {
    const double factor = overview_factors_[level];
    if (factor > 1.0 && factor <= wanted && (best < 0 || factor > overview_factors_[std::size_t(best)]))
      best = static_cast<int>(level);
  }
  if (best < 0) return pool_;
  std::lock_guard lock(overview_mutex_);
  std::unique_ptr<DatasetPool>& pool = overview_pools_[std::size_t(best)];
  if (!pool)
    pool = std::make_unique<DatasetPool>(path(), max_idle_datasets_,
                                         std::vector<std::string>{"OVERVIEW_LEVEL=" + std::to_string(best)});
  return *pool;
}

SourceInfo OpenedRaster::basic_info() const {
  SourceInfo info;
  info.name = path();
  info.min_zoom = 0;
  if (georef_.native_zoom) info.max_zoom = *georef_.native_zoom;
  info.bounds = georef_.bounds_wgs84;
  info.format = "gdal:" + georef_.driver;
  return info;
}

bool OpenedRaster::may_cover(const TileId& tile) const {
  if (!georef_.bounds_wgs84) return true;
  const std::optional<geo::LatLonBounds> t = geo::tile_bounds_latlon(tile);
  if (!t) return false;
  const geo::LatLonBounds& r = *georef_.bounds_wgs84;
  // Two pixels of margin: the extent's edges were transformed at a limited number of points,
  // and the resampling kernel reaches a pixel beyond a cell's centre.
  const double margin_lon = 2.0 * (r.max_lon - r.min_lon) / georef_.width;
  const double margin_lat = 2.0 * (r.max_lat - r.min_lat) / georef_.height;
  return t->max_lon > r.min_lon - margin_lon && t->min_lon < r.max_lon + margin_lon &&
         t->max_lat > r.min_lat - margin_lat && t->min_lat < r.max_lat + margin_lat;
}

std::string OpenedRaster::tile_error(const TileId& tile, const std::string& what) const {
  return path() + " " + geo::to_string(tile) + ": " + what;
}

}  // namespace trailray::terrain::gdal_detail
