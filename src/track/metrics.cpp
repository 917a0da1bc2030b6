#include "track/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "geo/geodesic.hpp"

namespace trailray::track {
namespace {

// Smallest key difference a rate is divided by: below it the rate is undefined (NaN).
constexpr double kMinTimeSpan_s = 1e-3;
constexpr double kMinDistanceSpan_m = 1e-3;

bool valid_coordinates(const TrackPoint& p) {
  return std::isfinite(p.lat) && std::isfinite(p.lon) && std::abs(p.lat) <= 90.0 && std::abs(p.lon) <= 180.0;
}

double non_negative_or_zero(double v) { return std::isfinite(v) && v > 0.0 ? v : 0.0; }

// For each sample k of one run [a, b) (keys non-decreasing), the window covering
// [key_k - half, key_k + half]: from the nearest sample at or before the left edge to the
// nearest sample at or after the right edge, each strictly before / after key_k, clipped to the
// run. Calls emit(k, first, last). O(b - a): both ends only move forward.
template <class Key, class Emit>
void windows_over_run(std::size_t a, std::size_t b, const Key& key, double half, const Emit& emit) {
  std::size_t p = a;  // samples [a, p): at or before the left edge, strictly before key_k
  std::size_t q = a;  // first sample at or after the right edge, strictly after key_k
  for (std::size_t k = a; k < b; ++k) {
    const double kk = key(k);
    while (p < b && key(p) <= kk - half && key(p) < kk) ++p;
    while (q < b && !(key(q) >= kk + half && key(q) > kk)) ++q;
    emit(k, p > a ? p - 1 : a, q < b ? q : b - 1);
  }
}

// out = d_value / span * scale, unless the span is below min_span or the rate is not finite
// (then out stays NaN).
inline void put_rate(double d_value, double span, double min_span, double scale, double& out) {
  if (span >= min_span) {
    const double rate = d_value / span * scale;
    if (std::isfinite(rate)) out = rate;
  }
}

// The points taking part in one windowed rate, in order, split into runs: a run is a stretch
// whose keys do not go backwards and that contains no pause (see metrics.hpp). When every
// point of the segment takes part (the usual case) the samples are the points themselves and
// only the run boundaries are stored; otherwise keys, values and point indices are gathered.
struct Samples {
  bool direct = true;                   // sample k is point k
  std::vector<double> key, value;       // gathered (not direct) only
  std::vector<std::size_t> point;       // gathered (not direct) only
  std::vector<std::size_t> run_starts;  // first sample of each run, then the sample count
};

// Fills `s` with the points where eligible(i), keyed by key(i) with value(i). A run starts at
// the first sample, where the piece (pause-free stretch: a new one starts at a timed point more
// than max_gap_s after the previous timed point) changes, where the key goes backwards, and,
// for time keys, after a key step longer than max_gap_s.
template <class Eligible, class Key, class Value>
void collect_samples(const std::vector<TrackPoint>& pts, bool all_eligible, const Eligible& eligible, const Key& key,
                     const Value& value, bool time_key, bool pauses, double max_gap_s, Samples& s) {
  const std::size_t n = pts.size();
  s.direct = all_eligible;
  s.key.clear();
  s.value.clear();
  s.point.clear();
  s.run_starts.clear();
  if (!all_eligible) {
    s.key.reserve(n);
    s.value.reserve(n);
    s.point.reserve(n);
  }
  std::size_t count = 0, piece = 0, prev_piece = 0;
  double last_time = kMissing, prev_key = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = pts[i].time;
    if (std::isfinite(t)) {
      if (pauses && !std::isnan(last_time) && t - last_time > max_gap_s) ++piece;
      last_time = t;
    }
    if (!all_eligible && !eligible(i)) continue;
    const double k = key(i);
    const bool start =
        count == 0 || piece != prev_piece || k < prev_key || (time_key && pauses && k - prev_key > max_gap_s);
    if (start) s.run_starts.push_back(count);
    if (!all_eligible) {
      s.key.push_back(k);
      s.value.push_back(value(i));
      s.point.push_back(i);
    }
    prev_piece = piece;
    prev_key = k;
    ++count;
  }
  s.run_starts.push_back(count);
}

template <class Key, class Value>
void windowed_rate(const Samples& s, const Key& key, const Value& value, double half, double min_span, double scale,
                   std::vector<double>& out) {
  for (std::size_t r = 0; r + 1 < s.run_starts.size(); ++r) {
    const std::size_t a = s.run_starts[r], b = s.run_starts[r + 1];
    if (s.direct) {
      windows_over_run(a, b, key, half, [&](std::size_t k, std::size_t first, std::size_t last) {
        put_rate(value(last) - value(first), key(last) - key(first), min_span, scale, out[k]);
      });
    } else {
      windows_over_run(
          a, b, [&](std::size_t k) { return s.key[k]; }, half,
          [&](std::size_t k, std::size_t first, std::size_t last) {
            put_rate(s.value[last] - s.value[first], s.key[last] - s.key[first], min_span, scale, out[s.point[k]]);
          });
    }
  }
}

double half_window(double full) { return std::isfinite(full) && full > 0.0 ? full / 2.0 : 0.0; }

}  // namespace

