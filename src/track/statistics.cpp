#include "track/statistics.hpp"

#include <algorithm>
#include <cmath>

namespace trailray::track {
namespace {

constexpr double kMsToKmh = 3.6;

bool valid_coordinates(const TrackPoint& p) {
  return std::isfinite(p.lat) && std::isfinite(p.lon) && std::abs(p.lat) <= 90.0 &&
         std::abs(p.lon) <= 180.0;
}

bool matches(const SegmentMetrics& m, std::size_t n) {
  return m.distance_m.size() == n && m.distance_3d_m.size() == n && m.elapsed_s.size() == n &&
         m.speed_ms.size() == n && m.vspeed_ms.size() == n && m.slope_pct.size() == n &&
         m.glide_ratio.size() == n;
}

std::optional<double> finite_or_null(std::optional<double> v) {
  return v && std::isfinite(*v) ? v : std::nullopt;
}

void keep_max(std::optional<double>& current, double v) {
  if (std::isfinite(v) && (!current || v > *current)) current = v;
}
void keep_min(std::optional<double>& current, double v) {
  if (std::isfinite(v) && (!current || v < *current)) current = v;
}

// Sums over segments, then turned into Statistics.
class Accumulator {
 public:
  explicit Accumulator(const StatisticsOptions& options) : options_(options) {}

  void add(const Segment& segment, const SegmentMetrics& given) {
    const auto& pts = segment.points;
    const std::size_t n = pts.size();
    ++s_.segments;
    s_.points += n;
    if (n == 0) return;
    SegmentMetrics own;
    const SegmentMetrics* mp = &given;
    if (!matches(given, n)) {
      own = compute_segment_metrics(segment, given.options);
      mp = &own;
    }
    const SegmentMetrics& m = *mp;

    const double d2 = m.distance_m.back() - m.distance_m.front();
    const double d3 = m.distance_3d_m.back() - m.distance_3d_m.front();
    if (std::isfinite(d2) && d2 > 0.0) s_.distance_2d_m += d2;
    if (std::isfinite(d3) && d3 > 0.0) s_.distance_3d_m += d3;

    add_times(pts, m);
    add_elevations(pts);
    for (std::size_t i = 0; i < n; ++i) {
      if (valid_coordinates(pts[i])) bbox_.add(pts[i].lat, pts[i].lon);
      keep_max(max_speed_ms_, m.speed_ms[i]);
      keep_max(max_vspeed_ms_, m.vspeed_ms[i]);
      keep_min(min_vspeed_ms_, m.vspeed_ms[i]);
    }
  }

  Statistics result() const {
    Statistics s = s_;
    if (timed_segments_ > 0) {
      s.duration_s = duration_s_;
      s.moving_time_s = moving_time_s_;
    }
    if (timed_points_ >= 2) s.elapsed_s = last_time_ - first_time_;
    if (elevation_segments_ > 0) {
      s.elevation_gain_m = gain_m_;
      s.elevation_loss_m = loss_m_;
    }
    if (max_speed_ms_) s.max_speed_kmh = *max_speed_ms_ * kMsToKmh;
    if (s.moving_time_s && *s.moving_time_s > 0.0)
      s.avg_speed_kmh = moving_distance_m_ / *s.moving_time_s * kMsToKmh;
    if (max_vspeed_ms_) s.max_climb_ms = std::max(0.0, *max_vspeed_ms_);
    if (min_vspeed_ms_) s.max_sink_ms = std::max(0.0, -*min_vspeed_ms_);
    if (!bbox_.empty()) s.bbox = bbox_;

    for (auto* v : {&s.duration_s, &s.elapsed_s, &s.moving_time_s, &s.elevation_gain_m, &s.elevation_loss_m,
                    &s.min_elevation_m, &s.max_elevation_m, &s.max_speed_kmh, &s.avg_speed_kmh,
                    &s.max_climb_ms, &s.max_sink_ms})
      *v = finite_or_null(*v);
    if (!std::isfinite(s.distance_2d_m)) s.distance_2d_m = 0.0;
    if (!std::isfinite(s.distance_3d_m)) s.distance_3d_m = 0.0;
    return s;
  }

