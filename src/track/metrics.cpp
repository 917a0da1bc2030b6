#include "track/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "geo/geodesic.hpp"

namespace trailray::track {
namespace {

// Smallest key difference a rate is divided by: below it the rate is undefined (NaN).
constexpr double kMinTimeSpan_s = 1e-3;
constexpr double kMinDistanceSpan_m = 1e-3;

bool valid_coordinates(const TrackPoint& p) {
  return std::isfinite(p.lat) && std::isfinite(p.lon) && std::abs(p.lat) <= 90.0 &&
         std::abs(p.lon) <= 180.0;
}

// Geodesic step between consecutive points; 0 where a coordinate is unusable.
double step_2d_m(const TrackPoint& a, const TrackPoint& b) {
  if (!valid_coordinates(a) || !valid_coordinates(b)) return 0.0;
  const double d = geo::geodesic_distance_m(a.lat, a.lon, b.lat, b.lon);
  return std::isfinite(d) ? d : 0.0;
}

double non_negative_or_zero(double v) { return std::isfinite(v) && v > 0.0 ? v : 0.0; }

// One point taking part in a windowed rate: its window coordinate (time or cumulative
// distance), the value whose rate is measured, and whether a new run starts at it.
struct Sample {
  double key;
  double value;
  std::size_t point;
  bool run_start;
};

// out[sample.point] = d value / d key over the window covering [key_i - half, key_i + half]:
// from the nearest point at or before the left edge to the nearest point at or after the right
// edge, each strictly before / after key_i, clipped to the run. O(n): both ends only move forward.
void windowed_rate(const std::vector<Sample>& s, double half, double min_span, double scale,
                   std::vector<double>& out) {
  const std::size_t n = s.size();
  std::size_t a = 0;
  while (a < n) {
    std::size_t b = a + 1;
    while (b < n && !s[b].run_start) ++b;
    std::size_t p = a;  // s[a, p): the points at or before the left edge, strictly before key_i
    std::size_t q = a;  // first point at or after the right edge, strictly after key_i
    for (std::size_t k = a; k < b; ++k) {
      const double key = s[k].key;
      while (p < b && s[p].key <= key - half && s[p].key < key) ++p;
      while (q < b && !(s[q].key >= key + half && s[q].key > key)) ++q;
      const std::size_t first = p > a ? p - 1 : a;
      const std::size_t last = q < b ? q : b - 1;
      const double span = s[last].key - s[first].key;
      if (span >= min_span) {
        const double rate = (s[last].value - s[first].value) / span * scale;
        if (std::isfinite(rate)) out[s[k].point] = rate;
      }
    }
    a = b;
  }
}

double half_window(double full) { return std::isfinite(full) && full > 0.0 ? full / 2.0 : 0.0; }

}  // namespace

SegmentMetrics compute_segment_metrics(const Segment& segment, const MetricsOptions& options,
                                       double distance_offset_m, double distance_3d_offset_m,
                                       double time_origin_s) {
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

  auto has_time = [&](std::size_t i) { return std::isfinite(pts[i].time); };
  auto has_ele = [&](std::size_t i) { return std::isfinite(pts[i].ele); };

  // Cumulative distances: one geodesic per consecutive pair.
  m.distance_m[0] = std::isfinite(distance_offset_m) ? distance_offset_m : 0.0;
  m.distance_3d_m[0] = std::isfinite(distance_3d_offset_m) ? distance_3d_offset_m : 0.0;
  for (std::size_t i = 1; i < n; ++i) {
    const double d2 = step_2d_m(pts[i - 1], pts[i]);
    double d3 = d2;
    if (has_ele(i - 1) && has_ele(i)) d3 = std::hypot(d2, pts[i].ele - pts[i - 1].ele);
    m.distance_m[i] = m.distance_m[i - 1] + d2;
    m.distance_3d_m[i] = m.distance_3d_m[i - 1] + (std::isfinite(d3) ? d3 : d2);
  }

  // Elapsed time.
  double origin = time_origin_s;
  if (!std::isfinite(origin)) {
    origin = kMissing;
    for (std::size_t i = 0; i < n && std::isnan(origin); ++i)
      if (has_time(i)) origin = pts[i].time;
  }
  for (std::size_t i = 0; i < n; ++i)
    if (has_time(i) && std::isfinite(origin)) m.elapsed_s[i] = pts[i].time - origin;

  // Pieces: a new piece starts at a timed point more than max_gap_s after the previous timed point.
  const bool pauses = std::isfinite(options.max_gap_s) && options.max_gap_s > 0.0;
  std::vector<std::size_t> piece(n, 0);
  {
    std::size_t id = 0;
    double last_time = kMissing;
    for (std::size_t i = 0; i < n; ++i) {
      if (has_time(i)) {
        if (pauses && !std::isnan(last_time) && pts[i].time - last_time > options.max_gap_s) ++id;
        last_time = pts[i].time;
      }
      piece[i] = id;
    }
  }

  std::vector<Sample> samples;
  samples.reserve(n);
  auto build = [&](auto eligible, auto key, auto value, bool time_key) {
    samples.clear();
    for (std::size_t i = 0; i < n; ++i) {
      if (!eligible(i)) continue;
      const double k = key(i);
      bool start = samples.empty();
      if (!start) {
        const Sample& prev = samples.back();
        start = piece[prev.point] != piece[i] || k < prev.key ||
                (time_key && pauses && k - prev.key > options.max_gap_s);
      }
      samples.push_back(Sample{k, value(i), i, start});
    }
  };

  const double half_time = half_window(options.speed_window_s);
  // Horizontal speed: points with a time; distance over time.
  build(has_time, [&](std::size_t i) { return pts[i].time; }, [&](std::size_t i) { return m.distance_m[i]; },
        true);
  windowed_rate(samples, half_time, kMinTimeSpan_s, 1.0, m.speed_ms);

  // Vertical speed: points with a time and an elevation.
  build([&](std::size_t i) { return has_time(i) && has_ele(i); }, [&](std::size_t i) { return pts[i].time; },
        [&](std::size_t i) { return pts[i].ele; }, true);
  windowed_rate(samples, half_time, kMinTimeSpan_s, 1.0, m.vspeed_ms);

  // Steepness: points with an elevation; elevation over horizontal distance, in percent.
  build(has_ele, [&](std::size_t i) { return m.distance_m[i]; }, [&](std::size_t i) { return pts[i].ele; },
        false);
  windowed_rate(samples, half_window(options.slope_window_m), kMinDistanceSpan_m, 100.0, m.slope_pct);

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
