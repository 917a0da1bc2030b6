// Time until one view's terrain tiles are all present, through the whole path the renderer and
// `trailray elevation` use (source -> decode -> TileLoader's workers -> memory):
//   - the view: LOD selection for 1920 x 1080, 60 degrees, 2 px, above Interlaken at 3000 m
//     looking at the Eiger, zoom up to 15 (about 150 tiles of mixed levels);
//   - the tiles: Terrarium PNGs of a smooth synthetic mountain range, written once to a temp
//     folder, served as a {z}/{x}/{y} folder and by the local test server on 127.0.0.1;
//   - folder/cold: a new loader reads and decodes every tile; folder/warm: the loader already
//     holds them (memory cache); http/cold: empty disk cache (download, check, store);
//     http/warm: every tile in the disk cache, a new loader (no network).
// Run: build/bench/terrain_view_bench --benchmark_repetitions=9 --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "../tests/terrain/local_tile_server.hpp"
#include "../tests/terrain/tile_fixtures.hpp"
#include "terrain/sources/encoded_sources.hpp"
#include "terrain/lod/lod_selection.hpp"
#include "terrain/sources/source_factory.hpp"
#include "terrain/loading/tile_loader.hpp"

namespace {

using namespace trailray;
using namespace trailray::terrain;
using namespace std::chrono_literals;

constexpr double kDeg = std::numbers::pi / 180.0;

struct Fixture {
  test::TempDir dir;
  std::vector<TileRequest> view;
  std::filesystem::path folder;
  std::unique_ptr<test::http::LocalTileServer> server;

  Fixture() {
    const LodCamera camera = look_at(46.68, 7.86, 3000.0, 46.577, 8.005, 3967.0, 60.0 * kDeg, 1920, 1080);
    LodSettings settings;
    settings.max_zoom = 15;
    const LodSelection s = select_tiles(camera, settings);
    std::vector<TileId> ids;
    for (const auto& t : s.tiles) {
      view.push_back({t.id, t.priority});
      ids.push_back(t.id);
    }
    test::MemoryHeightSource heights;
    for (const auto& id : ids)
      heights.add(test::make_height_tile(id, 256, [&](std::uint32_t c, std::uint32_t r) {
        const auto p = geo::latlon_from_tile_pixel(id, c + 0.5, r + 0.5, 256);
        return static_cast<float>(1500.0 + 900.0 * std::sin(p->lat * 40.0) * std::cos(p->lon * 55.0) +
                                  60.0 * std::sin(p->lat * 900.0 + p->lon * 700.0));
      }));
    folder = dir.path() / "tiles";
    test::write_terrarium_folder(heights, ids, folder);
    server = std::make_unique<test::http::LocalTileServer>(folder);
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

SourceSettings settings_for(const std::string& source) {
  SourceSettings s;
  s.source = source;
  s.encoding = HeightEncoding::terrarium;
  s.max_zoom = 15;
  return s;
}

void load_view(TileLoader<HeightTile>& loader, benchmark::State& state) {
  loader.request(fixture().view);
  if (!loader.wait_until_done(600s) || loader.progress().loaded != fixture().view.size())
    state.SkipWithError("not every tile loaded");
}

TileLoader<HeightTile>::LoadFunction load_from(HeightSource& s) {
  return [&s](const TileId& id, std::stop_token stop) { return s.load(id, stop); };
}

void BM_ViewFromFolderCold(benchmark::State& state) {
  auto source = open_height_source(settings_for(fixture().folder.string()), {});
  for (auto _ : state) {
    TileLoader<HeightTile> loader(load_from(*source));
    load_view(loader, state);
  }
  state.counters["tiles"] = static_cast<double>(fixture().view.size());
}

void BM_ViewFromFolderWarm(benchmark::State& state) {
  auto source = open_height_source(settings_for(fixture().folder.string()), {});
  TileLoader<HeightTile> loader(load_from(*source));
  load_view(loader, state);
  for (auto _ : state) load_view(loader, state);
  state.counters["tiles"] = static_cast<double>(fixture().view.size());
}

void BM_ViewFromHttp(benchmark::State& state, bool warm) {
  test::TempDir cache;
  SourceContext context;
  context.cache.folder = cache.path();
  const auto settings = settings_for(fixture().server->url("/tiles/{z}/{x}/{y}.png"));
  if (warm) {
    auto source = open_height_source(settings, context);
    TileLoader<HeightTile> loader(load_from(*source));
    load_view(loader, state);
  }
  for (auto _ : state) {
    state.PauseTiming();
    if (!warm) {
      std::filesystem::remove_all(cache.path() / "cache");
      std::filesystem::remove_all(cache.path() / "tiles");
      for (const auto& e : std::filesystem::directory_iterator(cache.path()))
        if (e.path().filename() != ".anchor") std::filesystem::remove_all(e.path());
    }
    auto source = open_height_source(settings, context);
    TileLoaderOptions options;
    options.threads = 8;
    TileLoader<HeightTile> loader(load_from(*source), options);
    state.ResumeTiming();
    load_view(loader, state);
  }
  state.counters["tiles"] = static_cast<double>(fixture().view.size());
}

BENCHMARK(BM_ViewFromFolderCold)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ViewFromFolderWarm)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ViewFromHttp, cold, false)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ViewFromHttp, warm, true)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