 private:
  void add_times(const std::vector<TrackPoint>& pts, const SegmentMetrics& m) {
    const bool pauses = std::isfinite(m.options.max_gap_s) && m.options.max_gap_s > 0.0;
    const double min_speed_ms = options_.moving_speed_kmh / kMsToKmh;
    std::size_t timed = 0, prev = 0;
    double seg_first = 0.0, seg_last = 0.0;
    double latest = 0.0;  // the latest time seen in this segment: backward jumps add no time twice
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double t = pts[i].time;
      if (!std::isfinite(t)) continue;
      if (timed_points_++ == 0) first_time_ = t;
      last_time_ = t;
      if (timed++ == 0) {
        seg_first = latest = t;
      } else {
        const double dt = t - latest;  // time newly covered; = t - previous time on a clean track
        if (dt > 0.0) {
          // Short intervals use the windowed speeds (robust to jitter); an interval longer than
          // the pause limit (a pause, lost signal, or a sparse logger) its own distance / dt.
          const double step_m = m.distance_m[i] - m.distance_m[prev];
          const double own = step_m / (t - pts[prev].time);
          const bool long_interval = pauses && t - pts[prev].time > m.options.max_gap_s;
          double v = long_interval ? own : 0.5 * (m.speed_ms[prev] + m.speed_ms[i]);
          if (!std::isfinite(v)) v = own;
          if (v >= min_speed_ms) {
            moving_time_s_ += dt;
            moving_distance_m_ += step_m;
          }
        }
        latest = std::max(latest, t);
      }
      seg_last = t;
      prev = i;
    }
    if (timed >= 2) {
      ++timed_segments_;
      duration_s_ += std::max(0.0, seg_last - seg_first);
    }
  }

  void add_elevations(const std::vector<TrackPoint>& pts) {
    std::vector<double> ele;
    ele.reserve(pts.size());
    for (const TrackPoint& p : pts) {
      if (!std::isfinite(p.ele)) continue;
      ele.push_back(p.ele);
      keep_min(s_.min_elevation_m, p.ele);
      keep_max(s_.max_elevation_m, p.ele);
    }
    if (ele.size() < 2) return;
    ++elevation_segments_;
    const GainLoss gl = elevation_gain_loss(ele, options_.elevation_threshold_m);
    gain_m_ += gl.gain_m;
    loss_m_ += gl.loss_m;
  }

  StatisticsOptions options_;
  Statistics s_;
  geo::LatLonBounds bbox_;
  std::size_t timed_points_ = 0, timed_segments_ = 0, elevation_segments_ = 0;
  double first_time_ = 0.0, last_time_ = 0.0;
  double duration_s_ = 0.0, moving_time_s_ = 0.0, moving_distance_m_ = 0.0;
  double gain_m_ = 0.0, loss_m_ = 0.0;
  std::optional<double> max_speed_ms_, max_vspeed_ms_, min_vspeed_ms_;
};

}  // namespace

GainLoss elevation_gain_loss(const std::vector<double>& elevations, double threshold_m) {
  const double threshold = std::isfinite(threshold_m) && threshold_m > 0.0 ? threshold_m : 0.0;
  GainLoss r;
  enum class Trend { Unknown, Up, Down } trend = Trend::Unknown;
  bool started = false;
  double low = 0.0, high = 0.0;        // range seen while the trend is unknown
  double anchor = 0.0, extreme = 0.0;  // last turning point; furthest point of the current trend
  for (const double e : elevations) {
    if (!std::isfinite(e)) continue;
    if (!started) {
      low = high = e;
      started = true;
      continue;
    }
    switch (trend) {
      case Trend::Unknown:
        low = std::min(low, e);
        high = std::max(high, e);
        if (e - low > threshold) {
          trend = Trend::Up;
          anchor = low;
          extreme = e;
        } else if (high - e > threshold) {
          trend = Trend::Down;
          anchor = high;
          extreme = e;
        }
        break;
      case Trend::Up:
        if (e > extreme) {
          extreme = e;
        } else if (extreme - e > threshold) {
          r.gain_m += extreme - anchor;
          trend = Trend::Down;
          anchor = extreme;
          extreme = e;
        }
        break;
      case Trend::Down:
        if (e < extreme) {
          extreme = e;
        } else if (e - extreme > threshold) {
          r.loss_m += anchor - extreme;
          trend = Trend::Up;
          anchor = extreme;
          extreme = e;
        }
        break;
    }
  }
  if (trend == Trend::Up) r.gain_m += extreme - anchor;
  if (trend == Trend::Down) r.loss_m += anchor - extreme;
  return r;
}

Statistics track_statistics(const Track& track, const TrackMetrics& metrics, const StatisticsOptions& options) {
  Accumulator acc(options);
  for (std::size_t i = 0; i < track.segments.size(); ++i) {
    if (i < metrics.segments.size()) {
      acc.add(track.segments[i], metrics.segments[i]);
    } else {
      SegmentMetrics none;
      none.options = metrics.options;
      acc.add(track.segments[i], none);  // recomputed inside
    }
  }
  return acc.result();
}

Statistics segment_statistics(const Segment& segment, const SegmentMetrics& metrics,
                              const StatisticsOptions& options) {
  Accumulator acc(options);
  acc.add(segment, metrics);
  return acc.result();
}

}  // namespace trailray::track