SegmentMetrics compute_segment_metrics(const Segment& segment, const MetricsOptions& options, double distance_offset_m,
                                       double distance_3d_offset_m, double time_origin_s) {
  const auto& pts = segment.points;
  const std::size_t n = pts.size();
  SegmentMetrics m;
  m.options = options;
  m.distance_m.assign(n, 0.0);
  m.distance_3d_m.assign(n, 0.0);
  m.elapsed_s.assign(n, kMissing);
  m.speed_ms.assign(n, kMissing);
  m.vspeed_ms.assign(n, kMissing);
  m.slope_pct.assign(n, kMissing);
  m.glide_ratio.assign(n, kMissing);
  if (n == 0) return m;

  // Geodesic steps, one per consecutive pair (0 where a coordinate is unusable), stored in
  // distance_m for now. A loop of its own: no chain through the cumulative sums, so the
  // processor overlaps consecutive steps.
  m.distance_m[0] = std::isfinite(distance_offset_m) ? distance_offset_m : 0.0;
  m.distance_3d_m[0] = std::isfinite(distance_3d_offset_m) ? distance_3d_offset_m : 0.0;
  bool prev_valid = valid_coordinates(pts[0]);
  for (std::size_t i = 1; i < n; ++i) {
    const TrackPoint& p = pts[i];
    const TrackPoint& q = pts[i - 1];
    const bool valid = valid_coordinates(p);
    double d2 = 0.0;
    if (valid && prev_valid) {
      d2 = geo::geodesic_distance_m(q.lat, q.lon, p.lat, p.lon);
      if (!std::isfinite(d2)) d2 = 0.0;
    }
    m.distance_m[i] = d2;
    prev_valid = valid;
  }

  // Cumulative distances (3D steps with the elevation difference where both points have one),
  // elapsed time, and the runs used below when every point has a time and an elevation: time
  // runs (a new one after a pause or where the time goes back).
  double origin = time_origin_s;
  if (!std::isfinite(origin)) {
    origin = kMissing;
    for (std::size_t i = 0; i < n && std::isnan(origin); ++i)
      if (std::isfinite(pts[i].time)) origin = pts[i].time;
  }
  const bool pauses = std::isfinite(options.max_gap_s) && options.max_gap_s > 0.0;
  // A pause is a step longer than max_gap_s and than four of the segment's usual steps: a logger
  // that records every two minutes (or a planned route with times) has no pauses between its fixes.
  double max_gap_s = options.max_gap_s;
  if (pauses) {
    std::vector<double> steps;
    double last = kMissing;
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(pts[i].time)) continue;
      if (std::isfinite(last) && pts[i].time > last) steps.push_back(pts[i].time - last);
      last = pts[i].time;
    }
    if (!steps.empty()) {
      const auto middle = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
      std::nth_element(steps.begin(), middle, steps.end());
      max_gap_s = std::max(max_gap_s, 4.0 * *middle);
    }
  }
  std::size_t timed = 0, with_ele = 0, timed_with_ele = 0;
  std::vector<std::size_t> time_runs{0};
  for (std::size_t i = 0; i < n; ++i) {
    const TrackPoint& p = pts[i];
    const bool t_ok = std::isfinite(p.time), e_ok = std::isfinite(p.ele);
    timed += t_ok;
    with_ele += e_ok;
    timed_with_ele += t_ok && e_ok;
    if (t_ok && std::isfinite(origin)) m.elapsed_s[i] = p.time - origin;
    if (i == 0) continue;
    const TrackPoint& q = pts[i - 1];
    const double d2 = m.distance_m[i];
    double d3 = d2;
    if (e_ok && std::isfinite(q.ele)) {
      const double dz = p.ele - q.ele;
      d3 = std::sqrt(d2 * d2 + dz * dz);                // hypot is slow in glibc; it is only
      if (!std::isfinite(d3)) d3 = std::hypot(d2, dz);  // needed where the squares overflow
    }
    m.distance_m[i] = m.distance_m[i - 1] + d2;
    m.distance_3d_m[i] = m.distance_3d_m[i - 1] + (std::isfinite(d3) ? d3 : d2);
    const bool pause = pauses && p.time - q.time > max_gap_s;
    if (pause || p.time < q.time) time_runs.push_back(i);
  }
  time_runs.push_back(n);

  // Windowed rates.
  auto time_of = [&](std::size_t i) { return pts[i].time; };
  auto ele_of = [&](std::size_t i) { return pts[i].ele; };
  auto distance_of = [&](std::size_t i) { return m.distance_m[i]; };
  const double half_time = half_window(options.speed_window_s);
  const double half_slope = half_window(options.slope_window_m);
  if (timed == n && with_ele == n) {
    // The usual case: every point takes part in every rate. Speed and vertical speed share
    // their windows; steepness runs over the whole segment (the cumulative distance never goes
    // back, and a slope is one over distance whatever the time between the fixes).
    for (std::size_t r = 0; r + 1 < time_runs.size(); ++r) {
      windows_over_run(time_runs[r], time_runs[r + 1], time_of, half_time,
                       [&](std::size_t k, std::size_t first, std::size_t last) {
                         const double span = pts[last].time - pts[first].time;
                         put_rate(m.distance_m[last] - m.distance_m[first], span, kMinTimeSpan_s, 1.0, m.speed_ms[k]);
                         put_rate(pts[last].ele - pts[first].ele, span, kMinTimeSpan_s, 1.0, m.vspeed_ms[k]);
                       });
    }
    windows_over_run(0, n, distance_of, half_slope, [&](std::size_t k, std::size_t first, std::size_t last) {
      put_rate(pts[last].ele - pts[first].ele, m.distance_m[last] - m.distance_m[first], kMinDistanceSpan_m, 100.0,
               m.slope_pct[k]);
    });
  } else {
    // Each rate over the points that take part in it. Pieces and runs: see collect_samples.
    auto has_time = [&](std::size_t i) { return std::isfinite(pts[i].time); };
    auto has_ele = [&](std::size_t i) { return std::isfinite(pts[i].ele); };
    Samples samples;

    // Horizontal speed: points with a time; distance over time.
    collect_samples(pts, timed == n, has_time, time_of, distance_of, true, pauses, max_gap_s, samples);
    windowed_rate(samples, time_of, distance_of, half_time, kMinTimeSpan_s, 1.0, m.speed_ms);

    // Vertical speed: points with a time and an elevation.
    collect_samples(
        pts, timed_with_ele == n, [&](std::size_t i) { return has_time(i) && has_ele(i); }, time_of, ele_of, true,
        pauses, max_gap_s, samples);
    windowed_rate(samples, time_of, ele_of, half_time, kMinTimeSpan_s, 1.0, m.vspeed_ms);

    // Steepness: points with an elevation; elevation over horizontal distance, in percent.
    // Steepness never stops at a pause: see above.
    collect_samples(pts, with_ele == n, has_ele, distance_of, ele_of, false, false, max_gap_s, samples);
    windowed_rate(samples, distance_of, ele_of, half_slope, kMinDistanceSpan_m, 100.0, m.slope_pct);
  }

  // Glide ratio while sinking.
  const double min_sink = non_negative_or_zero(options.min_sink_for_glide_ms);
  for (std::size_t i = 0; i < n; ++i) {
    const double sink = -m.vspeed_ms[i];
    if (std::isfinite(m.speed_ms[i]) && std::isfinite(sink) && sink > min_sink && sink > 0.0) {
      const double g = m.speed_ms[i] / sink;
      if (std::isfinite(g)) m.glide_ratio[i] = g;
    }
  }
  return m;
}

TrackMetrics compute_metrics(const Track& track, const MetricsOptions& options) {
  TrackMetrics out;
  out.options = options;
  double origin = kMissing;
  for (const Segment& s : track.segments) {
    for (const TrackPoint& p : s.points) {
      if (std::isfinite(p.time)) {
        origin = p.time;
        break;
      }
    }
    if (!std::isnan(origin)) break;
  }
  out.segments.reserve(track.segments.size());
  double offset = 0.0, offset_3d = 0.0;
  for (const Segment& s : track.segments) {
    out.segments.push_back(compute_segment_metrics(s, options, offset, offset_3d, origin));
    const SegmentMetrics& m = out.segments.back();
    if (!m.distance_m.empty()) {
      offset = m.distance_m.back();
      offset_3d = m.distance_3d_m.back();
    }
  }
  return out;
}

}  // namespace trailray::track
