#include "track/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace trailray::track {
namespace {

constexpr double kMsToKmh = 3.6;
constexpr double kInf = std::numeric_limits<double>::infinity();

bool valid_coordinates(const TrackPoint& p) {
  return std::isfinite(p.lat) && std::isfinite(p.lon) && std::abs(p.lat) <= 90.0 && std::abs(p.lon) <= 180.0;
}

bool matches(const SegmentMetrics& m, std::size_t n) {
  return m.distance_m.size() == n && m.distance_3d_m.size() == n && m.elapsed_s.size() == n && m.speed_ms.size() == n &&
         m.vspeed_ms.size() == n && m.slope_pct.size() == n && m.glide_ratio.size() == n;
}

std::optional<double> finite_or_null(std::optional<double> v) { return v && std::isfinite(*v) ? v : std::nullopt; }

void keep_max(std::optional<double>& current, double v) {
  if (std::isfinite(v) && (!current || v > *current)) current = v;
}
void keep_min(std::optional<double>& current, double v) {
  if (std::isfinite(v) && (!current || v < *current)) current = v;
}

// elevation_gain_loss, one elevation at a time (finite values only).
class GainLossCounter {
 public:
  explicit GainLossCounter(double threshold_m)
      : threshold_(std::isfinite(threshold_m) && threshold_m > 0.0 ? threshold_m : 0.0) {}

  void add(double e) {
    if (!started_) {
      low_ = high_ = e;
      started_ = true;
      return;
    }
    switch (trend_) {
      case Trend::Unknown:
        low_ = std::min(low_, e);
        high_ = std::max(high_, e);
        if (e - low_ > threshold_) {
          trend_ = Trend::Up;
          anchor_ = low_;
          extreme_ = e;
        } else if (high_ - e > threshold_) {
          trend_ = Trend::Down;
          anchor_ = high_;
          extreme_ = e;
        }
        break;
      case Trend::Up:
        if (e > extreme_) {
          extreme_ = e;
        } else if (extreme_ - e > threshold_) {
          r_.gain_m += extreme_ - anchor_;
          trend_ = Trend::Down;
          anchor_ = extreme_;
          extreme_ = e;
        }
        break;
      case Trend::Down:
        if (e < extreme_) {
          extreme_ = e;
        } else if (e - extreme_ > threshold_) {
          r_.loss_m += anchor_ - extreme_;
          trend_ = Trend::Up;
          anchor_ = extreme_;
          extreme_ = e;
        }
        break;
    }
  }

  GainLoss result() const {
    GainLoss r = r_;
    if (trend_ == Trend::Up) r.gain_m += extreme_ - anchor_;
    if (trend_ == Trend::Down) r.loss_m += anchor_ - extreme_;
    return r;
  }

 private:
  enum class Trend { Unknown, Up, Down };
  double threshold_;
  GainLoss r_;
  Trend trend_ = Trend::Unknown;
  bool started_ = false;
  double low_ = 0.0, high_ = 0.0;        // range seen while the trend is unknown
  double anchor_ = 0.0, extreme_ = 0.0;  // last turning point; furthest point of the current trend
};

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
    SegmentMetrics recomputed;
    const SegmentMetrics* mp = &given;
    if (!matches(given, n)) {
      recomputed = compute_segment_metrics(segment, given.options);
      mp = &recomputed;
    }
    const SegmentMetrics& m = *mp;

    const double d2 = m.distance_m.back() - m.distance_m.front();
    const double d3 = m.distance_3d_m.back() - m.distance_3d_m.front();
    if (std::isfinite(d2) && d2 > 0.0) s_.distance_2d_m += d2;
    if (std::isfinite(d3) && d3 > 0.0) s_.distance_3d_m += d3;

    // One pass over the points and their metrics: times, elevations, bounds, maxima.
    const bool pauses = std::isfinite(m.options.max_gap_s) && m.options.max_gap_s > 0.0;
    const double max_gap_s = m.options.max_gap_s;
    const double min_speed_ms = options_.moving_speed_kmh / kMsToKmh;
    std::size_t timed = 0, prev = 0, elevations = 0;
    double seg_first = 0.0, seg_last = 0.0;
    double latest = 0.0;  // the latest time seen in this segment: backward jumps add no time twice
    GainLossCounter gain_loss(options_.elevation_threshold_m);
    double min_ele = kInf, max_ele = -kInf;
    double max_speed = -kInf, max_vspeed = -kInf, min_vspeed = kInf;
    for (std::size_t i = 0; i < n; ++i) {
      const TrackPoint& p = pts[i];
      if (valid_coordinates(p)) bbox_.add(p.lat, p.lon);
      // Strict comparisons, as keep_max / keep_min: the first of equal values stays.
      const double sp = m.speed_ms[i], vs = m.vspeed_ms[i];
      if (std::isfinite(sp) && sp > max_speed) max_speed = sp;
      if (std::isfinite(vs)) {
        if (vs > max_vspeed) max_vspeed = vs;
        if (vs < min_vspeed) min_vspeed = vs;
      }
      if (std::isfinite(p.ele)) {
        ++elevations;
        gain_loss.add(p.ele);
        if (p.ele < min_ele) min_ele = p.ele;
        if (p.ele > max_ele) max_ele = p.ele;
      }
      const double t = p.time;
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
          const double interval = t - pts[prev].time;
          const bool long_interval = pauses && interval > max_gap_s;
          double v = long_interval ? kMissing : 0.5 * (m.speed_ms[prev] + m.speed_ms[i]);
          if (!std::isfinite(v)) v = step_m / interval;  // its own speed
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
    if (elevations > 0) {
      keep_min(s_.min_elevation_m, min_ele);
      keep_max(s_.max_elevation_m, max_ele);
    }
    if (elevations >= 2) {
      ++elevation_segments_;
      const GainLoss gl = gain_loss.result();
      gain_m_ += gl.gain_m;
      loss_m_ += gl.loss_m;
    }
    if (max_speed > -kInf) keep_max(max_speed_ms_, max_speed);
    if (max_vspeed > -kInf) keep_max(max_vspeed_ms_, max_vspeed);
    if (min_vspeed < kInf) keep_min(min_vspeed_ms_, min_vspeed);
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
    if (s.moving_time_s && *s.moving_time_s > 0.0) s.avg_speed_kmh = moving_distance_m_ / *s.moving_time_s * kMsToKmh;
    if (max_vspeed_ms_) s.max_climb_ms = std::max(0.0, *max_vspeed_ms_);
    if (min_vspeed_ms_) s.max_sink_ms = std::max(0.0, -*min_vspeed_ms_);
    if (!bbox_.empty()) s.bbox = bbox_;

    for (auto* v :
         {&s.duration_s, &s.elapsed_s, &s.moving_time_s, &s.elevation_gain_m, &s.elevation_loss_m, &s.min_elevation_m,
          &s.max_elevation_m, &s.max_speed_kmh, &s.avg_speed_kmh, &s.max_climb_ms, &s.max_sink_ms})
      *v = finite_or_null(*v);
    if (!std::isfinite(s.distance_2d_m)) s.distance_2d_m = 0.0;
    if (!std::isfinite(s.distance_3d_m)) s.distance_3d_m = 0.0;
    return s;
  }

 private:
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
  GainLossCounter counter(threshold_m);
  for (const double e : elevations)
    if (std::isfinite(e)) counter.add(e);
  return counter.result();
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

Statistics segment_statistics(const Segment& segment, const SegmentMetrics& metrics, const StatisticsOptions& options) {
  Accumulator acc(options);
  acc.add(segment, metrics);
  return acc.result();
}

}  // namespace trailray::track
