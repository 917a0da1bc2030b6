#pragma once
// Derived per-point channels, computed on the CPU once and used by statistics and the
// renderer's colour attribute. Every value is finite or NaN ("no value": no time, no
// elevation, too little data in the window, or undefined like the glide ratio while
// climbing); never infinite.
//
// Distances: geodesic (WGS84) between consecutive points, computed once per pair. The 3D step
// is sqrt(d2^2 + dz^2) where both points have an elevation, else the 2D step. Cumulative
// distance starts at 0 and continues across segments; a segment gap adds nothing.
//
// Rates are measured over windows, not between two noisy neighbours:
//   speed, vertical speed  centred time window of speed_window_s: [t_i - w/2, t_i + w/2];
//   steepness              centred distance window of slope_window_m: [d_i - w/2, d_i + w/2].
// The rate is (value at the window's last point - value at its first) / (key difference), with
// key = time or cumulative distance. The window reaches out to the nearest point at or beyond
// each edge (strictly before / after the centre point), so it always spans at least the whole
// centred interval where the data allow, and sparse recordings (one point every 10 s with a
// 10 s window) get a centred difference over their neighbours. A window never leaves its run:
// a run is a stretch of one segment whose keys do not go backwards and that contains no pause
// (two timed points more than max_gap_s apart); at a run's ends the window is one-sided.
// Undefined (NaN) when the window has no key difference (< 1 ms or < 1 mm).
// Speed uses the points with a time; vertical speed the points with a time and an elevation;
// steepness the points with an elevation. Glide ratio = speed / sink rate while the sink rate
// (-vertical speed) exceeds min_sink_for_glide_ms, NaN otherwise.

#include <vector>

#include "track/model.hpp"

namespace trailray::track {

struct MetricsOptions {
  double speed_window_s = 10.0;        // centred window for speed and vertical speed (full width)
  double slope_window_m = 50.0;        // centred horizontal window for steepness (full width)
  double max_gap_s = 60.0;             // a longer interval than this and than four of the segment's
                                       // usual (median) intervals is a pause: speed windows do not
                                       // cross it (steepness, over distance, does); <= 0 or not
                                       // finite: no pause detection
  double min_sink_for_glide_ms = 0.1;  // glide ratio only while sinking faster than this
};

// One entry per point, parallel to Segment::points.
struct SegmentMetrics {
  std::vector<double> distance_m;     // cumulative 2D geodesic distance from the track start
  std::vector<double> distance_3d_m;  // cumulative, with elevation differences where known
  std::vector<double> elapsed_s;      // seconds since the track's first timestamp (NaN: no time)
  std::vector<double> speed_ms;       // horizontal speed, m/s
  std::vector<double> vspeed_ms;      // vertical speed, m/s (positive = climbing)
  std::vector<double> slope_pct;      // steepness, percent (rise over run * 100)
  std::vector<double> glide_ratio;    // horizontal over sink speed, while sinking
  MetricsOptions options;             // the options these channels were computed with

  std::size_t size() const { return distance_m.size(); }
};

struct TrackMetrics {
  std::vector<SegmentMetrics> segments;  // parallel to Track::segments
  MetricsOptions options;                // the options these channels were computed with
};

// Cumulative distance continues across segments (a gap adds nothing). Elapsed time counts from
// the track's first timestamp in file order (it can be negative on a raw track whose times jump
// backwards).
TrackMetrics compute_metrics(const Track& track, const MetricsOptions& options = {});

// One segment on its own: cumulative distances start at `distance_offset_m` (2D) and
// `distance_3d_offset_m`, elapsed time counts from `time_origin_s` (NaN: from the segment's
// first timestamp).
SegmentMetrics compute_segment_metrics(const Segment& segment, const MetricsOptions& options = {},
                                       double distance_offset_m = 0.0, double distance_3d_offset_m = 0.0,
                                       double time_origin_s = kMissing);

}  // namespace trailray::track
