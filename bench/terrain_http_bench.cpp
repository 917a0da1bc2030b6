// The HTTP tile source against a local server: the time to fetch one view's tiles (64, an 8 x 8
// block at zoom 12) with an empty disk cache (download, validate, write + fsync + rename each
// tile) and with all of them cached and fresh (no network), from 1 thread and from 6 (the
// loader's workers, the default parallel-request limit). The counters give the bytes a cached
// tile takes on disk: payload, header overhead, and the disk blocks it occupies.
//
// Payloads are 256 x 256 RGB PNGs generated with noise so they compress like real terrain tiles
// (about 170 KB, the upper end of real ones), made once per tile; the server is tests/terrain/local_tile_server.hpp on
// 127.0.0.1.
//
//   build/bench/terrain_http_bench --benchmark_repetitions=9 --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>
#include <sys/stat.h>

#include <atomic>
#include <filesystem>
#include <memory>
#include <thread>
#include <vector>

#include "../tests/terrain/local_tile_server.hpp"
#include "terrain/sources/http_source.hpp"

namespace {

using trailray::terrain::EncodedTile;
using trailray::terrain::HttpSourceOptions;
using trailray::terrain::HttpTileSource;
using trailray::terrain::TileId;
using trailray::terrain::TileStatus;
namespace http = trailray::test::http;

constexpr int kZoom = 12;
constexpr std::uint32_t kFirstX = 2130, kFirstY = 1440, kSide = 8;

http::LocalTileServer& server() {
  static http::LocalTileServer* instance = [] {
    auto* s = new http::LocalTileServer();
    s->set_cache_control("max-age=3600");
    return s;
  }();
  return *instance;
}

std::unique_ptr<HttpTileSource> make_source(const std::filesystem::path& cache_folder) {
  HttpSourceOptions options;
  options.cache.folder = cache_folder;
  return std::make_unique<HttpTileSource>(server().url("/tiles/{z}/{x}/{y}.png"), options);
}

// Fetches the 64 tiles of the view from `threads` threads; false if any is not ok.
bool fetch_view(HttpTileSource& source, int threads) {
  std::atomic<std::uint32_t> next{0};
  std::atomic<bool> all_ok{true};
  auto worker = [&] {
    for (std::uint32_t i = next++; i < kSide * kSide; i = next++) {
      const EncodedTile tile = source.fetch(TileId{kZoom, kFirstX + i % kSide, kFirstY + i / kSide}, {});
      if (tile.status != TileStatus::ok) all_ok = false;
      benchmark::DoNotOptimize(tile.bytes.data());
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  return all_ok;
}

void report_bytes_per_tile(benchmark::State& state, const HttpTileSource& source) {
  double files = 0, file_bytes = 0, disk_bytes = 0, payload_bytes = 0;
  for (const auto& path : http::files_containing(source.disk_cache()->folder(), ".tile")) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) continue;
    files += 1;
    file_bytes += static_cast<double>(st.st_size);
    disk_bytes += static_cast<double>(st.st_blocks) * 512.0;
  }
  for (std::uint32_t i = 0; i < kSide * kSide; ++i) {
    payload_bytes += static_cast<double>(server().tile_bytes(kZoom, kFirstX + i % kSide, kFirstY + i / kSide).size());
  }
  if (files == 0) return;
  state.counters["payload_B_per_tile"] = payload_bytes / (kSide * kSide);
  state.counters["file_B_per_tile"] = file_bytes / files;
  state.counters["overhead_B_per_tile"] = (file_bytes - payload_bytes) / files;
  state.counters["disk_B_per_tile"] = disk_bytes / files;
}

void BM_ColdView64(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  std::unique_ptr<http::TempFolder> folder;
  std::unique_ptr<HttpTileSource> source;
  for (auto _ : state) {
    state.PauseTiming();
    source.reset();
    folder = std::make_unique<http::TempFolder>();  // a new, empty cache each time
    source = make_source(folder->path());
    state.ResumeTiming();
    if (!fetch_view(*source, threads)) state.SkipWithError("a tile failed");
  }
  report_bytes_per_tile(state, *source);
  state.counters["tiles_per_s"] = benchmark::Counter(
      static_cast<double>(kSide * kSide) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_WarmView64(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  http::TempFolder folder;
  std::unique_ptr<HttpTileSource> source = make_source(folder.path());
  if (!fetch_view(*source, threads)) state.SkipWithError("a tile failed while filling the cache");
  const int requests_before = server().request_count();
  for (auto _ : state) {
    if (!fetch_view(*source, threads)) state.SkipWithError("a tile failed");
  }
  if (server().request_count() != requests_before) state.SkipWithError("a warm fetch went to the network");
  report_bytes_per_tile(state, *source);
  state.counters["tiles_per_s"] = benchmark::Counter(
      static_cast<double>(kSide * kSide) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_ColdView64)->Arg(1)->Arg(6)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_WarmView64)->Arg(1)->Arg(6)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
