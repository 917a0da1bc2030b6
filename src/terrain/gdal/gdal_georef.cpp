#include "terrain/gdal/gdal_georef.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "geo/geodesic.hpp"
#include "geo/web_mercator.hpp"
#include "terrain/gdal/gdal_errors.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain::gdal_detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Points per edge when transforming the extent: a projected raster's straight edges are curves in
// WGS84, and the corners alone can miss their outermost point.
constexpr int kEdgeDensifyPoints = 21;

OGRSpatialReference wgs84_lon_lat() {
  OGRSpatialReference wgs84;
  wgs84.importFromEPSG(4326);
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  return wgs84;
}

OGRCoordinateTransformation* create_transformation(const OGRSpatialReference& from, const OGRSpatialReference& to) {
  return OGRCreateCoordinateTransformation(&from, &to);
}

void apply(const std::array<double, 6>& gt, double px, double py, double& x, double& y) {
  x = gt[0] + px * gt[1] + py * gt[2];
  y = gt[3] + px * gt[4] + py * gt[5];
}

std::optional<geo::LatLonBounds> extent_in_wgs84(const RasterGeoref& georef) {
  double min_x = std::numeric_limits<double>::infinity(), min_y = min_x;
  double max_x = -min_x, max_y = -min_x;
  const std::array<std::pair<int, int>, 4> corners = {
      {{0, 0}, {georef.width, 0}, {0, georef.height}, {georef.width, georef.height}}};
  for (const auto& [px, py] : corners) {
    double x = 0.0, y = 0.0;
    apply(georef.pixel_to_crs, px, py, x, y);
    min_x = std::min(min_x, x);
    max_x = std::max(max_x, x);
    min_y = std::min(min_y, y);
    max_y = std::max(max_y, y);
  }
  geo::LatLonBounds bounds;
  if (georef.crs_is_wgs84) {
    bounds.add(std::max(min_y, -90.0), min_x);
    bounds.add(std::min(max_y, 90.0), max_x);
    return bounds;
  }
  const OGRSpatialReference wgs84 = wgs84_lon_lat();
  std::unique_ptr<OGRCoordinateTransformation> to_wgs84(create_transformation(georef.crs, wgs84));
  if (!to_wgs84) return std::nullopt;
  double min_lon = 0.0, min_lat = 0.0, max_lon = 0.0, max_lat = 0.0;
  if (!to_wgs84->TransformBounds(min_x, min_y, max_x, max_y, &min_lon, &min_lat, &max_lon, &max_lat,
                                 kEdgeDensifyPoints))
    return std::nullopt;
  if (!std::isfinite(min_lon) || !std::isfinite(max_lon) || !std::isfinite(min_lat) || !std::isfinite(max_lat))
    return std::nullopt;
  if (min_lon > max_lon) {  // across the antimeridian: LatLonBounds has no way to say so
    min_lon = -180.0;
    max_lon = 180.0;
  }
  bounds.add(min_lat, min_lon);
  bounds.add(max_lat, max_lon);
  return bounds;
}

// The ground size of the pixel at the raster's centre: the geometric mean of the distances to
// its right and lower neighbours' corners.
std::optional<double> centre_pixel_ground_size_m(const RasterGeoref& georef, double& centre_lat) {
  const double cx = georef.width / 2.0, cy = georef.height / 2.0;
  std::array<double, 3> x{}, y{};
  apply(georef.pixel_to_crs, cx, cy, x[0], y[0]);
  apply(georef.pixel_to_crs, cx + 1.0, cy, x[1], y[1]);
  apply(georef.pixel_to_crs, cx, cy + 1.0, x[2], y[2]);
  if (!georef.crs_is_wgs84) {
    const OGRSpatialReference wgs84 = wgs84_lon_lat();
    std::unique_ptr<OGRCoordinateTransformation> to_wgs84(create_transformation(georef.crs, wgs84));
    std::array<int, 3> ok{};
    if (!to_wgs84 || !to_wgs84->Transform(3, x.data(), y.data(), nullptr, ok.data())) return std::nullopt;
    if (!ok[0] || !ok[1] || !ok[2]) return std::nullopt;
  }
  centre_lat = y[0];
  const double width_m = geo::geodesic_distance_m(y[0], x[0], y[1], x[1]);
  const double height_m = geo::geodesic_distance_m(y[0], x[0], y[2], x[2]);
  const double size = std::sqrt(width_m * height_m);
  if (!std::isfinite(size) || size <= 0.0) return std::nullopt;
  return size;
}

}  // namespace

