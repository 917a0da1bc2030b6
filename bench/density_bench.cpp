// Neighbour counts for the density view (`--color-by density`): 10,000 tracks of 1,000 points,
// every point counted against every track (the index built, then all points asked), on one
// thread and on every core (app/common/parallel_jobs, as `render` and `view` run it).
// - city: runs through a 20 x 20 km city, random walks from random starts, a fix every 5 to 15 m
//   (each track about 10 km);
// - club: 1,000 (club/1000/...) or 10,000 (club/10000/...) flights from one take-off, a fix every
//   20 to 60 m, wandering a few km: every track passes the take-off, so the points there count all
//   of them (the first 1,000 flights of the 10,000 are the 1,000).
// Radius 100 m (the default). The tracks are made once, outside the timing. The arguments: the
// tracks (club only), then the threads (1, or 0 for every core).
// Run: build/bench/density_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// (club/10000 took minutes before the counts were done per cell: --benchmark_filter='city|club/1000/'
// leaves it out).

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <span>
#include <vector>

#include "app/common/parallel_jobs.hpp"
#include "track/density.hpp"

namespace {

using trailray::track::PointLine;
using trailray::track::TrackPoint;

constexpr int kTracks = 10000, kPoints = 1000;
// The club's flights all pass one take-off and stay near it: every point counts hundreds of
// tracks, and the work grows with that count.
constexpr int kClubTracks = 10000;

// Random walks: each from a start drawn by `start`, steps of `step` metres, the heading turning a
// little each fix (local metres to degrees on a sphere: a few tens of km, exact enough here).
template <typename Start>
std::vector<std::vector<TrackPoint>> walks(int count, unsigned seed, Start start, double min_step, double max_step) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> heading(0.0, 2.0 * std::numbers::pi), turn(-0.3, 0.3),
      step(min_step, max_step);
  constexpr double lat0 = 47.37, lon0 = 8.54, metres_per_deg = 111195.0;
  const double cos_lat = std::cos(lat0 * std::numbers::pi / 180.0);
  std::vector<std::vector<TrackPoint>> out(static_cast<std::size_t>(count));
  for (auto& w : out) {
    auto [n, e] = start(rng);
    double h = heading(rng);
    w.resize(kPoints);
    for (TrackPoint& p : w) {
      p.lat = lat0 + n / metres_per_deg;
      p.lon = lon0 + e / (metres_per_deg * cos_lat);
      h += turn(rng);
      const double s = step(rng);
      n += s * std::cos(h);
      e += s * std::sin(h);
    }
  }
  return out;
}

const std::vector<std::vector<TrackPoint>>& city() {
  static const auto tracks = walks(
      kTracks, 1,
      [](std::mt19937& rng) {
        std::uniform_real_distribution<double> d(-10000.0, 10000.0);
        return std::pair{d(rng), d(rng)};
      },
      5.0, 15.0);
  return tracks;
}

const std::vector<std::vector<TrackPoint>>& club() {
  static const auto tracks = walks(
      kClubTracks, 2,
      [](std::mt19937&) {
        return std::pair{0.0, 0.0};
      },
      20.0, 60.0);
  return tracks;
}

// The first `count` tracks of `all` as sources and as targets.
void run(benchmark::State& state, const std::vector<std::vector<TrackPoint>>& all, std::size_t count,
         unsigned threads) {
  const std::span<const std::vector<TrackPoint>> tracks(all.data(), count);
  std::vector<trailray::track::NeighbourSource> sources;
  std::vector<std::vector<PointLine>> targets;
  for (const auto& t : tracks) {
    sources.push_back({{PointLine(t)}});
    targets.push_back({PointLine(t)});
  }
  const trailray::track::ParallelFor parallel = trailray::app::parallel_for(threads);
  double total = 0;
  for (auto _ : state) {
    const auto counts = trailray::track::neighbour_counts(sources, targets, 100.0, parallel);
    total = 0;
    for (const auto& t : counts) total += t.front()[t.front().size() / 2];
    benchmark::DoNotOptimize(total);
  }
  state.counters["points"] = static_cast<double>(tracks.size()) * kPoints;
  state.counters["mean_count_mid"] = total / static_cast<double>(tracks.size());
  state.counters["threads"] = threads == 0 ? trailray::app::default_job_threads() : threads;
}

void count_city(benchmark::State& state) { run(state, city(), kTracks, static_cast<unsigned>(state.range(0))); }

void count_club(benchmark::State& state) {
  run(state, club(), static_cast<std::size_t>(state.range(0)), static_cast<unsigned>(state.range(1)));
}

}  // namespace

BENCHMARK(count_city)->Name("city")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(count_club)->Name("club")->ArgsProduct({{1000, 10000}, {1, 0}})->Unit(benchmark::kMillisecond)->UseRealTime();
