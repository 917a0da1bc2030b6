#include "terrain/gdal/gdal_dataset_pool.hpp"

#include <algorithm>

#include "terrain/gdal/gdal_errors.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain::gdal_detail {

GDALDatasetUniquePtr open_raster_read_only(const std::string& path, const std::vector<std::string>& open_options) {
  ensure_gdal_registered();
  GdalErrorCapture errors;
  std::vector<const char*> options;
  for (const std::string& option : open_options) options.push_back(option.c_str());
  options.push_back(nullptr);
  GDALDatasetUniquePtr dataset(GDALDataset::Open(
      path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY | GDAL_OF_VERBOSE_ERROR, nullptr, options.data(), nullptr));
  if (!dataset) throw SourceError(path + ": cannot open as a raster: " + errors.message());
  return dataset;
}

DatasetPool::DatasetPool(std::string path, std::size_t max_idle, std::vector<std::string> open_options)
    : path_(std::move(path)), max_idle_(std::max<std::size_t>(max_idle, 1)), open_options_(std::move(open_options)) {
  idle_.push_back(open_raster_read_only(path_, open_options_));
}

DatasetPool::~DatasetPool() {
  // Closing flushes nothing (read-only), but GDAL may still have something to say about it.
  GdalErrorCapture errors;
  idle_.clear();
}

DatasetPool::Lease DatasetPool::acquire() {
  {
    std::lock_guard lock(mutex_);
    if (!idle_.empty()) {
      GDALDatasetUniquePtr dataset = std::move(idle_.back());
      idle_.pop_back();
      return Lease(*this, std::move(dataset));
    }
  }
  // Opened outside the lock: other callers keep borrowing idle handles meanwhile.
  return Lease(*this, open_raster_read_only(path_, open_options_));
}

void DatasetPool::give_back(GDALDatasetUniquePtr dataset) {
  {
    std::lock_guard lock(mutex_);
    if (idle_.size() < max_idle_) {
      idle_.push_back(std::move(dataset));
      return;
    }
  }
  GdalErrorCapture errors;
  dataset.reset();
}

}  // namespace trailray::terrain::gdal_detail
