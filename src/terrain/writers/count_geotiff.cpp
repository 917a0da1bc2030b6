#include "terrain/writers/count_geotiff.hpp"

#include <cpl_conv.h>
#include <cpl_string.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <atomic>
#include <memory>
#include <stdexcept>
#include <string>

#include "terrain/gdal/gdal_errors.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain {
namespace {

struct DatasetCloser {
  void operator()(void* dataset) const { GDALClose(dataset); }
};

std::string unique_name() {
  static std::atomic<std::uint64_t> counter{0};
  return "/vsimem/trailray-counts-" + std::to_string(counter.fetch_add(1)) + ".tif";
}

}  // namespace

std::vector<unsigned char> encode_count_geotiff(std::span<const std::uint32_t> counts, std::uint32_t width,
                                                std::uint32_t height, const std::array<double, 6>& geotransform,
                                                std::string_view what) {
  if (counts.size() != std::size_t{width} * height || width == 0 || height == 0)
    throw std::runtime_error("a count raster of " + std::to_string(width) + "x" + std::to_string(height) +
                             " cells with " + std::to_string(counts.size()) + " counts");
  gdal_detail::ensure_gdal_registered();
  gdal_detail::GdalErrorCapture errors;
  GDALDriverH driver = GDALGetDriverByName("GTiff");
  if (!driver) throw std::runtime_error("GDAL has no GTiff driver");
  const std::string name = unique_name();
  char** options = nullptr;
  options = CSLSetNameValue(options, "COMPRESS", "DEFLATE");
  options = CSLSetNameValue(options, "TILED", "YES");
  options = CSLSetNameValue(options, "BIGTIFF", "IF_SAFER");
  {
    std::unique_ptr<void, DatasetCloser> dataset(GDALCreate(driver, name.c_str(), static_cast<int>(width),
                                                            static_cast<int>(height), 1, GDT_UInt32, options));
    CSLDestroy(options);
    if (!dataset) throw std::runtime_error("cannot create a GeoTIFF: " + errors.message());
    std::array<double, 6> transform = geotransform;
    OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
    OSRImportFromEPSG(srs, 3857);
    char* wkt = nullptr;
    OSRExportToWkt(srs, &wkt);
    const bool placed = GDALSetGeoTransform(dataset.get(), transform.data()) == CE_None &&
                        GDALSetProjection(dataset.get(), wkt) == CE_None;
    CPLFree(wkt);
    OSRDestroySpatialReference(srs);
    std::vector<std::uint32_t> rows(counts.begin(), counts.end());  // GDALRasterIO wants a non-const buffer
    GDALRasterBandH band = GDALGetRasterBand(dataset.get(), 1);
    GDALSetDescription(band, std::string(what).c_str());
    if (!placed || GDALRasterIO(band, GF_Write, 0, 0, static_cast<int>(width), static_cast<int>(height), rows.data(),
                                static_cast<int>(width), static_cast<int>(height), GDT_UInt32, 0, 0) != CE_None) {
      dataset.reset();
      VSIUnlink(name.c_str());
      throw std::runtime_error("cannot write a GeoTIFF: " + errors.message());
    }
  }  // closing the dataset writes the file
  vsi_l_offset length = 0;
  GByte* buffer = VSIGetMemFileBuffer(name.c_str(), &length, TRUE);
  if (!buffer) throw std::runtime_error("cannot write a GeoTIFF: no in-memory file " + name);
  std::vector<unsigned char> out(buffer, buffer + length);
  CPLFree(buffer);
  return out;
}

std::optional<CountRaster> describe_count_raster(const std::string& path) {
  gdal_detail::ensure_gdal_registered();
  gdal_detail::GdalErrorCapture errors;
  std::unique_ptr<void, DatasetCloser> dataset(GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr,
                                                          nullptr, nullptr));
  if (!dataset) throw SourceError(path + ": cannot open: " + errors.message());
  if (GDALGetRasterCount(dataset.get()) != 1) return std::nullopt;
  GDALRasterBandH band = GDALGetRasterBand(dataset.get(), 1);
  const GDALDataType type = GDALGetRasterDataType(band);
  if (type == GDT_Byte || GDALGetRasterColorInterpretation(band) == GCI_PaletteIndex) return std::nullopt;
  CountRaster out;
  double min_max[2] = {0.0, 0.0};
  if (GDALComputeRasterMinMax(band, FALSE, min_max) != CE_None)
    throw SourceError(path + ": cannot read its counts: " + errors.message());
  out.maximum = min_max[1];
  out.what = GDALGetDescription(band);
  std::array<double, 6> transform{};
  if (GDALGetGeoTransform(dataset.get(), transform.data()) == CE_None) out.cell_m = transform[1];
  return out;
}

}  // namespace trailray::terrain
