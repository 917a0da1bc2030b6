#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>

#include "terrain/gdal/gdal_errors.hpp"
#include "terrain/codecs/height_decode.hpp"
#include "terrain/codecs/height_tiff.hpp"

namespace trailray::terrain::detail {
namespace {

// ---------------------------------------------------------------------------------------------
// Float TIFF tiles, through GDAL's in-memory files. Each decode gets its own /vsimem name (a
// process-wide counter), and GdalErrorCapture is per thread, so decodes may run on any number of
// threads at once.

std::string unique_vsimem_name() {
  static std::atomic<std::uint64_t> counter{0};
  return "/vsimem/trailray-height-tile-" + std::to_string(counter.fetch_add(1)) + ".tif";
}

// A copy of the bytes as a GDAL in-memory file (GDAL wants a writable buffer; ours is const).
class VsimemFile {
 public:
  explicit VsimemFile(std::span<const unsigned char> bytes)
      : data_(bytes.begin(), bytes.end()), name_(unique_vsimem_name()) {
    VSILFILE* f = VSIFileFromMemBuffer(name_.c_str(), data_.data(), data_.size(), FALSE);
    if (!f) throw TileDecodeError("cannot create the in-memory file " + name_);
    VSIFCloseL(f);
  }
  ~VsimemFile() { VSIUnlink(name_.c_str()); }
  VsimemFile(const VsimemFile&) = delete;
  VsimemFile& operator=(const VsimemFile&) = delete;
  const std::string& name() const { return name_; }

 private:
  std::vector<GByte> data_;
  std::string name_;
};

struct GdalDatasetCloser {
  void operator()(void* dataset) const { GDALClose(dataset); }
};
using GdalDataset = std::unique_ptr<void, GdalDatasetCloser>;

}  // namespace

HeightTile decode_float_tiff(std::span<const unsigned char> bytes, const TileId& id) {
  gdal_detail::ensure_gdal_registered();
  gdal_detail::GdalErrorCapture errors;
  VsimemFile file(bytes);
  // Only the TIFF driver: these bytes come from a tile server, not a trusted file of any format.
  static const char* const kDrivers[] = {"GTiff", nullptr};
  GdalDataset dataset(GDALOpenEx(file.name().c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, kDrivers, nullptr, nullptr));
  if (!dataset) throw TileDecodeError("corrupt TIFF: " + errors.message());
  const int bands = GDALGetRasterCount(dataset.get());
  if (bands != 1) throw TileDecodeError("a float height tile has one band; this TIFF has " + std::to_string(bands));
  const int width = GDALGetRasterXSize(dataset.get()), height = GDALGetRasterYSize(dataset.get());
  if (width <= 0 || height <= 0) throw TileDecodeError("corrupt TIFF: no pixels");
  check_tile_size(static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height));

  HeightTile tile;
  tile.id = id;
  tile.width = tile.height = static_cast<std::uint32_t>(width);
  tile.layout = layout_for_size(tile.width);
  tile.heights.resize(std::size_t{tile.width} * tile.height);
  GDALRasterBandH band = GDALGetRasterBand(dataset.get(), 1);
  if (GDALRasterIO(band, GF_Read, 0, 0, width, height, tile.heights.data(), width, height, GDT_Float32, 0, 0) !=
      CE_None)
    throw TileDecodeError("corrupt TIFF: " + errors.message());
  int has_nodata = 0;
  const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
  // A nodata value beyond float's range (a Float64 band's -1e300) cannot appear in the floats.
  if (has_nodata && std::isfinite(nodata) && std::abs(nodata) <= std::numeric_limits<float>::max()) {
    const float nodata_f = static_cast<float>(nodata);
    std::replace(tile.heights.begin(), tile.heights.end(), nodata_f, kNoHeight);
  }
  std::replace_if(
      tile.heights.begin(), tile.heights.end(), [](float h) { return std::isinf(h); }, kNoHeight);
  return tile;
}

std::vector<unsigned char> encode_float_tiff(const HeightTile& tile) {
  gdal_detail::ensure_gdal_registered();
  gdal_detail::GdalErrorCapture errors;
  GDALDriverH driver = GDALGetDriverByName("GTiff");
  if (!driver) throw TileDecodeError("GDAL has no GTiff driver");
  const std::string name = unique_vsimem_name();
  {
    GdalDataset dataset(GDALCreate(driver, name.c_str(), static_cast<int>(tile.width), static_cast<int>(tile.height), 1,
                                   GDT_Float32, nullptr));
    if (!dataset) throw TileDecodeError("cannot create a TIFF: " + errors.message());
    std::vector<float> heights = tile.heights;  // GDALRasterIO takes a non-const buffer for writing too
    if (GDALRasterIO(GDALGetRasterBand(dataset.get(), 1), GF_Write, 0, 0, static_cast<int>(tile.width),
                     static_cast<int>(tile.height), heights.data(), static_cast<int>(tile.width),
                     static_cast<int>(tile.height), GDT_Float32, 0, 0) != CE_None) {
      dataset.reset();
      VSIUnlink(name.c_str());
      throw TileDecodeError("cannot write a TIFF: " + errors.message());
    }
  }  // closing the dataset writes the file
  vsi_l_offset length = 0;
  GByte* buffer = VSIGetMemFileBuffer(name.c_str(), &length, TRUE);  // TRUE: we own it, the file is gone
  if (!buffer) throw TileDecodeError("cannot write a TIFF: no in-memory file " + name);
  std::vector<unsigned char> out(buffer, buffer + length);
  CPLFree(buffer);
  return out;
}

}  // namespace trailray::terrain::detail
