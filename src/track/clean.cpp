#include "track/clean.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geo/geodesic.hpp"
#include "geo/local_frame.hpp"

namespace trailray::track {
namespace {

bool valid_coordinates(const TrackPoint& p) {
  return std::isfinite(p.lat) && std::isfinite(p.lon) && std::abs(p.lat) <= 90.0 &&
         std::abs(p.lon) <= 180.0;
}

// A segment whose clock never advances: at least 3 timestamps spanning less than 1 ms per point
// (no GPS logs at 1 kHz; seen with placeholder times such as 1901-12-13T20:45:52Z).
bool frozen_clock(const std::vector<TrackPoint>& in) {
  std::size_t timed = 0;
  double lo = 0.0, hi = 0.0;
  for (const TrackPoint& p : in) {
    if (!valid_coordinates(p) || !std::isfinite(p.time)) continue;
    lo = timed == 0 ? p.time : std::min(lo, p.time);
    hi = timed == 0 ? p.time : std::max(hi, p.time);
    ++timed;
  }
  return timed >= 3 && hi - lo < 1e-3 * static_cast<double>(timed - 1);
}

bool same_fix(const TrackPoint& a, const TrackPoint& b) {
  const bool same_ele = a.ele == b.ele || (std::isnan(a.ele) && std::isnan(b.ele));
  return a.time == b.time && a.lat == b.lat && a.lon == b.lon && same_ele;
}

// Step 2b: runs of one timestamp at different places get evenly spread times over the
// interval to the next later timestamp (at most 1 s: loggers stamp whole seconds). Real runs
// are up to 10 long (10 Hz loggers); a longer run than kMaxFixesPerSecond is a stuck clock
// (seen: 51 fixes, 30 m apart, all stamped 10:24:03) and loses its times instead.
constexpr std::size_t kMaxFixesPerSecond = 20;

void spread_same_second_runs(std::vector<TrackPoint>& pts, CleanReport& report) {
  std::size_t i = 0;
  while (i < pts.size()) {
    if (!pts[i].has_time()) {
      ++i;
      continue;
    }
    const double t = pts[i].time;
    std::size_t end = i + 1;
    while (end < pts.size() && pts[end].time == t) ++end;
    const std::size_t run = end - i;
    if (run > kMaxFixesPerSecond) {
      // No logger writes that many fixes in one second: the clock stood still. Keep the
      // places, drop the made-up times.
      for (std::size_t k = 1; k < run; ++k) pts[i + k].time = kMissing;
      report.frozen_time += run - 1;
    } else if (run >= 2) {
      double next = kMissing;
      for (std::size_t k = end; k < pts.size(); ++k)
        if (pts[k].has_time()) {
          next = pts[k].time;
          break;
        }
      const double span = std::isnan(next) || next <= t ? 1.0 : std::min(next - t, 1.0);
      for (std::size_t k = 1; k < run; ++k) pts[i + k].time = t + span * static_cast<double>(k) / static_cast<double>(run);
      report.spread_time += run - 1;
    }
    i = end;
  }
}

// Steps 1 and 2: invalid coordinates, non-finite values, duplicates, same-second runs,
// non-increasing timestamps.
std::vector<TrackPoint> drop_invalid_and_unordered(const std::vector<TrackPoint>& in, CleanReport& report) {
  const bool frozen = frozen_clock(in);
  std::vector<TrackPoint> valid;
  valid.reserve(in.size());
  for (TrackPoint p : in) {
    if (!valid_coordinates(p)) {
      ++report.invalid_coordinates;
      continue;
    }
    const bool repaired = std::isinf(p.ele) || std::isinf(p.time);
    if (std::isinf(p.ele)) p.ele = kMissing;
    if (std::isinf(p.time)) p.time = kMissing;
    if (repaired) ++report.invalid_values;
    if (frozen && p.has_time()) {
      p.time = kMissing;
      ++report.frozen_time;
    }
    if (!valid.empty() && p.has_time() && same_fix(valid.back(), p)) {
      ++report.duplicate_points;
      continue;
    }
    valid.push_back(p);
  }
  spread_same_second_runs(valid, report);

  std::vector<TrackPoint> out;
  out.reserve(valid.size());
  double last_time = kMissing;  // the last kept timestamp of this segment
  for (const TrackPoint& p : valid) {
    if (p.has_time()) {
      if (!std::isnan(last_time) && !(p.time > last_time)) {
        ++report.non_increasing_time;
        continue;
      }
      last_time = p.time;
    }
    out.push_back(p);
  }
  return out;
}

// Step 3: minimum distance between consecutive kept points; first and last points stay.
std::vector<TrackPoint> enforce_min_distance(const std::vector<TrackPoint>& in, double min_distance_m,
                                             CleanReport& report) {
  if (!(min_distance_m > 0.0) || in.size() < 2) return in;
  std::vector<TrackPoint> out;
  out.reserve(in.size());
  out.push_back(in.front());
  for (std::size_t i = 1; i < in.size(); ++i) {
    const TrackPoint& p = in[i];
    const TrackPoint& prev = out.back();
    double d = geo::geodesic_distance_m(prev.lat, prev.lon, p.lat, p.lon);
    if (prev.has_ele() && p.has_ele()) d = std::hypot(d, p.ele - prev.ele);
    if (d >= min_distance_m) {
      out.push_back(p);
    } else if (i + 1 < in.size()) {
      ++report.too_close;
    } else if (out.size() >= 2) {
      out.back() = p;  // the last point replaces the previous kept one
      ++report.too_close;
    } else {
      out.push_back(p);  // only the first point before it: keep both
    }
  }
  return out;
}

// Step 4: Gaussian smoothing with a symmetric, renormalised kernel over pts[first, last).
void smooth_gaussian(std::vector<TrackPoint>& pts, std::size_t first, std::size_t last, int half_width,
                     double sigma) {
  const std::size_t n = last - first;
  if (n < 3 || half_width <= 0 || !(sigma > 0.0) || !std::isfinite(sigma)) return;
  const std::size_t half = static_cast<std::size_t>(half_width);

  std::vector<double> weight(half + 1);
  for (std::size_t j = 0; j <= half; ++j) {
    const double x = static_cast<double>(j);
    weight[j] = std::exp(-x * x / (2.0 * sigma * sigma));
  }

  const TrackPoint& origin = pts[first];
  const double h0 = origin.has_ele() ? origin.ele : 0.0;
  const geo::LocalFrame frame(origin.lat, origin.lon, h0);
  std::vector<geo::Enu> enu(n);
  std::vector<double> ele(n);
  for (std::size_t i = 0; i < n; ++i) {
    enu[i] = frame.to_local(pts[first + i].lat, pts[first + i].lon, h0);
    ele[i] = pts[first + i].ele;
  }

  for (std::size_t i = 1; i + 1 < n; ++i) {
    const std::size_t k = std::min({half, i, n - 1 - i});
    geo::Enu sum;
    double wsum = 0.0, ele_sum = 0.0, ele_wsum = 0.0;
    for (std::size_t j = i - k; j <= i + k; ++j) {
      const double w = weight[j > i ? j - i : i - j];
      sum.east += w * enu[j].east;
      sum.north += w * enu[j].north;
      sum.up += w * enu[j].up;
      wsum += w;
      if (!std::isnan(ele[j])) {
        ele_sum += w * ele[j];
        ele_wsum += w;
      }
    }
    TrackPoint& p = pts[first + i];
    const geo::Enu mean{sum.east / wsum, sum.north / wsum, sum.up / wsum};
    double h = 0.0;
    frame.to_geodetic(mean, p.lat, p.lon, h);
    if (p.has_ele()) p.ele = ele_sum / ele_wsum;  // ele_wsum includes the point itself
  }
}

// Smooths each stretch between pauses (timed points more than max_gap_s apart) on its own.
void smooth_pieces(std::vector<TrackPoint>& pts, const CleanOptions& o) {
  const bool pauses = std::isfinite(o.max_gap_s) && o.max_gap_s > 0.0;
  std::size_t start = 0;
  double last_time = kMissing;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!pts[i].has_time()) continue;
    if (pauses && !std::isnan(last_time) && pts[i].time - last_time > o.max_gap_s) {
      smooth_gaussian(pts, start, i, o.smooth_half_width, o.smooth_sigma);
      start = i;
    }
    last_time = pts[i].time;
  }
  smooth_gaussian(pts, start, pts.size(), o.smooth_half_width, o.smooth_sigma);
}

}  // namespace

Segment clean_segment(const Segment& segment, const CleanOptions& options, CleanReport& report) {
  Segment out;
  out.points = drop_invalid_and_unordered(segment.points, report);
  out.points = enforce_min_distance(out.points, options.min_distance_m, report);
  if (options.smooth) smooth_pieces(out.points, options);
  return out;
}

Track clean_track(const Track& track, const CleanOptions& options, CleanReport& report) {
  Track out;
  out.name = track.name;
  out.description = track.description;
  out.type = track.type;
  out.segments.reserve(track.segments.size());
  for (const Segment& s : track.segments) out.segments.push_back(clean_segment(s, options, report));
  return out;
}

}  // namespace trailray::track
