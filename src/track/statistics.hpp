#pragma once
// Summary figures of a track or one segment, the numbers `trailray stats` prints.
// Definitions (also in README). "Timed point": a point with a timestamp. Segment gaps are never
// measured: nothing is added between the last point of one segment and the first of the next.
//   points, segments  all points; all segments, empty ones included;
//   distance_2d_m   sum over segments of the WGS84 geodesic distances between consecutive points;
//   distance_3d_m   the same, each step sqrt(d^2 + dz^2) where both points have an elevation;
//   duration_s      sum over segments of (last - first timestamp), taking each segment's first
//                   and last timed points (a segment whose last time is before its first adds
//                   0); absent when no segment has two timed points. Equal to gpxpy's sum of
//                   segment durations wherever gpxpy finds a time (it only looks at the first
//                   two and the last two points of a segment);
//   elapsed_s       last minus first timestamp (file order) over the whole track; absent with
//                   fewer than two timed points;
//   moving_time_s   sum of the intervals between consecutive timed points of a segment whose
//                   speed is at least moving_speed_kmh. An interval up to max_gap_s long (the
//                   metrics' pause limit) takes the mean of the windowed speeds (metrics.hpp) at
//                   its two ends, robust to jitter while standing; a longer one (a pause, lost
//                   signal, a sparse logger) its own distance / dt, so a 3-hour stop counts
//                   nothing and 3 hours of flight logged every 20 minutes count in full. On a raw
//                   track whose time jumps backwards an interval only adds the time beyond the
//                   latest timestamp so far, so no second counts twice. Absent like duration_s;
//   elevation_gain_m / loss_m   per segment over the points with an elevation, with hysteresis:
//                   a climb (descent) counts only once the elevation has risen (fallen) more
//                   than elevation_threshold_m above (below) the last turning point (at the
//                   segment's start: the lowest / highest elevation so far), and then
//                   counts from that turning point to the next confirmed one (or to the highest
//                   / lowest point reached at the segment's end); wiggles smaller than the
//                   threshold count nothing. Absent when no segment has two elevations;
//   min/max_elevation_m   over all points with an elevation;
//   max_speed_kmh   largest windowed speed;  avg_speed_kmh  distance covered in the moving intervals / moving time
//   (absent
//                   when the moving time is 0 or absent);
//   max_climb_ms, max_sink_ms   largest windowed vertical speed upwards / downwards (the sink as
//                   a positive number, 0 when the track never descends); the windowed
//                   channels damp single-point spikes;
//   bbox            latitude/longitude bounds of all points.
// Absent values are std::nullopt (JSON null); no field is ever NaN or infinite.

#include <cstddef>
#include <optional>
#include <vector>

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

// `metrics` should come from compute_metrics(track); a segment whose metrics do not match its
// point count is measured with freshly computed metrics (with metrics.options).
Statistics track_statistics(const Track& track, const TrackMetrics& metrics, const StatisticsOptions& options = {});
Statistics segment_statistics(const Segment& segment, const SegmentMetrics& metrics,
                              const StatisticsOptions& options = {});

// Elevation gain and loss of a sequence of elevations (NaN entries skipped) with the hysteresis
// rule above. Returns {gain, loss}, both >= 0.
struct GainLoss {
  double gain_m = 0.0;
  double loss_m = 0.0;
};
GainLoss elevation_gain_loss(const std::vector<double>& elevations, double threshold_m);

}  // namespace trailray::track
