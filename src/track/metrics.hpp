#pragma once
// Derived per-point channels, computed on the CPU once and used by statistics and (later) the
// renderer's colour attribute. Every value is finite or NaN ("no value": no time, no
// elevation, or undefined like the glide ratio while climbing); never infinite.
//
// Rates are measured over windows, not between two noisy neighbours: speed and vertical speed
// over a centred time window, steepness over a centred horizontal-distance window. Windows
// stay inside one segment and do not stretch across a time gap longer than max_gap_s.

#include <vector>

#include "track/model.hpp"

namespace trailray::track {

struct MetricsOptions {
  double speed_window_s = 10.0;  // centred window for speed and vertical speed
  double slope_window_m = 50.0;  // centred horizontal window for steepness
  double max_gap_s = 60.0;       // a longer interval is a pause: windows do not cross it
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
};

struct TrackMetrics {
  std::vector<SegmentMetrics> segments;  // parallel to Track::segments
};

// Cumulative distance continues across segments (a gap adds nothing).
TrackMetrics compute_metrics(const Track& track, const MetricsOptions& options = {});

}  // namespace trailray::track
