#pragma once
// Terrain height at any latitude/longitude, on the CPU.
//
// A source with its own grid (a GDAL raster: HeightSource::sample_native) is sampled there:
// bilinear between the four nearest raster cells, no Mercator resampling in between.
// A tile source is sampled on the finest level it has (its info().max_zoom, or a chosen zoom):
// bilinear between the four nearest samples of the tile pyramid's global grid, across tile
// seams (the neighbouring tile is loaded when a point lies within half a sample of an edge), so
// the result is the continuous bilinear surface through the source's samples. Where that level
// has no data (a hole, a 404, a failed tile) the point falls back to the parent levels.
//
// Error bound: the interpolation adds nothing beyond float rounding (under 1 mm for heights of
// a few thousand metres). What remains is the source's own error: its sample spacing (a
// 256-sample tile at zoom z is 40075 km * cos(lat) / 2^z / 256 apart: 3.3 m at zoom 15 and 47 N)
// against the terrain's curvature, and the encoding's quantisation (Terrarium 1/256 m, Mapbox
// terrain-RGB 0.1 m, AlpineMaps 1/8 m). Nodata neighbours are left out and the weights of the
// others renormalised, so a point next to a hole still gets a height; a point with four nodata
// neighbours has none (NaN).

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "geo/web_mercator.hpp"
#include "terrain/loading/tile_loader.hpp"
#include "terrain/tile_sampling.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain {

struct HeightSamplerOptions {
  int zoom = -1;                   // the level to sample; -1: the source's max_zoom
  unsigned threads = 4;            // tile loads in parallel (more for network sources)
  std::size_t tiles_per_batch = 96;  // bounds the decoded tiles held at once (256 KiB each)
};

struct SamplingReport {
  std::size_t points = 0, with_height = 0;
  std::size_t tiles_loaded = 0, tiles_no_data = 0, tiles_failed = 0;
  std::vector<std::string> errors;  // of the failed tiles ("<source> z/x/y: ...")
};

class HeightSampler {
 public:
  explicit HeightSampler(HeightSource& source, HeightSamplerOptions options = {});

  // Heights in metres (NaN where no level has data). on_progress is called while tiles load
  // (from this thread), with the progress of the current batch and the batch count.
  using ProgressFunction = std::function<void(const LoadProgress& batch, std::size_t batch_index, std::size_t batches)>;
  std::vector<double> sample(std::span<const geo::LatLon> points, const ProgressFunction& on_progress = {});

  double sample(double lat, double lon);

  const SamplingReport& report() const { return report_; }

 private:
  void sample_level(std::span<const geo::LatLon> points, std::vector<std::size_t>& todo, int zoom,
                    std::vector<double>& out, const ProgressFunction& on_progress);
  bool wait(TileLoader<HeightTile>& loader, const ProgressFunction& on_progress, std::size_t batch,
            std::size_t batches);

  HeightSource& source_;
  HeightSamplerOptions options_;
  SampleGrid grid_;  // of the level being sampled, from its first tile
  SamplingReport report_;
};

}  // namespace trailray::terrain
