#include "track/summary.hpp"

#include <future>

namespace trailray::track {
namespace {

// Below this many points a second thread costs more than it saves.
constexpr std::size_t kParallelPoints = 10000;

}  // namespace

TrackSummary summarize_track(const Track& track, const AnalysisOptions& options) {
  TrackSummary s;
  s.name = track.name;
  // The raw and the clean analyses are independent: on a big track the raw one runs on a
  // second thread while this one cleans.
  auto analyse_raw = [&track, &options] {
    TrackMetrics m = compute_metrics(track, options.metrics);
    Statistics st = track_statistics(track, m, options.statistics);
    return std::make_pair(std::move(m), st);
  };
  std::future<std::pair<TrackMetrics, Statistics>> raw_future;
  std::pair<TrackMetrics, Statistics> raw;
  const bool parallel = track.point_count() >= kParallelPoints;
  if (parallel)
    raw_future = std::async(std::launch::async, analyse_raw);
  else
    raw = analyse_raw();

  const Track cleaned = clean_track(track, options.clean, s.cleaning);
  const TrackMetrics clean_metrics = compute_metrics(cleaned, options.metrics);
  s.clean = track_statistics(cleaned, clean_metrics, options.statistics);

  if (parallel) raw = raw_future.get();
  const TrackMetrics& raw_metrics = raw.first;
  s.raw = raw.second;

  s.segments.resize(track.segments.size());
  for (std::size_t i = 0; i < track.segments.size(); ++i) {
    s.segments[i].raw = segment_statistics(track.segments[i], raw_metrics.segments[i], options.statistics);
    s.segments[i].clean = segment_statistics(cleaned.segments[i], clean_metrics.segments[i], options.statistics);
  }
  return s;
}

}  // namespace trailray::track
