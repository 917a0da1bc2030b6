#pragma once
// Cleaning a track for display and measurement (thesis §3.2.1, improved): per segment, never
// across a segment gap. In this order:
//   1. drop points with invalid coordinates (latitude or longitude not finite, |lat| > 90,
//      |lon| > 180; defensive, readers already drop them). A non-finite elevation or time
//      becomes "missing" (NaN) and the point is kept.
//   2. drop points whose timestamp is not strictly after the last kept timestamp of the
//      segment (duplicates and backward jumps), so no speed downstream divides by zero or goes
//      negative. Points without a time are kept.
//   3. enforce a minimum geodesic distance between consecutive kept points (repeated positions
//      and jitter while standing). The segment's last point is always kept: when it is too
//      close to the previous kept point, it replaces that point, unless that point is the
//      segment's first (then both stay). The first point is always kept.
//   4. Gaussian smoothing, weights exp(-j^2 / (2 sigma^2)) for offsets j = -N..N (in points):
//      - positions in a local east-north-up frame (geo::LocalFrame) with its origin at the
//        segment's first point; every point is projected at the origin's height, so the
//        horizontal result does not depend on which points have an elevation; east, north and
//        up are averaged, then converted back to latitude and longitude;
//      - elevation (the "up" axis) averaged over the neighbours that have one; a point without
//        elevation stays without;
//      - near a segment end the kernel is truncated symmetrically to the neighbours that exist
//        on both sides (half-width min(N, i, n-1-i)) and renormalised (divided by the sum of
//        the weights used), so ends are not pulled inward: a segment's first and last points
//        stay where they are and a straight, evenly sampled line stays straight and in place.
//      Segments of one or two points are unchanged by smoothing.
// Times and the recorded extension channels are carried over unchanged.
// Every dropped or repaired point is counted in CleanReport.

#include <cstddef>

#include "track/model.hpp"

namespace trailray::track {

struct CleanOptions {
  double min_distance_m = 3.0;  // 0 disables
  bool smooth = true;
  int smooth_half_width = 5;    // N: the kernel spans 2N+1 points; 0 disables smoothing
  double smooth_sigma = 1.0;    // in points; <= 0 disables smoothing
};

struct CleanReport {
  std::size_t invalid_coordinates = 0;
  std::size_t non_increasing_time = 0;  // duplicate or backward timestamps dropped
  std::size_t too_close = 0;            // dropped by the minimum distance
  std::size_t invalid_values = 0;       // kept points whose non-finite elevation/time became missing
  std::size_t total_dropped() const { return invalid_coordinates + non_increasing_time + too_close; }
};

// A cleaned copy of `track` with the same number of segments (a segment may become empty).
// Adds to `report` (does not reset it), so one report can cover several tracks.
Track clean_track(const Track& track, const CleanOptions& options, CleanReport& report);

// Cleans one segment (steps 1-4 above), adding to `report`.
Segment clean_segment(const Segment& segment, const CleanOptions& options, CleanReport& report);

}  // namespace trailray::track
