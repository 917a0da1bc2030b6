#include "track/summary.hpp"

namespace trailray::track {

TrackSummary summarize_track(const Track& track, const AnalysisOptions& options) {
  TrackSummary s;
  s.name = track.name;
  const TrackMetrics raw_metrics = compute_metrics(track, options.metrics);
  s.raw = track_statistics(track, raw_metrics, options.statistics);

  const Track cleaned = clean_track(track, options.clean, s.cleaning);
  const TrackMetrics clean_metrics = compute_metrics(cleaned, options.metrics);
  s.clean = track_statistics(cleaned, clean_metrics, options.statistics);

  s.segments.resize(track.segments.size());
  for (std::size_t i = 0; i < track.segments.size(); ++i) {
    s.segments[i].raw = segment_statistics(track.segments[i], raw_metrics.segments[i], options.statistics);
    s.segments[i].clean = segment_statistics(cleaned.segments[i], clean_metrics.segments[i], options.statistics);
  }
  return s;
}

}  // namespace trailray::track
