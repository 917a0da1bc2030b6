// Track files read and built on several threads give what a read one file after the other gives:
// the same tracks in the same order with the same colours, the same warnings in the same order,
// and the same first error; the job runner under them runs each job once and stops as told.
#include "app/common/track_reading.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "app/common/parallel_jobs.hpp"
#include "app/common/track_arguments.hpp"
#include "app/track_cli_support.hpp"
#include "scene/tracks/track_building.hpp"
#include "scene/tracks/track_files.hpp"

namespace trailray::app {
namespace {

using trailray::test::east_line;
using trailray::test::GpxTrack;

constexpr double kLat = 46.6, kLon = 7.9, kT0 = 1718704800.0;

// `count` GPX files in a folder, each different (place, length, times, tracks and segments);
// `bad`: indexes written as broken XML; `warned`: indexes with a point out of range (a warning).
struct GeneratedFolder {
  trailray::test::TempDir dir;
  GeneratedFolder(int count, const std::set<int>& bad = {}, const std::set<int>& warned = {}) {
    for (int i = 0; i < count; ++i) {
      char name[32];
      std::snprintf(name, sizeof name, "track_%04d.gpx", i);
      std::ofstream out(dir.path() / name, std::ios::binary);
      if (bad.count(i)) {
        out << "<?xml version=\"1.0\"?>\n<gpx version=\"1.1\">\n <trk><trkseg>\n  <trkpt lat=\"46\" lon=\"7\">\n"
               " </trk>\n</gpx>\n";
        continue;
      }
      std::vector<GpxTrack> tracks;
      const double north = 150.0 * i;
      const double interval = i % 3 == 0 ? trailray::test::kNoValue : 1.0 + i % 4;
      GpxTrack t{"flight " + std::to_string(i),
                 {east_line(kLat, kLon, 0.0, 20 + i % 17, 12.0 + i % 5,
                            i % 3 == 0 ? trailray::test::kNoValue : kT0 + 60.0 * i, interval, 600.0 + 7.0 * i, north)}};
      if (i % 4 == 1)  // a second segment after a gap
        t.segments.push_back(east_line(kLat, kLon, 900.0, 15, 10.0, kT0 + 60.0 * i + 500.0, 2.0, 640.0, north));
      tracks.push_back(t);
      if (i % 5 == 2)  // a second track in the same file
        tracks.push_back({"", {east_line(kLat, kLon, 0.0, 12, 20.0, kT0, 3.0, 700.0, north + 40.0)}});
      std::string text = trailray::test::gpx_text(tracks);
      if (warned.count(i)) {
        const std::string fix = "<trkseg>\n";
        text.insert(text.find(fix) + fix.size(), "   <trkpt lat=\"95\" lon=\"7.9\"><ele>600</ele></trkpt>\n");
      }
      out << text;
    }
  }
  std::vector<std::string> paths() const { return expand_track_arguments({dir.path().string()}); }
};

template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void expect_same_tracks(const std::vector<scene::Track>& expected, const std::vector<scene::Track>& got) {
  ASSERT_EQ(expected.size(), got.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE("track " + std::to_string(i) + " of " + expected[i].source);
    const scene::Track& e = expected[i];
    const scene::Track& g = got[i];
    EXPECT_EQ(e.name, g.name);
    EXPECT_EQ(e.source, g.source);
    EXPECT_EQ(e.color_srgb, g.color_srgb);
    EXPECT_EQ(e.is_route, g.is_route);
    EXPECT_EQ(e.by_value, g.by_value);
    EXPECT_EQ(e.segment_first, g.segment_first);
    EXPECT_TRUE(same_bits(e.distance_m, g.distance_m));
    EXPECT_TRUE(same_bits(e.time_unix_s, g.time_unix_s));
    EXPECT_TRUE(same_bits(e.altitude_m, g.altitude_m));
    EXPECT_TRUE(same_bits(e.speed_kmh, g.speed_kmh));
    EXPECT_TRUE(same_bits(e.vspeed_ms, g.vspeed_ms));
    EXPECT_EQ(e.flights != nullptr, g.flights != nullptr);
    ASSERT_EQ(e.geometry.segments.size(), g.geometry.segments.size());
    for (std::size_t s = 0; s < e.geometry.segments.size(); ++s) {
      EXPECT_TRUE(same_bits(e.geometry.segments[s].points_ecef, g.geometry.segments[s].points_ecef));
      EXPECT_TRUE(same_bits(e.geometry.segments[s].values, g.geometry.segments[s].values));
    }
  }
}

// The reference: scene's own reading and building, one file after the other.
std::vector<scene::Track> sequential(const std::vector<std::string>& paths, const scene::TrackStyle& style,
                                     const scene::TrackBuildOptions& options, std::vector<std::string>& warnings) {
  scene::CollectedDiagnostics d;
  const auto files = scene::read_track_files(paths, {}, d);
  auto tracks = scene::build_tracks(files, style, options, d, 3);
  warnings = d.warnings;
  return tracks;
}

std::vector<scene::Track> parallel(const std::vector<std::string>& paths, const scene::TrackStyle& style,
                                   const scene::TrackBuildOptions& options, std::vector<std::string>& warnings,
                                   unsigned threads) {
  scene::CollectedDiagnostics d;
  const auto files = read_track_files_parallel(paths, {}, d, threads);
  auto tracks = build_tracks_parallel(files, style, options, d, 3, threads);
  warnings = d.warnings;
  return tracks;
}

TEST(TrackReading, ParallelGivesTheSequentialTracksInOrder) {
  const GeneratedFolder folder(60, {}, {4, 17, 33});
  const std::vector<std::string> paths = folder.paths();
  ASSERT_EQ(paths.size(), 60u);
  for (const auto metric : {track::ColorMetric::solid, track::ColorMetric::speed}) {
    SCOPED_TRACE(track::color_metric_name(metric));
    scene::TrackStyle style;
    style.color_by = metric;
    scene::TrackBuildOptions options;
    options.inspect = true;
    std::vector<std::string> expected_warnings;
    const auto expected = sequential(paths, style, options, expected_warnings);
    ASSERT_EQ(expected.size(), 60u + 12u);  // files 2, 7, 12, ... hold two tracks
    EXPECT_EQ(expected_warnings.size(), 3u);
    for (unsigned threads : {1u, 2u, 7u, 0u}) {
      SCOPED_TRACE("threads " + std::to_string(threads));
      std::vector<std::string> warnings;
      expect_same_tracks(expected, parallel(paths, style, options, warnings, threads));
      EXPECT_EQ(warnings, expected_warnings);
    }
  }
}

TEST(TrackReading, TheFirstBadFileInOrderIsTheError) {
  const GeneratedFolder folder(40, {9, 31}, {3, 20});
  const std::vector<std::string> paths = folder.paths();
  std::string expected_error;
  scene::CollectedDiagnostics expected;
  try {
    scene::read_track_files(paths, {}, expected);
  } catch (const std::runtime_error& e) {
    expected_error = e.what();
  }
  ASSERT_NE(expected_error.find("track_0009.gpx:"), std::string::npos) << expected_error;  // file and position
  for (unsigned threads : {1u, 2u, 8u}) {
    scene::CollectedDiagnostics d;
    try {
      read_track_files_parallel(paths, {}, d, threads);
      ADD_FAILURE() << "no error with " << threads << " threads";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(e.what(), expected_error);
    }
    EXPECT_EQ(d.warnings, expected.warnings);  // file 3's warning, said before the error
  }
}

TEST(TrackReading, EveryFileReadWhenErrorsDoNotStop) {
  const GeneratedFolder folder(30, {5, 21});
  const std::vector<std::string> paths = folder.paths();
  const auto outcomes = read_track_file_outcomes(paths, {}, {3, false}, nullptr);
  ASSERT_EQ(outcomes.size(), paths.size());
  for (std::size_t i = 0; i < paths.size(); ++i) {
    EXPECT_TRUE(outcomes[i].read);
    EXPECT_EQ(outcomes[i].error.has_value(), i == 5 || i == 21) << i;
    if (outcomes[i].error) {
      EXPECT_EQ(outcomes[i].error->rfind(paths[i] + ":", 0), 0u) << *outcomes[i].error;
    }
    if (outcomes[i].loaded) {
      EXPECT_EQ(outcomes[i].loaded->path, paths[i]);
    }
  }
}

// Progress lines as a terminal would show them.
struct ProgressLines : scene::CollectedDiagnostics {
  std::vector<std::string> lines;
  int done = 0;
  void progress(const std::string& status) override { lines.push_back(status); }
  void progress_done() override { ++done; }
};

TEST(TrackReading, ProgressCountsTheFilesThenTheirTracks) {
  const GeneratedFolder folder(25);
  ProgressLines d;
  const auto files = read_track_files_parallel(folder.paths(), {}, d, 2);
  ASSERT_FALSE(d.lines.empty());
  EXPECT_EQ(d.lines.back(), "reading 25/25 files");
  EXPECT_EQ(d.done, 1);
  build_tracks_parallel(files, {}, {}, d, 0, 2);
  EXPECT_EQ(d.lines.back(), "preparing the tracks of 25/25 files");
  EXPECT_EQ(d.done, 2);
  // One file: no progress line to flash.
  ProgressLines one;
  read_track_files_parallel({folder.paths().front()}, {}, one, 2);
  EXPECT_TRUE(one.lines.empty());
}

TEST(ParallelJobs, EachJobRunsOnceAndProgressEndsAtTheCount) {
  const std::size_t count = 500;
  std::vector<std::atomic<int>> runs(count);
  std::vector<std::pair<std::size_t, std::size_t>> reports;
  const std::thread::id caller = std::this_thread::get_id();
  bool progress_elsewhere = false;
  const std::size_t ran = run_parallel_jobs(count, [&](std::size_t i) { return ++runs[i] > 0; },
                                            {4, [&](std::size_t done, std::size_t n) {
                                               progress_elsewhere =
                                                   progress_elsewhere || std::this_thread::get_id() != caller;
                                               reports.emplace_back(done, n);
                                             }});
  EXPECT_EQ(ran, count);
  for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(runs[i].load(), 1) << i;
  ASSERT_FALSE(reports.empty());
  EXPECT_EQ(reports.back(), std::make_pair(count, count));
  EXPECT_FALSE(progress_elsewhere);
}

TEST(ParallelJobs, AStopLetsTheEarlierJobsRunAndSkipsLaterOnes) {
  const std::size_t count = 2000, stop = 100;
  for (unsigned threads : {1u, 3u}) {
    std::vector<std::atomic<int>> runs(count);
    run_parallel_jobs(count,
                      [&](std::size_t i) {
                        ++runs[i];
                        return i != stop;
                      },
                      {threads, {}});
    for (std::size_t i = 0; i <= stop; ++i) EXPECT_EQ(runs[i].load(), 1) << i;
    std::size_t after = 0;
    for (std::size_t i = stop + 1; i < count; ++i) after += static_cast<std::size_t>(runs[i].load());
    // Only jobs already taken when the stop came may have run (at most one per other thread).
    EXPECT_LE(after, threads - 1) << threads << " threads";
  }
}

}  // namespace
}  // namespace trailray::app
