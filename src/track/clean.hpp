#pragma once
// Cleaning a track for display and measurement (thesis §3.2.1, improved): per segment, never
// across a segment gap.
//   1. drop points with invalid coordinates (defensive; readers already drop them);
//   2. drop points whose timestamp is not after the previous kept point's (duplicates and
//      backward jumps), so no speed downstream divides by zero or goes negative;
//   3. enforce a minimum distance between consecutive kept points (repeated positions and
//      jitter while standing); a segment's last point is always kept;
//   4. Gaussian smoothing of position and altitude (half-width N, sigma) in a local metric
//      frame, with the kernel renormalised at segment ends so ends are not pulled inward.
// Every dropped or repaired point is counted in CleanReport.

#include <cstddef>

#include "track/model.hpp"

namespace trailray::track {

struct CleanOptions {
  double min_distance_m = 3.0;  // 0 disables
  bool smooth = true;
  int smooth_half_width = 5;    // N: the kernel spans 2N+1 points
  double smooth_sigma = 1.0;    // in points
};

struct CleanReport {
  std::size_t invalid_coordinates = 0;
  std::size_t non_increasing_time = 0;  // duplicate or backward timestamps dropped
  std::size_t too_close = 0;            // dropped by the minimum distance
  std::size_t total_dropped() const { return invalid_coordinates + non_increasing_time + too_close; }
};

// A cleaned copy of `track` with the same number of segments (a segment may become empty).
Track clean_track(const Track& track, const CleanOptions& options, CleanReport& report);

}  // namespace trailray::track
