#pragma once
// Band 1 of a raster as heights for point queries (GdalHeightSource::sample_native): pixels are
// read on demand in blocks and kept, and heights are interpolated from the four nearest pixel
// centres. Internal to the terrain library.

#include <cstddef>
#include <cstdint>
#include <list>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "terrain/gdal/gdal_dataset_pool.hpp"

namespace trailray::terrain::gdal_detail {

// How band 1's raw values become metres.
struct HeightBandValues {
  std::optional<double> nodata;  // raw values equal to this are missing (NaN ones always are)
  double scale = 1.0, offset = 0.0;
};

// Reads a band's description (nodata, scale, offset).
HeightBandValues read_height_band_values(GDALRasterBand& band);

class NativeHeightGrid {
 public:
  // Side of the square blocks the raster is read in, unless the whole raster fits the budget
  // (then it is one block, read once).
  static constexpr int kBlockSize = 256;

  // `read_whole`: false reads by blocks even a raster that fits the budget.
  NativeHeightGrid(DatasetPool& pool, int width, int height, HeightBandValues values, std::size_t budget_bytes,
                   bool read_whole = true);

  // Heights at continuous pixel coordinates (px, py), (0, 0) being the outer corner of the first
  // pixel, by the rule documented at GdalHeightSource::sample_native (steps 2 to 5). The three
  // spans have the same length. Thread-safe.
  void sample(std::span<const double> px, std::span<const double> py, std::span<double> heights);

  // The last failure to read pixels (those pixels counted as missing); empty when none.
  std::string read_error() const;

 private:
  struct Block {
    int x0 = 0, y0 = 0, width = 0, height = 0;
    std::vector<float> heights;  // metres, NaN where missing; row-major
  };
  // The block a sample is reading from, kept between samples: consecutive track points almost
  // always fall in the same block, so the cache's lock is taken about once per block change.
  struct Cursor {
    std::int64_t key = -1;
    std::shared_ptr<const Block> block;
  };

  float pixel(int col, int row, Cursor& cursor);
  std::shared_ptr<const Block> block(int block_col, int block_row);  // nullptr when it cannot be read
  std::shared_ptr<const Block> read_block(int block_col, int block_row);
  double sample_one(double px, double py, Cursor& cursor);

  DatasetPool& pool_;
  const int width_, height_;
  const HeightBandValues values_;
  int block_width_ = kBlockSize, block_height_ = kBlockSize, blocks_across_ = 1;
  std::size_t max_blocks_ = 1;

  mutable std::mutex mutex_;
  std::list<std::int64_t> recency_;  // most recently used first
  struct Entry {
    std::shared_ptr<const Block> block;
    std::list<std::int64_t>::iterator position;
  };
  std::unordered_map<std::int64_t, Entry> blocks_;
  std::string read_error_;
};

}  // namespace trailray::terrain::gdal_detail
