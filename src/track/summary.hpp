#pragma once
// Raw ("as recorded") and clean (after clean_track) statistics of a track and of each of its
// segments: the numbers `trailray stats` reports.

#include <string>
#include <vector>

#include "track/clean.hpp"
#include "track/metrics.hpp"
#include "track/statistics.hpp"

namespace trailray::track {

struct AnalysisOptions {
  CleanOptions clean;
  MetricsOptions metrics;
  StatisticsOptions statistics;
};

struct SegmentSummary {
  Statistics raw;
  Statistics clean;
};

struct TrackSummary {
  std::string name;
  Statistics raw;
  Statistics clean;
  std::vector<SegmentSummary> segments;  // parallel to Track::segments
  CleanReport cleaning;
};

TrackSummary summarize_track(const Track& track, const AnalysisOptions& options = {});

// The same from a track already cleaned (clean_track(track, options.clean, cleaning)) and
// measured (compute_metrics(cleaned, options.metrics)): only the raw analysis is left to do.
// Throws std::invalid_argument when `cleaned` does not have the raw track's segments or
// `clean_metrics` does not match `cleaned`.
TrackSummary summarize_cleaned_track(const Track& track, const Track& cleaned, const CleanReport& cleaning,
                                     const TrackMetrics& clean_metrics, const AnalysisOptions& options = {});

}  // namespace trailray::track
