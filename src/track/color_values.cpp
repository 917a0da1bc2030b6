#include "track/color_values.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <utility>

#include <fast_float/fast_float.h>
#include <fmt/format.h>

namespace trailray::track {
namespace {

constexpr double kMsToKmh = 3.6;
constexpr float kNoValue = std::numeric_limits<float>::quiet_NaN();

struct MetricInfo {
  ColorMetric metric;
  std::string_view name, label, unit;
};

// One row per enum value, in enum order (color_metric_names relies on it).
constexpr std::array<MetricInfo, 14> kMetrics{{
    {ColorMetric::solid, "solid", "", ""},
    {ColorMetric::speed, "speed", "Speed", "km/h"},
    {ColorMetric::vspeed, "vspeed", "Vertical speed", "m/s"},
    {ColorMetric::slope, "slope", "Steepness", "%"},
    {ColorMetric::altitude, "altitude", "Altitude", "m"},
    {ColorMetric::agl, "agl", "Height above ground", "m"},
    {ColorMetric::hr, "hr", "Heart rate", "bpm"},
    {ColorMetric::cadence, "cadence", "Cadence", "rpm"},
    {ColorMetric::power, "power", "Power", "W"},
    {ColorMetric::time, "time", "Elapsed time", ""},
    {ColorMetric::phase, "phase", "Climb in thermals", "m/s"},
    {ColorMetric::density, "density", "Tracks nearby", "tracks"},
    {ColorMetric::thermals, "thermals", "Flights climbing nearby", "flights"},
    {ColorMetric::cover, "cover", "Cover", ""},
}};

const MetricInfo& info(ColorMetric metric) {
  for (const MetricInfo& m : kMetrics) {
    if (m.metric == metric) return m;
  }
  return kMetrics[0];
}

// A double as the float the GPU gets: NaN stays "no value", and a finite double too large for a
// float becomes NaN rather than the infinity a plain cast would give.
float to_value(double v) {
  if (!std::isfinite(v)) return kNoValue;
  const float f = static_cast<float>(v);
  return std::isfinite(f) ? f : kNoValue;
}

// The metrics channel a metric reads (nullptr: the metric reads the points themselves).
const std::vector<double>* metrics_channel(const SegmentMetrics& m, ColorMetric metric) {
  switch (metric) {
    case ColorMetric::speed:
      return &m.speed_ms;
    case ColorMetric::vspeed:
      return &m.vspeed_ms;
    case ColorMetric::slope:
      return &m.slope_pct;
    case ColorMetric::time:
      return &m.elapsed_s;
    default:
      return nullptr;
  }
}

bool uses_metrics(ColorMetric metric) {
  return metric == ColorMetric::speed || metric == ColorMetric::vspeed || metric == ColorMetric::slope ||
         metric == ColorMetric::time;
}

std::string shape_error(std::string_view what, std::size_t segment, std::size_t got, std::size_t want) {
  return std::string(what) + " of segment " + std::to_string(segment) + " has " + std::to_string(got) + " values for " +
         std::to_string(want) + " points";
}

void check_shapes(const Track& track, const TrackMetrics& metrics, ColorMetric metric,
                  const std::vector<std::vector<double>>* ground_heights_m) {
  const std::size_t segments = track.segments.size();
  if (uses_metrics(metric)) {
    if (metrics.segments.size() != segments) {
      throw std::invalid_argument("color_values: the metrics have " + std::to_string(metrics.segments.size()) +
                                  " segments for a track of " + std::to_string(segments));
    }
    for (std::size_t s = 0; s < segments; ++s) {
      const std::size_t n = track.segments[s].points.size();
      const std::size_t got = metrics_channel(metrics.segments[s], metric)->size();
      if (got != n) throw std::invalid_argument("color_values: the metrics " + shape_error("channel", s, got, n));
    }
  }
  if (metric == ColorMetric::agl) {
    if (ground_heights_m == nullptr) {
      throw std::invalid_argument("color_values: height above ground needs the ground heights below the points");
    }
    if (ground_heights_m->size() != segments) {
      throw std::invalid_argument("color_values: the ground heights have " + std::to_string(ground_heights_m->size()) +
                                  " segments for a track of " + std::to_string(segments));
    }
    for (std::size_t s = 0; s < segments; ++s) {
      const std::size_t n = track.segments[s].points.size();
      const std::size_t got = (*ground_heights_m)[s].size();
      if (got != n) throw std::invalid_argument("color_values: the " + shape_error("ground heights", s, got, n));
    }
  }
}

// The value of one point for a metric that the points carry themselves.
float point_value(const TrackPoint& p, ColorMetric metric) {
  switch (metric) {
    case ColorMetric::altitude:
      return to_value(p.ele);
    case ColorMetric::hr:
      return to_value(p.heart_rate);
    case ColorMetric::cadence:
      return to_value(p.cadence);
    case ColorMetric::power:
      return to_value(p.power);
    default:
      return kNoValue;
  }
}

// Linear interpolation between order statistics: rank p/100 * (n - 1) in the sorted values (the
// "linear" method of numpy.percentile and R type 7).
double percentile(const std::vector<double>& sorted, double p) {
  const double rank = p / 100.0 * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(rank));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double fraction = rank - static_cast<double>(below);
  return sorted[below] + (sorted[above] - sorted[below]) * fraction;
}

// Fixed-point text with `decimals` decimals; a value that rounds to zero has no sign ("0.0", never
// "-0.0"). Non-finite values print as "n/a".
std::string fixed(double v, int decimals) {
  if (!std::isfinite(v)) return "n/a";
  // fmt, not std::to_chars: Emscripten's libc++ has no floating-point to_chars. Both round exactly.
  std::string text = fmt::format("{:.{}f}", v, std::max(decimals, 0));
  if (text.front() == '-' && text.find_first_not_of("-0.") == std::string::npos) text.erase(0, 1);
  return text;
}

// Elapsed time as h:mm, whole minutes rounded towards zero (the legend's ends do not claim a
// minute that has not passed): 3900 s -> "1:05", 59 s -> "0:00", -60 s -> "-0:01".
std::string hours_minutes(double seconds) {
  if (!std::isfinite(seconds)) return "n/a";
  const double minutes = std::floor(std::abs(seconds) / 60.0);
  const double hours = std::floor(minutes / 60.0);
  // fmod is exact: minutes - hours * 60 loses the minutes (and leaves int's range) for huge values.
  const auto mm = static_cast<int>(std::clamp(std::fmod(minutes, 60.0), 0.0, 59.0));
  std::string text = (seconds < 0.0 && minutes > 0.0) ? "-" : "";
  text += fixed(hours, 0);
  text += ':';
  if (mm < 10) text += '0';
  text += std::to_string(mm);
  return text;
}

std::optional<double> parse_finite(std::string_view text) {
  double v = 0.0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  const auto [end, ec] = fast_float::from_chars(first, last, v);  // libc++ 13 has no double from_chars
  if (text.empty() || ec != std::errc{} || end != last || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

std::string_view color_metric_name(ColorMetric metric) { return info(metric).name; }

std::optional<ColorMetric> parse_color_metric(std::string_view name) {
  for (const MetricInfo& m : kMetrics) {
    if (m.name == name) return m.metric;
  }
  return std::nullopt;
}

std::vector<std::string_view> color_metric_names() {
  std::vector<std::string_view> names;
  for (const MetricInfo& m : kMetrics) names.push_back(m.name);
  return names;
}

std::string_view color_metric_label(ColorMetric metric) { return info(metric).label; }
std::string_view color_metric_unit(ColorMetric metric) { return info(metric).unit; }

bool color_metric_is_signed(ColorMetric metric) { return metric == ColorMetric::vspeed; }

std::string format_color_value(ColorMetric metric, double value) {
  switch (metric) {
    case ColorMetric::speed:
      // 99.95 and above would print as "100.0": from there on whole km/h.
      return fixed(value, std::abs(value) < 99.95 ? 1 : 0);
    case ColorMetric::vspeed:
    case ColorMetric::phase:
      return fixed(value, 1);
    case ColorMetric::time:
      return hours_minutes(value);
    case ColorMetric::solid:
      return fixed(value, 1);
    case ColorMetric::slope:
    case ColorMetric::altitude:
    case ColorMetric::agl:
    case ColorMetric::hr:
    case ColorMetric::cadence:
    case ColorMetric::power:
    case ColorMetric::density:
    case ColorMetric::thermals:
    case ColorMetric::cover:
      return fixed(value, 0);
  }
  return fixed(value, 1);
}

std::vector<std::vector<float>> color_values(const Track& track, const TrackMetrics& metrics, ColorMetric metric,
                                             const std::vector<std::vector<double>>* ground_heights_m) {
  check_shapes(track, metrics, metric, ground_heights_m);
  std::vector<std::vector<float>> values(track.segments.size());
  for (std::size_t s = 0; s < track.segments.size(); ++s) {
    const std::vector<TrackPoint>& points = track.segments[s].points;
    std::vector<float>& out = values[s];
    out.assign(points.size(), kNoValue);
    if (uses_metrics(metric)) {
      const std::vector<double>& channel = *metrics_channel(metrics.segments[s], metric);
      const double scale = metric == ColorMetric::speed ? kMsToKmh : 1.0;
      for (std::size_t i = 0; i < points.size(); ++i) out[i] = to_value(channel[i] * scale);
    } else if (metric == ColorMetric::agl) {
      const std::vector<double>& ground = (*ground_heights_m)[s];
      for (std::size_t i = 0; i < points.size(); ++i) out[i] = to_value(points[i].ele - ground[i]);
    } else if (metric != ColorMetric::solid) {
      for (std::size_t i = 0; i < points.size(); ++i) out[i] = point_value(points[i], metric);
    }
  }
  return values;
}

std::optional<ValueRange> robust_range(std::span<const std::vector<float>> values, bool symmetric_about_zero,
                                       double low_percentile, double high_percentile) {
  if (!(low_percentile >= 0.0 && low_percentile <= high_percentile && high_percentile <= 100.0)) {
    throw std::invalid_argument("robust_range: percentiles " + std::to_string(low_percentile) + " and " +
                                std::to_string(high_percentile) + " are not 0 <= low <= high <= 100");
  }
  std::vector<double> finite;
  for (const std::vector<float>& v : values) {
    for (float x : v) {
      if (std::isfinite(x) && !is_category_value(x)) finite.push_back(x);
    }
  }
  if (finite.empty()) return std::nullopt;
  std::sort(finite.begin(), finite.end());

  ValueRange range{percentile(finite, low_percentile), percentile(finite, high_percentile)};
  if (symmetric_about_zero) {
    const double magnitude = std::max(std::abs(range.min), std::abs(range.max));
    range = {-magnitude, magnitude};
  }
  if (range.max - range.min <= 0.0) {
    // One value everywhere (a flat lake, a constant heart rate): a scale around it, wide enough
    // to show for large values too.
    const double centre = range.min;
    const double half = std::max(0.5, 0.01 * std::abs(centre));
    range = {centre - half, centre + half};
  }
  return range;
}

std::optional<ValueRange> parse_value_range(std::string_view text) {
  // The separator is the only ':'; a '-' always belongs to a number ("-5:-1").
  const std::size_t colon = text.find(':');
  if (colon == std::string_view::npos || text.find(':', colon + 1) != std::string_view::npos) return std::nullopt;
  const std::optional<double> min = parse_finite(text.substr(0, colon));
  const std::optional<double> max = parse_finite(text.substr(colon + 1));
  if (!min || !max || !(*min < *max)) return std::nullopt;
  return ValueRange{*min, *max};
}

}  // namespace trailray::track
