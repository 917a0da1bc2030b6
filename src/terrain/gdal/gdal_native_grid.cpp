#include "terrain/gdal/gdal_native_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "terrain/gdal/gdal_errors.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain::gdal_detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Rows read per RasterIO call when filling a block: bounds the temporary double buffer.
constexpr std::size_t kReadChunkValues = std::size_t{1} << 20;

}  // namespace

HeightBandValues read_height_band_values(GDALRasterBand& band) {
  GdalErrorCapture errors;
  HeightBandValues values;
  int has = 0;
  const double nodata = band.GetNoDataValue(&has);
  if (has) values.nodata = nodata;
  has = 0;
  const double scale = band.GetScale(&has);
  if (has && std::isfinite(scale) && scale != 0.0) values.scale = scale;
  has = 0;
  const double offset = band.GetOffset(&has);
  if (has && std::isfinite(offset)) values.offset = offset;
  return values;
}

NativeHeightGrid::NativeHeightGrid(DatasetPool& pool, int width, int height, HeightBandValues values,
                                   std::size_t budget_bytes, bool read_whole)
    : pool_(pool), width_(width), height_(height), values_(values) {
  const std::size_t whole = std::size_t(width) * std::size_t(height) * sizeof(float);
  if (read_whole && whole <= budget_bytes) {
    block_width_ = width;
    block_height_ = height;
  }
  blocks_across_ = (width + block_width_ - 1) / block_width_;
  const std::size_t block_bytes = std::size_t(block_width_) * std::size_t(block_height_) * sizeof(float);
  max_blocks_ = std::max<std::size_t>(1, budget_bytes / block_bytes);
}

std::string NativeHeightGrid::read_error() const {
  std::lock_guard lock(mutex_);
  return read_error_;
}

std::shared_ptr<const NativeHeightGrid::Block> NativeHeightGrid::read_block(int block_col, int block_row) {
  auto block = std::make_shared<Block>();
  block->x0 = block_col * block_width_;
  block->y0 = block_row * block_height_;
  block->width = std::min(block_width_, width_ - block->x0);
  block->height = std::min(block_height_, height_ - block->y0);
  block->heights.resize(std::size_t(block->width) * std::size_t(block->height));

  std::optional<DatasetPool::Lease> dataset;
  try {
    dataset.emplace(pool_.acquire());
  } catch (const SourceError& e) {
    std::lock_guard lock(mutex_);
    read_error_ = e.what();
    return nullptr;
  }
  GdalErrorCapture errors;
  GDALRasterBand* band = (*dataset)->GetRasterBand(1);
  const int rows_per_read = static_cast<int>(std::max<std::size_t>(1, kReadChunkValues / std::size_t(block->width)));
  std::vector<double> raw;
  for (int row = 0; row < block->height; row += rows_per_read) {
    const int rows = std::min(rows_per_read, block->height - row);
    raw.resize(std::size_t(block->width) * std::size_t(rows));
    if (band == nullptr || band->RasterIO(GF_Read, block->x0, block->y0 + row, block->width, rows, raw.data(),
                                          block->width, rows, GDT_Float64, 0, 0, nullptr) != CE_None) {
      std::lock_guard lock(mutex_);
      read_error_ = pool_.path() + ": cannot read pixels " + std::to_string(block->x0) + "," +
                    std::to_string(block->y0 + row) + " (" + std::to_string(block->width) + "x" + std::to_string(rows) +
                    "): " + errors.message();
      return nullptr;
    }
    float* out = block->heights.data() + std::size_t(row) * std::size_t(block->width);
    for (double value : raw) {
      const bool missing = std::isnan(value) || (values_.nodata && value == *values_.nodata);
      *out++ = missing ? std::numeric_limits<float>::quiet_NaN()
                       : static_cast<float>(value * values_.scale + values_.offset);
    }
  }
  return block;
}

std::shared_ptr<const NativeHeightGrid::Block> NativeHeightGrid::block(int block_col, int block_row) {
  const std::int64_t key = std::int64_t(block_row) * blocks_across_ + block_col;
  {
    std::lock_guard lock(mutex_);
    if (auto found = blocks_.find(key); found != blocks_.end()) {
      recency_.splice(recency_.begin(), recency_, found->second.position);
      return found->second.block;
    }
  }
  // Read outside the lock: other threads keep sampling cached blocks meanwhile. Two threads
  // missing the same block both read it; the first one stored wins.
  std::shared_ptr<const Block> fresh = read_block(block_col, block_row);
  if (!fresh) return nullptr;
  std::lock_guard lock(mutex_);
  if (auto found = blocks_.find(key); found != blocks_.end()) return found->second.block;
  recency_.push_front(key);
  blocks_.emplace(key, Entry{fresh, recency_.begin()});
  while (blocks_.size() > max_blocks_) {
    blocks_.erase(recency_.back());
    recency_.pop_back();
  }
  return fresh;
}

float NativeHeightGrid::pixel(int col, int row, Cursor& cursor) {
  const int block_col = col / block_width_, block_row = row / block_height_;
  const std::int64_t key = std::int64_t(block_row) * blocks_across_ + block_col;
  if (key != cursor.key) {
    cursor.block = block(block_col, block_row);
    cursor.key = key;
  }
  if (!cursor.block) return std::numeric_limits<float>::quiet_NaN();
  const Block& b = *cursor.block;
  return b.heights[std::size_t(row - b.y0) * std::size_t(b.width) + std::size_t(col - b.x0)];
}

double NativeHeightGrid::sample_one(double px, double py, Cursor& cursor) {
  // Written as a negation so that NaN coordinates (failed transformations) fall out here too.
  if (!(px >= 0.0 && px <= width_ && py >= 0.0 && py <= height_)) return kNaN;
  const double u = px - 0.5, v = py - 0.5;
  const double u0 = std::floor(u), v0 = std::floor(v);
  const int col0 = static_cast<int>(u0), row0 = static_cast<int>(v0);
  const double fx = u - u0, fy = v - v0;
  const double weight_x[2] = {1.0 - fx, fx}, weight_y[2] = {1.0 - fy, fy};
  double sum = 0.0, weight_sum = 0.0;
  for (int dy = 0; dy < 2; ++dy) {
    const int row = row0 + dy;
    if (row < 0 || row >= height_) continue;
    for (int dx = 0; dx < 2; ++dx) {
      const int col = col0 + dx;
      if (col < 0 || col >= width_) continue;
      const float h = pixel(col, row, cursor);
      if (std::isnan(h)) continue;
      const double w = weight_x[dx] * weight_y[dy];
      sum += w * h;
      weight_sum += w;
    }
  }
  return weight_sum > 0.0 ? sum / weight_sum : kNaN;
}

void NativeHeightGrid::sample(std::span<const double> px, std::span<const double> py, std::span<double> heights) {
  Cursor cursor;
  for (std::size_t i = 0; i < heights.size(); ++i) heights[i] = sample_one(px[i], py[i], cursor);
}

}  // namespace trailray::terrain::gdal_detail
