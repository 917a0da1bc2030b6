// Memory per point of the tracks a picture or the viewer holds: 1000 generated walks of 1000
// timed points with elevations (a million points), built as `render` builds them (what is drawn)
// and as `view` does (inspect: the summaries and every per-point number of the panels). Counters:
// heap bytes per point in use after building (glibc's mallinfo2, the files read freed), and the
// bytes per point each part of a scene::Track holds (vector capacities), the largest first.
// Run: build/bench/scene_memory_bench
// (issue "heatmaps on Dask": 420 bytes a point when measured first; aim under 150; 142 on 2026-11-29.)

#include <benchmark/benchmark.h>
#include <malloc.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "app/drawing/scene_setup.hpp"
#include "scene/diagnostics.hpp"

namespace {

using namespace trailray;

constexpr int kTracks = 1000, kPoints = 1000;

std::vector<scene::LoadedTrackFile> generated_files() {
  std::vector<scene::LoadedTrackFile> files;
  for (int f = 0; f < kTracks; ++f) {
    scene::LoadedTrackFile file;
    file.path = "walk" + std::to_string(f) + ".gpx";
    track::Track t;
    t.name = file.path;
    t.segments.emplace_back();
    for (int i = 0; i < kPoints; ++i) {
      track::TrackPoint p;
      p.lat = 46.5 + 0.01 * (f % 30) + 0.00002 * i;
      p.lon = 7.5 + 0.01 * (f / 30) + 0.00003 * i + 0.00001 * std::sin(i * 0.1);
      p.ele = 1000.0 + 50.0 * std::sin(i * 0.01);
      p.time = 1.7e9 + 86400.0 * f + 5.0 * i;
      t.segments[0].points.push_back(p);
    }
    file.file.tracks.push_back(std::move(t));
    files.push_back(std::move(file));
  }
  return files;
}

template <class T>
std::size_t bytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

// What each part of the tracks holds, in bytes.
std::map<std::string, double> parts(const scene::TrackSet& set) {
  std::map<std::string, double> out;
  for (const scene::Track& t : set.tracks()) {
    for (const auto& s : t.cleaned.segments) out["cleaned points"] += static_cast<double>(bytes(s.points));
    out["panel numbers"] += static_cast<double>(
        bytes(t.distance_m) + bytes(t.time_unix_s) + bytes(t.altitude_m) +
        bytes(t.pressure_altitude_m) + bytes(t.gnss_altitude_m) + bytes(t.ground_m) + bytes(t.speed_kmh) +
        bytes(t.vspeed_ms) + bytes(t.heart_rate_bpm) + bytes(t.cadence_rpm) + bytes(t.power_w) +
        bytes(t.timed_points));
    for (const auto& s : t.geometry.segments)
      out["geometry"] += static_cast<double>(bytes(s.points_ecef) + bytes(s.values) + bytes(s.heights_above_ground_m));
  }
  return out;
}

void build(benchmark::State& state, bool inspect) {
  scene::CollectedDiagnostics diagnostics;
  for (auto _ : state) {
    malloc_trim(0);
    const std::size_t before = mallinfo2().uordblks;
    app::SceneTracks tracks;
    {
      std::vector<scene::LoadedTrackFile> files = generated_files();
      scene::TrackBuildOptions options;
      options.inspect = inspect;
      tracks = app::build_scene_tracks(std::move(files), {}, {}, {}, options, diagnostics);
    }  // the points read are freed as their tracks are built, as render and video do
    const std::size_t after = mallinfo2().uordblks;
    const double points = double{kTracks} * kPoints;
    state.counters["B/pt"] = static_cast<double>(after - before) / points;
    for (const auto& [name, b] : parts(tracks.tracks)) state.counters[name + " B/pt"] = b / points;
  }
}

void BM_SceneMemory_Render(benchmark::State& state) { build(state, false); }
void BM_SceneMemory_View(benchmark::State& state) { build(state, true); }

}  // namespace

BENCHMARK(BM_SceneMemory_Render)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SceneMemory_View)->Iterations(1)->Unit(benchmark::kMillisecond);
