#include "scene/film/film_timing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "track/io/parse_util.hpp"

namespace trailray::scene {
namespace {

// "1h30m", "90s", "2m", "45" (seconds): a sum of numbers each with an optional unit.
std::optional<double> parse_hms(std::string_view text) {
  text = track::trim(text);
  if (text.empty()) return std::nullopt;
  double total = 0.0;
  while (!text.empty()) {
    std::size_t n = 0;
    while (n < text.size() && (std::isdigit(static_cast<unsigned char>(text[n])) != 0 || text[n] == '.')) ++n;
    if (n == 0) return std::nullopt;
    const auto number = track::parse_double(text.substr(0, n));
    if (!number) return std::nullopt;
    double unit = 1.0;
    if (n < text.size()) {
      switch (text[n]) {
        case 'h':
          unit = 3600.0;
          break;
        case 'm':
          unit = 60.0;
          break;
        case 's':
          unit = 1.0;
          break;
        default:
          return std::nullopt;
      }
      ++n;
    } else if (total > 0.0) {
      return std::nullopt;  // "1m30" is ambiguous: say "1m30s"
    }
    total += *number * unit;
    text.remove_prefix(n);
  }
  if (!std::isfinite(total)) return std::nullopt;  // hundreds of digits: no length at all
  return total;
}

// "13:45" or "13:45:30": seconds since midnight.
std::optional<double> parse_time_of_day(std::string_view text) {
  int h = 0, m = 0;
  double s = 0.0;
  if (text.size() < 5 || text[2] != ':') return std::nullopt;
  const auto hh = track::parse_double(text.substr(0, 2)), mm = track::parse_double(text.substr(3, 2));
  if (!hh || !mm) return std::nullopt;
  h = static_cast<int>(*hh);
  m = static_cast<int>(*mm);
  if (text.size() > 5) {
    if (text[5] != ':') return std::nullopt;
    const auto ss = track::parse_double(text.substr(6));
    if (!ss) return std::nullopt;
    s = *ss;
  }
  if (h < 0 || h > 23 || m < 0 || m > 59 || s < 0.0 || s >= 61.0) return std::nullopt;
  return h * 3600.0 + m * 60.0 + s;
}

}  // namespace

double FilmTiming::time_of(std::size_t i) const {
  if (frames <= 1) return span.start;
  const double f = static_cast<double>(std::min(i, frames - 1)) / static_cast<double>(frames - 1);
  return span.start + f * (span.end - span.start);
}

Result<FilmTiming> make_film_timing(const TimeSpan& span, const FilmLength& length, double fps) {
  if (!(fps > 0.0) || fps > 240.0 || !std::isfinite(fps))
    return {std::nullopt, fmt::format("--fps: '{}' is not a frame rate in (0, 240]", fps)};
  double film_s = 0.0;
  if (length.duration_s) {
    film_s = *length.duration_s;
    if (!(film_s > 0.0) || !std::isfinite(film_s))
      return {std::nullopt, fmt::format("--duration: '{}' is not a positive length", film_s)};
  } else {
    const double speed = length.speed.value_or(0.0);
    if (!(speed > 0.0) || !std::isfinite(speed))
      return {std::nullopt, fmt::format("--speed: '{}' is not a positive factor", speed)};
    film_s = (span.end - span.start) / speed;
  }
  const double frames = std::max(1.0, std::round(film_s * fps));
  if (frames > static_cast<double>(kMaxFilmFrames))
    return {std::nullopt, fmt::format("--duration/--speed: {:.0f} frames is more than {}", frames, kMaxFilmFrames)};
  return {FilmTiming{span, static_cast<std::size_t>(frames), fps}, {}};
}

Result<double> parse_film_duration(std::string_view text) {
  const auto s = parse_hms(text);
  if (!s || !(*s > 0.0))
    return {std::nullopt, fmt::format("--duration: '{}' is not a length such as 60s, 90, 1m30s or 2m", text)};
  return {*s, {}};
}

Result<double> parse_film_speed(std::string_view text) {
  std::string_view t = track::trim(text);
  if (!t.empty() && (t.back() == 'x' || t.back() == 'X')) t.remove_suffix(1);
  const auto v = track::parse_double(t);
  if (!v || !(*v > 0.0) || !std::isfinite(*v)) return {std::nullopt, fmt::format("--speed: '{}' is not a time factor such as 50x", text)};
  return {*v, {}};
}

Result<double> parse_film_instant(std::string_view text, const TimeSpan& span, std::string_view option) {
  const std::string_view t = track::trim(text);
  std::optional<double> when;
  if (!t.empty() && t.front() == '+') {
    if (const auto offset = parse_hms(t.substr(1))) when = span.start + *offset;
  } else if (t.find('T') != std::string_view::npos || t.find('-') != std::string_view::npos) {
    when = track::parse_iso8601(t);
  } else if (t.find(':') != std::string_view::npos) {
    if (const auto of_day = parse_time_of_day(t)) {
      const double midnight = std::floor(span.start / 86400.0) * 86400.0;
      when = midnight + *of_day;
    }
  } else if (const auto f = track::parse_double(t); f && *f >= 0.0 && *f <= 1.0) {
    when = span.start + *f * (span.end - span.start);
  }
  if (!when)
    return {std::nullopt, fmt::format("{}: '{}' is not a fraction (0.25), an offset (+10m), a UTC time (13:45) or a "
                                      "date-time (2024-07-01T13:45:00Z)",
                                      option, text)};
  if (*when < span.start - 1e-6 || *when > span.end + 1e-6)
    return {std::nullopt, fmt::format("{}: '{}' lies outside the tracks' time", option, text)};
  return {std::clamp(*when, span.start, span.end), {}};
}

}  // namespace trailray::scene
