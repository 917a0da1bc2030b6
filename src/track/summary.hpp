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

}  // namespace trailray::track
