#pragma once
// Cleaning a track for display and measurement (thesis §3.2.1, improved): per segment, never
// across a segment gap. In this order:
//   1. drop points with invalid coordinates (latitude or longitude not finite, |lat| > 90,
//      |lon| > 180; defensive, readers already drop them). A non-finite elevation or time
//      becomes "missing" (NaN) and the point is kept.
//   2. timestamps, so that no speed downstream divides by zero or goes negative:
//      a. drop exact duplicates: a point with the same time and position as the one before;
//      b. spread same-second runs: loggers that record several fixes per second but stamp
//         whole seconds (a 10 Hz SkyTraq, XCTrack) write runs of one timestamp at different
//         places; their times are spread evenly over the interval to the next timestamp (at
//         most 1 s), keeping the geometry instead of dropping nine points in ten. A run longer
//         than 20 (no logger writes 20 fixes a second) is a stuck clock: the places are kept,
//         the repeated times removed (counted as frozen_time);
//      c. drop points whose timestamp is not strictly after the last kept timestamp of the
//         segment (backward jumps). Points without a time are kept. Exception, a frozen clock: when a segment's
//      timestamps (at least 3) span less than 1 ms per point, they are placeholders (such as
//      1901-12-13T20:45:52Z); its times are removed and its points kept.
//   3. enforce a minimum distance between consecutive kept points (repeated positions and
//      jitter while standing): the geodesic distance, combined with the elevation difference
//      (sqrt(d^2 + dz^2)) where both points have an elevation, so that a vertical climb (a
//      drone, a balloon, a thermal) is not collapsed. The segment's first point is always
//      kept, and so is its last: when it is too close to the previous kept point, it replaces
//      that point, unless that point is the segment's first (then both stay).
//   4. Gaussian smoothing, weights exp(-j^2 / (2 sigma^2)) for offsets j = -N..N (in points):
//      - positions averaged as 3D points on the ellipsoid (as in a local east-north-up frame;
//        every point taken at height 0, so the horizontal result does not depend on which
//        points have an elevation), the mean projected back onto the ellipsoid. Computed per
//        point in closed form from the moments of the neighbours' latitude/longitude offsets
//        (geo::local_mean_offset: within 0.1 mm of the exact 3D mean); a window reaching
//        further than geo::kLocalMeanMaxOffsetDeg, or near a pole, averages ECEF coordinates;
//      - elevation (the "up" axis) averaged over the neighbours that have one; a point without
//        elevation stays without; the IGC pressure and GNSS altitudes likewise, each on its own
//        (so a flight's two altitudes stay comparable, and equal `ele` where it is one of them);
//      - near a segment end the kernel is truncated symmetrically to the neighbours that exist
//        on both sides (half-width min(N, i, n-1-i)) and renormalised (divided by the sum of
//        the weights used), so ends are not pulled inward: a segment's first and last points
//        stay where they are and a straight, evenly sampled line stays straight and in place.
//      The kernel does not cross a pause or a loss of signal either: timed points more than
//      max_gap_s apart split the segment into stretches that are smoothed on their own (the
//      points on either side of the pause stay where they are), so positions kilometres apart
//      in time are never averaged. Stretches of one or two points are unchanged by smoothing.
// Times and the recorded extension channels (heart rate, cadence, ...) are carried over unchanged.
// Every dropped or repaired point is counted in CleanReport.

#include <cstddef>

#include "track/model.hpp"

namespace trailray::track {

struct CleanOptions {
  double min_distance_m = 3.0;  // 0 disables
  bool smooth = true;
  int smooth_half_width = 5;  // N: the kernel spans 2N+1 points; 0 disables smoothing
  double smooth_sigma = 1.0;  // in points; <= 0 disables smoothing
  double max_gap_s = 60.0;    // smoothing does not cross a longer interval; <= 0: no limit
                              // (same meaning as MetricsOptions::max_gap_s)
};

struct CleanReport {
  std::size_t invalid_coordinates = 0;
  std::size_t duplicate_points = 0;     // exact repeats (same time and position) dropped
  std::size_t spread_time = 0;          // same-second points given spread sub-second times (kept)
  std::size_t non_increasing_time = 0;  // backward (or still repeated) timestamps dropped
  std::size_t too_close = 0;            // dropped by the minimum distance
  std::size_t invalid_values = 0;       // kept points whose non-finite elevation/time became missing
  std::size_t frozen_time = 0;          // points whose placeholder timestamp was removed (kept)
  std::size_t total_dropped() const { return invalid_coordinates + duplicate_points + non_increasing_time + too_close; }
};

// A cleaned copy of `track` with the same number of segments (a segment may become empty).
// Adds to `report` (does not reset it), so one report can cover several tracks.
Track clean_track(const Track& track, const CleanOptions& options, CleanReport& report);

// Cleans one segment (steps 1-4 above), adding to `report`.
Segment clean_segment(const Segment& segment, const CleanOptions& options, CleanReport& report);

}  // namespace trailray::track
