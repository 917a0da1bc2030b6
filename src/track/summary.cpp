#include "track/summary.hpp"

#include <future>
#include <stdexcept>
#include <string>

#include "geo/threads.hpp"

namespace trailray::track {
namespace {

// Below this many points a second thread costs more than it saves.
constexpr std::size_t kParallelPoints = 10000;

// Cleaning keeps every segment (possibly emptied), so raw and clean segments pair up by index.
std::vector<SegmentSummary> segment_summaries(const Track& raw, const TrackMetrics& raw_metrics, const Track& cleaned,
                                              const TrackMetrics& clean_metrics, const StatisticsOptions& options) {
  std::vector<SegmentSummary> out(raw.segments.size());
  for (std::size_t i = 0; i < raw.segments.size(); ++i) {
    out[i].raw = segment_statistics(raw.segments[i], raw_metrics.segments[i], options);
    out[i].clean = segment_statistics(cleaned.segments[i], clean_metrics.segments[i], options);
  }
  return out;
}

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
  const bool parallel = geo::kThreadsAvailable && track.point_count() >= kParallelPoints;
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

  s.segments = segment_summaries(track, raw_metrics, cleaned, clean_metrics, options.statistics);
  return s;
}

TrackSummary summarize_cleaned_track(const Track& track, const Track& cleaned, const CleanReport& cleaning,
                                     const TrackMetrics& clean_metrics, const AnalysisOptions& options) {
  if (cleaned.segments.size() != track.segments.size() || clean_metrics.segments.size() != cleaned.segments.size())
    throw std::invalid_argument("summarize_cleaned_track: track '" + track.name + "' has " +
                                std::to_string(track.segments.size()) + " segments, its cleaned copy " +
                                std::to_string(cleaned.segments.size()) + " and their metrics " +
                                std::to_string(clean_metrics.segments.size()));
  TrackSummary s;
  s.name = track.name;
  s.cleaning = cleaning;
  s.clean = track_statistics(cleaned, clean_metrics, options.statistics);
  const TrackMetrics raw_metrics = compute_metrics(track, options.metrics);
  s.raw = track_statistics(track, raw_metrics, options.statistics);
  s.segments = segment_summaries(track, raw_metrics, cleaned, clean_metrics, options.statistics);
  return s;
}

}  // namespace trailray::track
