#pragma once
// A HeightSource computed from a formula, for tests of the code that consumes sources (loader,
// sampler, LOD): heights are a plane in the global sample grid of each level, which bilinear
// interpolation reproduces exactly, so any sampling error shows as a difference.

#include <atomic>
#include <chrono>
#include <functional>
#include <set>
#include <thread>

#include "terrain/sources/tile_source.hpp"

namespace trailray::test {

class SyntheticHeightSource : public terrain::HeightSource {
 public:
  SyntheticHeightSource(std::uint32_t width, terrain::SampleLayout layout, int max_zoom = 12)
      : width_(width), layout_(layout) {
    info_.name = "synthetic";
    info_.min_zoom = 0;
    info_.max_zoom = max_zoom;
  }

  // Height of global sample (col, row) at a zoom: 100 + 0.5 col' + 0.25 row', where col', row'
  // are in units of the finest level's samples, so all levels describe the same plane.
  double plane(double col, double row, int zoom) const {
    const double scale = static_cast<double>(std::uint64_t{1} << (info_.max_zoom - zoom));
    return 100.0 + 0.5e-3 * col * scale + 0.25e-3 * row * scale;
  }

  const terrain::SourceInfo& info() const override { return info_; }

  terrain::TileResult<terrain::HeightTile> load(const terrain::TileId& id, std::stop_token stop) override {
    ++loads;
    if (delay.count() > 0) {
      const auto until = std::chrono::steady_clock::now() + delay;
      while (std::chrono::steady_clock::now() < until) {
        if (stop.stop_requested()) {
          ++cancelled;
          return {terrain::TileStatus::cancelled, {}, {}};
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    }
    if (failing.contains(id.x)) return {terrain::TileStatus::failed, {}, "synthetic " + geo::to_string(id) + ": broken"};
    if (empty_at_zoom.contains(id.zoom)) return {terrain::TileStatus::no_data, {}, {}};
    terrain::HeightTile t;
    t.id = id;
    t.width = t.height = width_;
    t.layout = layout_;
    const std::uint64_t step = layout_ == terrain::SampleLayout::pixel_is_area ? width_ : width_ - 1;
    t.heights.resize(std::size_t{width_} * width_);
    for (std::uint32_t r = 0; r < width_; ++r)
      for (std::uint32_t c = 0; c < width_; ++c)
        t.heights[std::size_t{r} * width_ + c] =
            static_cast<float>(plane(static_cast<double>(id.x * step + c), static_cast<double>(id.y * step + r), id.zoom));
    if (hole) hole(t);
    terrain::update_height_range(t);
    return {terrain::TileStatus::ok, std::move(t), {}};
  }

  std::atomic<int> loads{0}, cancelled{0};
  std::chrono::milliseconds delay{0};
  std::set<std::uint32_t> failing;  // tile columns that fail
  std::set<int> empty_at_zoom;      // levels without data
  std::function<void(terrain::HeightTile&)> hole;

 private:
  std::uint32_t width_;
  terrain::SampleLayout layout_;
  terrain::SourceInfo info_;
};

}  // namespace trailray::test
