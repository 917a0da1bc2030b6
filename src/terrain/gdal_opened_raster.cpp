#include "terrain/gdal_opened_raster.hpp"

namespace trailray::terrain::gdal_detail {
namespace {

RasterGeoref georef_of(DatasetPool& pool) {
  DatasetPool::Lease dataset = pool.acquire();
  return read_georef(*dataset, pool.path());
}

}  // namespace

OpenedRaster::OpenedRaster(const std::string& path, std::size_t max_idle_datasets)
    : pool_(path, max_idle_datasets), georef_(georef_of(pool_)) {}

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
