// Reading many track files as `render`, `video` and `view` do (parse, then each file's tracks
// cleaned, measured and placed; app/common/track_reading), one file after the other (threads 1) against
// all cores (threads 0: std::thread::hardware_concurrency()). Two inputs of 1000 files:
// - generated: 1000 GPX files of 1000 timed points each (written once into a temporary folder);
// - real: the IGC and GPX files of ../shared/data (those that read), named again and again up to
//   1000 paths (skipped when the data is absent).
// Wall-clock time (UseRealTime); the CPU column is the whole process's, every thread.
// Run: build/bench/track_loading_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "app/common/track_arguments.hpp"
#include "app/common/track_reading.hpp"
#include "scene/diagnostics.hpp"

namespace {

namespace fs = std::filesystem;
using trailray::app::build_tracks_parallel;
using trailray::app::read_track_files_parallel;

constexpr int kFiles = 1000, kPoints = 1000;

// 1000 GPX files of a walk heading north-east, each from another place and day.
const std::vector<std::string>& generated_paths() {
  static const std::vector<std::string> paths = [] {
    const fs::path dir = fs::temp_directory_path() / "trailray-track-loading-bench";
    fs::create_directories(dir);
    std::vector<std::string> out;
    for (int f = 0; f < kFiles; ++f) {
      char name[32];
      std::snprintf(name, sizeof name, "walk_%04d.gpx", f);
      const fs::path path = dir / name;
      out.push_back(path.string());
      if (fs::exists(path)) continue;
      std::ofstream gpx(path);
      gpx << "<?xml version=\"1.0\"?>\n<gpx version=\"1.1\" creator=\"bench\" "
             "xmlns=\"http://www.topografix.com/GPX/1/1\">\n<trk><name>walk "
          << f << "</name><trkseg>\n";
      const double lat0 = 46.0 + 0.01 * (f % 50), lon0 = 7.0 + 0.01 * (f / 50);
      for (int i = 0; i < kPoints; ++i) {
        const int s = i * 5;  // 5 s apart
        char line[200];
        std::snprintf(
            line, sizeof line,
            "<trkpt lat=\"%.7f\" lon=\"%.7f\"><ele>%.1f</ele><time>2024-06-%02dT%02d:%02d:%02dZ</time></trkpt>\n",
            lat0 + 0.00005 * i + 0.00001 * std::sin(i * 0.1), lon0 + 0.00004 * i, 600.0 + 50.0 * std::sin(i * 0.01),
            1 + f % 28, 8 + s / 3600, (s / 60) % 60, s % 60);
        gpx << line;
      }
      gpx << "</trkseg></trk>\n</gpx>\n";
    }
    return out;
  }();
  return paths;
}

// The shared data's IGC and GPX files that read without error, repeated to 1000 paths.
const std::vector<std::string>& real_paths() {
  static const std::vector<std::string> paths = [] {
    std::vector<std::string> readable;
    const std::string root = TRAILRAY_SHARED_DATA;
    if (!fs::exists(root + "/igc")) return readable;
    for (const std::string& path : trailray::app::expand_track_arguments({root + "/igc", root + "/gpx"})) {
      trailray::scene::CollectedDiagnostics ignored;
      try {
        read_track_files_parallel({path}, {}, ignored, 1);
        readable.push_back(path);
      } catch (const std::exception&) {
      }
    }
    std::vector<std::string> out;
    while (!readable.empty() && out.size() < static_cast<std::size_t>(kFiles))
      out.push_back(readable[out.size() % readable.size()]);
    return out;
  }();
  return paths;
}

void load(benchmark::State& state, const std::vector<std::string>& (*paths_of)()) {
  const std::vector<std::string>& paths = paths_of();
  if (paths.empty()) return state.SkipWithError("shared data absent");
  const auto threads = static_cast<unsigned>(state.range(0));
  std::size_t tracks = 0;
  for (auto _ : state) {
    trailray::scene::CollectedDiagnostics ignored;
    const auto files = read_track_files_parallel(paths, {}, ignored, threads);
    tracks = build_tracks_parallel(files, {}, {}, ignored, 0, threads).size();
    benchmark::DoNotOptimize(tracks);
  }
  state.counters["files"] = static_cast<double>(paths.size());
  state.counters["tracks"] = static_cast<double>(tracks);
  state.counters["threads"] = threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : threads;
}

}  // namespace

// threads 1: one file after the other; 0: every core.
BENCHMARK_CAPTURE(load, generated_1000x1000, generated_paths)
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK_CAPTURE(load, real_repeated_1000, real_paths)
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
