// GDAL raster sources on the real DEMs of shared/data:
//   - warped height tiles per second (the tile cache off, so every load warps): the Interlaken
//     DEM in LV95 (a real reprojection) and in WGS84, bilinear and cubic, zooms 12 to 14 over
//     the raster, cycled;
//   - native samples per second: 100,000 points spread over the raster, as one batch
//     (sample_native(span)) and one call per point, on the LV95 and WGS84 rasters.
// Run: build/bench/terrain_gdal_bench --benchmark_repetitions=9 --benchmark_report_aggregates_only=true
// Skips (state.SkipWithError) when shared/data is absent.

#include <benchmark/benchmark.h>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "terrain/gdal/gdal_raster.hpp"

namespace {

using namespace trailray::terrain;
using trailray::geo::LatLon;

const std::string kLv95 = std::string(TRAILRAY_SHARED_DATA) + "/dem/interlaken_dhm25_25m_lv95.tif";
const std::string kWgs84 = std::string(TRAILRAY_SHARED_DATA) + "/dem/interlaken_dhm25_wgs84.tif";

// The tiles of zooms 12..14 over the Interlaken raster (7.814..7.929 E, 46.680..46.735 N).
std::vector<TileId> interlaken_tiles() {
  std::vector<TileId> ids;
  for (int zoom = 12; zoom <= 14; ++zoom) {
    const TileId nw = *trailray::geo::tile_containing(46.7347, 7.8142, zoom);
    const TileId se = *trailray::geo::tile_containing(46.6803, 7.9291, zoom);
    for (std::uint32_t y = nw.y; y <= se.y; ++y)
      for (std::uint32_t x = nw.x; x <= se.x; ++x) ids.push_back(TileId{zoom, x, y});
  }
  return ids;
}

std::vector<LatLon> interlaken_points(std::size_t n) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> lat(46.6810, 46.7340), lon(7.8150, 7.9280);
  std::vector<LatLon> points(n);
  for (LatLon& p : points) p = {lat(rng), lon(rng)};
  return points;
}

void warp_tiles(benchmark::State& state, const std::string& path, GdalResampling resampling) {
  if (!std::filesystem::exists(path)) {
    state.SkipWithError(("shared data absent: " + path).c_str());
    return;
  }
  GdalOptions options;
  options.tile_cache_bytes = 0;
  options.resampling = resampling;
  GdalHeightSource source(path, options);
  const std::vector<TileId> ids = interlaken_tiles();
  std::size_t next = 0;
  for (auto _ : state) {
    TileResult<HeightTile> r = source.load(ids[next++ % ids.size()], {});
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations());
}

void sample_batch(benchmark::State& state, const std::string& path) {
  if (!std::filesystem::exists(path)) {
    state.SkipWithError(("shared data absent: " + path).c_str());
    return;
  }
  GdalHeightSource source(path);
  const std::vector<LatLon> points = interlaken_points(100000);
  std::vector<double> heights(points.size());
  source.sample_native(points, heights);  // the raster's pixels are read once, outside the timing
  for (auto _ : state) {
    source.sample_native(points, heights);
    benchmark::DoNotOptimize(heights.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points.size()));
}

void sample_one_by_one(benchmark::State& state, const std::string& path) {
  if (!std::filesystem::exists(path)) {
    state.SkipWithError(("shared data absent: " + path).c_str());
    return;
  }
  GdalHeightSource source(path);
  const std::vector<LatLon> points = interlaken_points(100000);
  (void)source.sample_native(points[0].lat, points[0].lon);
  for (auto _ : state) {
    double sum = 0.0;
    for (const LatLon& p : points) sum += *source.sample_native(p.lat, p.lon);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points.size()));
}

void BM_GdalWarpTileLv95Bilinear(benchmark::State& state) { warp_tiles(state, kLv95, GdalResampling::bilinear); }
void BM_GdalWarpTileLv95Cubic(benchmark::State& state) { warp_tiles(state, kLv95, GdalResampling::cubic); }
void BM_GdalWarpTileWgs84Bilinear(benchmark::State& state) { warp_tiles(state, kWgs84, GdalResampling::bilinear); }
void BM_GdalSampleNativeBatchLv95(benchmark::State& state) { sample_batch(state, kLv95); }
void BM_GdalSampleNativeBatchWgs84(benchmark::State& state) { sample_batch(state, kWgs84); }
void BM_GdalSampleNativeEachLv95(benchmark::State& state) { sample_one_by_one(state, kLv95); }
void BM_GdalSampleNativeEachWgs84(benchmark::State& state) { sample_one_by_one(state, kWgs84); }

BENCHMARK(BM_GdalWarpTileLv95Bilinear)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GdalWarpTileLv95Cubic)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GdalWarpTileWgs84Bilinear)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GdalSampleNativeBatchLv95)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GdalSampleNativeBatchWgs84)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GdalSampleNativeEachLv95)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GdalSampleNativeEachWgs84)->Unit(benchmark::kMillisecond);

}  // namespace
