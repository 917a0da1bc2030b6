#pragma once
// Summary figures of a track or one segment, the numbers `trailray stats` prints.
// Definitions (also in README):
//   distance_2d_m   sum over segments of geodesic distances between consecutive points;
//   distance_3d_m   the same with elevation differences where both points have elevation;
//   duration_s      sum over segments of (last - first timestamp); absent without times;
//   elapsed_s       last minus first timestamp over the whole track;
//   moving_time_s   sum of intervals whose speed is at least moving_speed_kmh (pauses excluded);
//   elevation_gain_m / loss_m   hysteresis: a climb or descent counts only once it exceeds
//                   elevation_threshold_m from the last turning point (filters GPS noise);
//   avg_speed_kmh   distance_2d / moving time;  max_speed_kmh, max_climb_ms, max_sink_ms from
//                   the windowed channels of metrics.hpp (robust to single-point spikes).

#include <cstddef>
#include <optional>

#include "geo/bounds.hpp"
#include "track/metrics.hpp"
#include "track/model.hpp"

namespace trailray::track {

struct StatisticsOptions {
  double moving_speed_kmh = 1.0;
  double elevation_threshold_m = 5.0;
};

struct Statistics {
  std::size_t points = 0;
  std::size_t segments = 0;
  double distance_2d_m = 0.0;
  double distance_3d_m = 0.0;
  std::optional<double> duration_s;
  std::optional<double> elapsed_s;
  std::optional<double> moving_time_s;
  std::optional<double> elevation_gain_m;
  std::optional<double> elevation_loss_m;
  std::optional<double> min_elevation_m;
  std::optional<double> max_elevation_m;
  std::optional<double> max_speed_kmh;
  std::optional<double> avg_speed_kmh;
  std::optional<double> max_climb_ms;
  std::optional<double> max_sink_ms;  // positive number: the fastest descent rate
  std::optional<geo::LatLonBounds> bbox;
};

Statistics track_statistics(const Track& track, const TrackMetrics& metrics,
                            const StatisticsOptions& options = {});
Statistics segment_statistics(const Segment& segment, const SegmentMetrics& metrics,
                              const StatisticsOptions& options = {});

}  // namespace trailray::track
