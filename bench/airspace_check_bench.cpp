// `trailray check`'s core: a whole country's OpenAir file against a 10-hour 1 Hz flight
// (36,000 fixes), target well under a second. The flight is synthetic: a Lissajous curve over
// Switzerland (45.95..47.65 N, 6.1..10.3 E, about 20 m/s) climbing and sinking between 1500 and
// 3500 m, so it crosses many TMAs and CTRs; pressure altitude 30 m below GNSS. Measured: the
// index and the check (find_infringements), and reading the file (arcs and circles included).
// Needs ../shared/data/airspace; skips a file that is absent.
// Run: build/bench/airspace_check_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "track/airspace/infringement.hpp"
#include "track/airspace/openair_reader.hpp"

namespace {

using namespace trailray::track::airspace;

std::vector<CheckPoint> ten_hour_flight() {
  std::vector<CheckPoint> out;
  constexpr double kTwoPi = 2 * std::numbers::pi;
  for (int t = 0; t < 36000; ++t) {
    const double msl = 2500 + 1000 * std::sin(kTwoPi * t / 3000.0);
    out.push_back({46.8 + 0.85 * std::sin(kTwoPi * t / 14000.0), 8.2 + 2.1 * std::sin(kTwoPi * t / 9000.0 + 0.7),
                   1.7e9 + t, msl, msl - 30, trailray::track::kMissing});
  }
  return out;
}

std::string data(const char* name) { return std::string(TRAILRAY_SHARED_DATA) + "/airspace/" + name; }

void check_flight(benchmark::State& state, const char* name) {
  if (!std::filesystem::exists(data(name))) return state.SkipWithError("shared data absent");
  const AirspaceReadResult r = load_openair_file(data(name));
  const std::vector<std::vector<CheckPoint>> flight{ten_hour_flight()};
  std::size_t found = 0;
  for (auto _ : state) {
    const AirspaceIndex index(r.file);
    found = find_infringements(index, flight).size();
    benchmark::DoNotOptimize(found);
  }
  state.counters["airspaces"] = static_cast<double>(r.file.airspaces.size());
  state.counters["infringements"] = static_cast<double>(found);
}

void read_file(benchmark::State& state, const char* name) {
  if (!std::filesystem::exists(data(name))) return state.SkipWithError("shared data absent");
  for (auto _ : state) benchmark::DoNotOptimize(load_openair_file(data(name)));
}

}  // namespace

BENCHMARK_CAPTURE(check_flight, switzerland_10h, "openairrs_Switzerland.txt")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(check_flight, germany_10h, "openairrs_Germany.txt")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(read_file, switzerland, "openairrs_Switzerland.txt")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(read_file, germany, "openairrs_Germany.txt")->Unit(benchmark::kMillisecond);
