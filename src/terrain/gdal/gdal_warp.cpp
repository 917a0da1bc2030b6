#include "terrain/gdal/gdal_warp.hpp"

#include <gdal_alg.h>
#include <gdalwarper.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <array>
#include <limits>
#include <memory>

#include "terrain/gdal/gdal_errors.hpp"

namespace trailray::terrain::gdal_detail {
namespace {

// The approximating transformer interpolates linearly between exactly transformed points as long as
// that stays within this many source pixels. GDAL's default (1/8 pixel) shifts a 25 m DEM by up to
// 3 m, a visible step in steep terrain; 1/100 costs a few more exact transformations per row.
constexpr double kMaxTransformErrorPx = 0.01;

const std::string& web_mercator_wkt() {
  static const std::string wkt = [] {
    OGRSpatialReference mercator;
    mercator.importFromEPSG(3857);
    char* text = nullptr;
    mercator.exportToWkt(&text);
    std::string result = text != nullptr ? text : "";
    CPLFree(text);
    return result;
  }();
  return wkt;
}

// GDAL progress callback: returning FALSE makes the warper stop with CPLE_UserInterrupt.
int CPL_STDCALL continue_unless_stopped(double /*done*/, const char* /*message*/, void* stop_token) {
  return static_cast<const StopToken*>(stop_token)->stop_requested() ? FALSE : TRUE;
}

struct WarpOptionsDeleter {
  void operator()(GDALWarpOptions* options) const { GDALDestroyWarpOptions(options); }
};
struct TransformerDeleter {
  void operator()(void* transformer) const { GDALDestroyTransformer(transformer); }
};
struct WarpOperationDeleter {
  void operator()(void* operation) const { GDALDestroyWarpOperation(static_cast<GDALWarpOperationH>(operation)); }
};

int* new_band_list(const std::vector<int>& bands) {
  auto* list = static_cast<int*>(CPLMalloc(sizeof(int) * bands.size()));
  std::copy(bands.begin(), bands.end(), list);
  return list;
}

// An in-memory EPSG:3857 dataset covering the tile; nullptr (GDAL has said why) on failure.
GDALDatasetUniquePtr create_tile_dataset(const TileId& tile, const WarpSpec& spec, int band_count) {
  GDALDriver* memory = GetGDALDriverManager()->GetDriverByName("MEM");
  if (memory == nullptr) return nullptr;
  const int size = static_cast<int>(spec.tile_size);
  GDALDatasetUniquePtr dataset(memory->Create("", size, size, band_count, spec.data_type, nullptr));
  if (!dataset) return nullptr;
  const std::optional<geo::MercatorBounds> bounds = geo::tile_bounds_mercator(tile);
  if (!bounds) return nullptr;
  // Area convention, as the tile's pixel_is_area layout: (0, 0) is the tile's north-west corner.
  const double cell_width = (bounds->max_x - bounds->min_x) / size;
  const double cell_height = (bounds->max_y - bounds->min_y) / size;
  std::array<double, 6> geotransform = {bounds->min_x, cell_width, 0.0, bounds->max_y, 0.0, -cell_height};
  if (dataset->SetGeoTransform(geotransform.data()) != CE_None) return nullptr;
  if (dataset->SetProjection(web_mercator_wkt().c_str()) != CE_None) return nullptr;
  return dataset;
}

}  // namespace

WarpOutput warp_tile(GDALDataset& source, const TileId& tile, const WarpSpec& spec, StopToken stop) {
  WarpOutput out;
  GdalErrorCapture errors;
  const int band_count = static_cast<int>(spec.source_bands.size());
  GDALDatasetUniquePtr destination = create_tile_dataset(tile, spec, band_count + (spec.destination_alpha ? 1 : 0));
  if (!destination) {
    out.error = "cannot create the in-memory tile: " + errors.message();
    return out;
  }

  // Only the geotransform: the same georeferencing sample_native uses, even where a file also
  // carries GCPs or RPCs.
  const char* const transformer_options[] = {"SRC_METHOD=GEOTRANSFORM", nullptr};
  void* exact =
      GDALCreateGenImgProjTransformer2(GDALDataset::ToHandle(&source), GDALDataset::ToHandle(destination.get()),
                                       const_cast<char**>(transformer_options));
  if (exact == nullptr) {
    out.error = "no transformation from the raster to Web Mercator: " + errors.message();
    return out;
  }
  std::unique_ptr<void, TransformerDeleter> transformer(
      GDALCreateApproxTransformer(GDALGenImgProjTransform, exact, kMaxTransformErrorPx));
  GDALApproxTransformerOwnsSubtransformer(transformer.get(), TRUE);

  std::unique_ptr<GDALWarpOptions, WarpOptionsDeleter> options(GDALCreateWarpOptions());
  options->hSrcDS = GDALDataset::ToHandle(&source);
  options->hDstDS = GDALDataset::ToHandle(destination.get());
  options->nBandCount = band_count;
  options->panSrcBands = new_band_list(spec.source_bands);
  std::vector<int> destination_bands(spec.source_bands.size());
  for (int i = 0; i < band_count; ++i) destination_bands[static_cast<std::size_t>(i)] = i + 1;
  options->panDstBands = new_band_list(destination_bands);
  options->eResampleAlg = spec.resampling == GdalResampling::cubic ? GRA_Cubic
                          : spec.resampling == GdalResampling::max ? GRA_Max
                                                                   : GRA_Bilinear;
  options->eWorkingDataType = spec.data_type;
  // With a nodata value the warper builds a validity mask and leaves invalid pixels out of the
  // kernel (renormalising its weights): nodata is never blended into the result.
  if (spec.source_nodata) GDALWarpInitSrcNoDataReal(options.get(), *spec.source_nodata);
  if (band_count > 1 && spec.source_nodata)
    options->papszWarpOptions = CSLSetNameValue(options->papszWarpOptions, "UNIFIED_SRC_NODATA", "YES");
  options->nSrcAlphaBand = spec.source_alpha_band;
  if (spec.destination_alpha) {
    options->nDstAlphaBand = band_count + 1;
    options->papszWarpOptions = CSLSetNameValue(options->papszWarpOptions, "INIT_DEST", "0");
  } else {
    GDALWarpInitDstNoDataReal(options.get(), std::numeric_limits<double>::quiet_NaN());
    options->papszWarpOptions = CSLSetNameValue(options->papszWarpOptions, "INIT_DEST", "NO_DATA");
  }
  options->pfnProgress = continue_unless_stopped;
  options->pProgressArg = &stop;
  options->pfnTransformer = GDALApproxTransform;
  options->pTransformerArg = transformer.get();

  std::unique_ptr<void, WarpOperationDeleter> operation(GDALCreateWarpOperation(options.get()));
  if (!operation) {
    out.error = "cannot set up the warp: " + errors.message();
    return out;
  }
  const int size = static_cast<int>(spec.tile_size);
  const CPLErr result = GDALChunkAndWarpImage(static_cast<GDALWarpOperationH>(operation.get()), 0, 0, size, size);
  if (stop.stop_requested()) {
    out.status = WarpStatus::cancelled;
    return out;
  }
  if (result != CE_None) {
    out.error = "warp failed: " + errors.message();
    return out;
  }
  out.status = WarpStatus::ok;
  out.tile = std::move(destination);
  return out;
}

}  // namespace trailray::terrain::gdal_detail
