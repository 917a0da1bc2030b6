#pragma once
// Where a raster lies: its size, geotransform and CRS, its extent in WGS84 and the zoom that
// matches its resolution; and the WGS84 -> raster CRS transformation for point queries.
// Internal to the terrain library.

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <array>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "geo/bounds.hpp"

namespace trailray::terrain::gdal_detail {

struct RasterGeoref {
  std::string driver;  // GDAL's short name: "GTiff", "SRTMHGT", ...
  int width = 0, height = 0;
  // GDAL geotransforms: pixel/line -> CRS x/y (area convention: (0, 0) is the outer corner of the
  // first pixel) and back.
  std::array<double, 6> pixel_to_crs{}, crs_to_pixel{};
  OGRSpatialReference crs;                        // with OAMS_TRADITIONAL_GIS_ORDER (x = easting or longitude)
  bool crs_is_wgs84 = false;                      // the CRS is WGS84 longitude/latitude: no transformation needed
  std::optional<geo::LatLonBounds> bounds_wgs84;  // none when GDAL cannot transform the extent
  std::optional<double> pixel_ground_size_m;      // geometric mean of a centre pixel's sides
  std::optional<int> native_zoom;                 // zoom_for_ground_resolution at the centre
};

// Reads the georeferencing of an open raster. Throws SourceError "<path>: ..." when it has no
// raster band, no geotransform, a degenerate one, or no CRS.
RasterGeoref read_georef(GDALDataset& dataset, const std::string& path);

// The zoom whose 256-pixel tiles have pixels about as large on the ground as `pixel_size_m` at
// latitude `lat_deg` (rounded log2, clamped to 0..24).
int zoom_for_ground_resolution(double pixel_size_m, double lat_deg);

// The WGS84 (EPSG:4326, longitude first) -> raster CRS transformation. OGR transformation
// objects are not thread-safe: each call borrows one of a pool of clones.
class LonLatToRaster {
 public:
  // Throws SourceError "<path>: ..." when OGR has no transformation between the two CRS.
  LonLatToRaster(const RasterGeoref& georef, const std::string& path);
  ~LonLatToRaster();
  LonLatToRaster(const LonLatToRaster&) = delete;
  LonLatToRaster& operator=(const LonLatToRaster&) = delete;

  // In place: x holds longitudes and becomes raster CRS x, y latitudes -> y. Points that fail to
  // transform become NaN.
  void transform(std::span<double> x, std::span<double> y);

 private:
  struct Deleter {
    void operator()(OGRCoordinateTransformation* transformation) const;
  };
  using Transformation = std::unique_ptr<OGRCoordinateTransformation, Deleter>;
  Transformation borrow();
  void give_back(Transformation transformation);

  bool identity_ = false;
  Transformation prototype_;  // never used directly: cloned for each concurrent caller
  std::mutex mutex_;
  std::vector<Transformation> idle_;
};

}  // namespace trailray::terrain::gdal_detail
