// Level-of-detail selection time for one frame (target: under 1 ms), 1920 x 1080, 60 degrees
// vertical field of view, 2 px screen error, the default budgets (600 tiles):
//   - an oblique mountain view: above Interlaken (46.68 N, 7.86 E) at 3000 m looking at the
//     Eiger (46.577 N, 8.005 E, 3967 m), heights unknown (default range) or known (a constant
//     range standing in for loaded tiles);
//   - a top-down view from 5000 m over the same place.
// The `tiles` counter is the number of selected tiles.
// Run: build/bench/terrain_lod_bench --benchmark_repetitions=9 --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <numbers>
#include <optional>
#include <utility>

#include "terrain/lod/lod_selection.hpp"

namespace {

using namespace trailray::terrain;

constexpr double kDeg = std::numbers::pi / 180.0;

LodCamera mountain_view() { return look_at(46.68, 7.86, 3000.0, 46.577, 8.005, 3967.0, 60.0 * kDeg, 1920, 1080); }
LodCamera top_down_view() { return look_at(46.68, 7.86, 5000.0, 46.68, 7.86, 0.0, 60.0 * kDeg, 1920, 1080); }

HeightRange bernese_oberland_heights() {
  return [](const TileId&) { return std::optional<std::pair<float, float>>({500.0f, 4200.0f}); };
}

void run(benchmark::State& state, const LodCamera& camera, const HeightRange& heights) {
  const LodSettings settings;
  std::size_t tiles = 0;
  bool limited = false;
  for (auto _ : state) {
    LodSelection s = select_tiles(camera, settings, heights);
    tiles = s.tiles.size();
    limited = s.budget_limited;
    benchmark::DoNotOptimize(s);
  }
  state.counters["tiles"] = static_cast<double>(tiles);
  state.counters["budget_limited"] = limited ? 1.0 : 0.0;
}

void BM_LodMountainViewDefaultHeights(benchmark::State& state) { run(state, mountain_view(), {}); }
void BM_LodMountainViewKnownHeights(benchmark::State& state) {
  run(state, mountain_view(), bernese_oberland_heights());
}
void BM_LodTopDownDefaultHeights(benchmark::State& state) { run(state, top_down_view(), {}); }
void BM_LodTopDownKnownHeights(benchmark::State& state) { run(state, top_down_view(), bernese_oberland_heights()); }

BENCHMARK(BM_LodMountainViewDefaultHeights)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LodMountainViewKnownHeights)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LodTopDownDefaultHeights)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LodTopDownKnownHeights)->Unit(benchmark::kMicrosecond);

}  // namespace
