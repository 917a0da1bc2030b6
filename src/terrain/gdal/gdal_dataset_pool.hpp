#pragma once
// Read-only handles on one raster file, one per concurrent caller. A GDALDataset is not
// thread-safe, but separate handles on the same file are independent: a caller borrows a handle
// for the duration of one read and hands it back; the pool keeps a few idle ones so that the
// steady state opens nothing. Internal to the terrain library.

#include <gdal_priv.h>

#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

namespace trailray::terrain::gdal_detail {

// Opens `path` read-only as a raster (GDAL_OF_RASTER | GDAL_OF_READONLY), with GDAL open options
// ("OVERVIEW_LEVEL=2": the dataset is then that overview); throws SourceError
// "<path>: cannot open as a raster: <GDAL's message>" when GDAL cannot.
GDALDatasetUniquePtr open_raster_read_only(const std::string& path, const std::vector<std::string>& open_options = {});

class DatasetPool {
 public:
  // Opens the first handle now, so that a file that cannot be opened fails here (SourceError).
  DatasetPool(std::string path, std::size_t max_idle, std::vector<std::string> open_options = {});
  ~DatasetPool();
  DatasetPool(const DatasetPool&) = delete;
  DatasetPool& operator=(const DatasetPool&) = delete;

  // A borrowed handle, returned to the pool when the lease ends.
  class Lease {
   public:
    Lease(DatasetPool& pool, GDALDatasetUniquePtr dataset) : pool_(&pool), dataset_(std::move(dataset)) {}
    Lease(Lease&&) noexcept = default;
    Lease& operator=(Lease&&) = delete;
    ~Lease() {
      if (dataset_) pool_->give_back(std::move(dataset_));
    }
    GDALDataset& operator*() const { return *dataset_; }
    GDALDataset* operator->() const { return dataset_.get(); }

   private:
    DatasetPool* pool_;
    GDALDatasetUniquePtr dataset_;
  };

  // An idle handle, or a newly opened one (SourceError if the file can no longer be opened).
  Lease acquire();
  const std::string& path() const { return path_; }

 private:
  void give_back(GDALDatasetUniquePtr dataset);

  const std::string path_;
  const std::size_t max_idle_;
  const std::vector<std::string> open_options_;
  std::mutex mutex_;
  std::vector<GDALDatasetUniquePtr> idle_;
};

}  // namespace trailray::terrain::gdal_detail
