// Cleaning step 3 (clean.hpp): the minimum distance between consecutive kept points.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "geo/geodesic.hpp"
#include "track/clean_steps.hpp"

namespace trailray::track::detail {

// Step 3: minimum distance between consecutive kept points; first and last points stay.
// In place: pts[0, kept) are the kept points, the last of them the one compared with. The
// distances between consecutive input points are computed a block ahead, in a loop of their
// own (no dependency between them, so the processor overlaps them); the comparison uses them
// whenever the previous point was kept, which is nearly always.
void enforce_min_distance(std::vector<TrackPoint>& pts, double min_distance_m, CleanReport& report) {
  if (!(min_distance_m > 0.0) || pts.size() < 2) return;
  const std::size_t n = pts.size();
  constexpr std::size_t kBlock = 1024;
  double step[kBlock];
  std::size_t kept = 1;
  bool prev_is_last_kept = true;  // the point before i is pts[kept - 1]
  for (std::size_t start = 1; start < n; start += kBlock) {
    const std::size_t end = std::min(n, start + kBlock);
    // pts[start - 1, end) are all originals here: compaction only wrote below kept <= start.
    for (std::size_t i = start; i < end; ++i)
      step[i - start] = geo::geodesic_distance_m(pts[i - 1].lat, pts[i - 1].lon, pts[i].lat, pts[i].lon);
    for (std::size_t i = start; i < end; ++i) {
      const TrackPoint& p = pts[i];
      const TrackPoint& prev = pts[kept - 1];
      double d = prev_is_last_kept ? step[i - start] : geo::geodesic_distance_m(prev.lat, prev.lon, p.lat, p.lon);
      if (prev.has_ele() && p.has_ele()) {
        const double dz = p.ele - prev.ele;
        const double d3 = std::sqrt(d * d + dz * dz);    // hypot is slow in glibc; it is only
        d = std::isfinite(d3) ? d3 : std::hypot(d, dz);  // needed where the squares overflow
      }
      prev_is_last_kept = true;
      if (d >= min_distance_m) {
        if (kept != i) pts[kept] = p;
        ++kept;
      } else if (i + 1 < n) {
        ++report.too_close;
        prev_is_last_kept = false;
      } else if (kept >= 2) {
        pts[kept - 1] = p;  // the last point replaces the previous kept one
        ++report.too_close;
      } else {
        if (kept != i) pts[kept] = p;  // only the first point before it: keep both
        ++kept;
      }
    }
  }
  pts.resize(kept);
}

}  // namespace trailray::track::detail
