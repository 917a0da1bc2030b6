// Flight analysis (take-off, landing, phases, thermals, glides, wind) of the real flights with
// the most fixes: the 10.7-hour 1 Hz free flight (38,675 fixes) and the biggest IGC file
// (65,924 B records, 9,916 distinct seconds). Reading the file is not timed.
// Needs ../shared/data/igc; skips a file that is absent.
// Run: build/bench/flight_analysis_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <filesystem>

#include "track/flight/flight_analysis.hpp"
#include "track/io/load.hpp"

namespace {

void analyse(benchmark::State& state, const char* name) {
  const std::string path = std::string(TRAILRAY_SHARED_DATA) + "/igc/" + name;
  if (!std::filesystem::exists(path)) return state.SkipWithError("shared data absent");
  const trailray::track::ReadResult r = trailray::track::load_track_file(path);
  if (!r.ok() || r.file.tracks.empty()) return state.SkipWithError("unreadable");
  std::size_t thermals = 0;
  for (auto _ : state) {
    const auto a = trailray::track::flight::analyse_flights(r.file.tracks.front());
    thermals = a.flights.empty() ? 0 : a.flights.front().thermals.size();
    benchmark::DoNotOptimize(thermals);
  }
  state.counters["points"] = static_cast<double>(r.file.tracks.front().point_count());
  state.counters["thermals"] = static_cast<double>(thermals);
}

}  // namespace

BENCHMARK_CAPTURE(analyse, freeflight_10h, "scoring/xcscore_freeflight-xcontest-465.33.igc")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(analyse, dup_fixes_66k, "xcscore_dup-fixes.igc")->Unit(benchmark::kMillisecond);