RasterGeoref read_georef(GDALDataset& dataset, const std::string& path) {
  GdalErrorCapture errors;
  RasterGeoref georef;
  if (dataset.GetRasterCount() < 1) throw SourceError(path + ": the raster has no band");
  georef.driver = dataset.GetDriver() != nullptr ? dataset.GetDriver()->GetDescription() : "unknown";
  georef.width = dataset.GetRasterXSize();
  georef.height = dataset.GetRasterYSize();
  if (georef.width < 1 || georef.height < 1) throw SourceError(path + ": the raster is empty");
  if (dataset.GetGeoTransform(georef.pixel_to_crs.data()) != CE_None)
    throw SourceError(path + ": the raster has no geotransform (not georeferenced, or by GCPs only)");
  if (!GDALInvGeoTransform(georef.pixel_to_crs.data(), georef.crs_to_pixel.data()))
    throw SourceError(path + ": the raster's geotransform cannot be inverted");
  const OGRSpatialReference* crs = dataset.GetSpatialRef();
  if (crs == nullptr || crs->IsEmpty()) throw SourceError(path + ": the raster has no coordinate reference system");
  georef.crs = *crs;
  georef.crs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  const OGRSpatialReference wgs84 = wgs84_lon_lat();
  const char* const same_options[] = {"IGNORE_DATA_AXIS_TO_SRS_AXIS_MAPPING=YES", "CRITERION=EQUIVALENT", nullptr};
  georef.crs_is_wgs84 = georef.crs.IsSame(&wgs84, same_options);
  georef.bounds_wgs84 = extent_in_wgs84(georef);
  double centre_lat = 0.0;
  georef.pixel_ground_size_m = centre_pixel_ground_size_m(georef, centre_lat);
  if (georef.pixel_ground_size_m)
    georef.native_zoom = zoom_for_ground_resolution(*georef.pixel_ground_size_m, centre_lat);
  return georef;
}

int zoom_for_ground_resolution(double pixel_size_m, double lat_deg) {
  // A zoom-z tile pixel spans 2 pi R cos(lat) / (256 * 2^z) metres of ground at latitude lat.
  const double equator_m = 2.0 * geo::kMercatorHalfExtentM;
  const double cos_lat =
      std::cos(std::clamp(lat_deg, -geo::kMercatorMaxLatDeg, geo::kMercatorMaxLatDeg) * std::numbers::pi / 180.0);
  const double zoom = std::log2(equator_m * cos_lat / (256.0 * pixel_size_m));
  if (!std::isfinite(zoom)) return 0;
  return static_cast<int>(std::clamp(std::round(zoom), 0.0, 24.0));
}

void LonLatToRaster::Deleter::operator()(OGRCoordinateTransformation* transformation) const {
  OGRCoordinateTransformation::DestroyCT(transformation);
}

LonLatToRaster::LonLatToRaster(const RasterGeoref& georef, const std::string& path) : identity_(georef.crs_is_wgs84) {
  if (identity_) return;
  GdalErrorCapture errors;
  const OGRSpatialReference wgs84 = wgs84_lon_lat();
  prototype_.reset(create_transformation(wgs84, georef.crs));
  if (!prototype_) throw SourceError(path + ": no transformation from WGS84 to the raster's CRS: " + errors.message());
}

LonLatToRaster::~LonLatToRaster() = default;

LonLatToRaster::Transformation LonLatToRaster::borrow() {
  {
    std::lock_guard lock(mutex_);
    if (!idle_.empty()) {
      Transformation transformation = std::move(idle_.back());
      idle_.pop_back();
      return transformation;
    }
  }
  return Transformation(prototype_->Clone());
}

void LonLatToRaster::give_back(Transformation transformation) {
  if (!transformation) return;
  std::lock_guard lock(mutex_);
  idle_.push_back(std::move(transformation));
}

void LonLatToRaster::transform(std::span<double> x, std::span<double> y) {
  if (identity_ || x.empty()) return;
  GdalErrorCapture errors;
  Transformation transformation = borrow();
  std::vector<int> ok(x.size(), 0);
  // OGR counts points in int; its per-point flags say which failed (the return value only
  // whether all succeeded, depending on the version).
  constexpr std::size_t kChunk = std::size_t{1} << 30;
  for (std::size_t first = 0; transformation && first < x.size(); first += kChunk) {
    const int count = static_cast<int>(std::min(kChunk, x.size() - first));
    transformation->Transform(count, x.data() + first, y.data() + first, nullptr, ok.data() + first);
  }
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!ok[i]) x[i] = y[i] = kNaN;
  }
  give_back(std::move(transformation));
}

}  // namespace trailray::terrain::gdal_detail
