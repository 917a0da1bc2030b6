// The readable report of `trailray flight`: per flight a summary, the thermals, the glides and
// the wind per altitude band. Times are UTC.
#include <fmt/format.h>

#include <cmath>
#include <ctime>

#include "app/flight/flight_report.hpp"
#include "track/io/text_output.hpp"

namespace trailray::app {
namespace {

namespace fl = track::flight;

std::tm utc(double t) {
  const auto secs = static_cast<std::time_t>(std::floor(t));
  std::tm tm{};
  gmtime_r(&secs, &tm);
  return tm;
}

std::string clock(double t) {
  const std::tm tm = utc(t);
  return fmt::format("{:02d}:{:02d}:{:02d}", tm.tm_hour, tm.tm_min, tm.tm_sec);
}

std::string date(double t) {
  const std::tm tm = utc(t);
  return fmt::format("{:04d}-{:02d}-{:02d}", tm.tm_year + 1900, tm.tm_mon + 1, tm.tm_mday);
}

// "2 h 05 min", "12 min", "45 s".
std::string long_duration(double s) {
  const long v = std::lround(s);
  if (v >= 3600) return fmt::format("{} h {:02d} min", v / 3600, v % 3600 / 60);
  if (v >= 60) return fmt::format("{} min", v / 60);
  return fmt::format("{} s", v);
}

// "4:35", "1:02:10".
std::string short_duration(double s) {
  const long v = std::lround(s);
  if (v >= 3600) return fmt::format("{}:{:02d}:{:02d}", v / 3600, v % 3600 / 60, v % 60);
  return fmt::format("{}:{:02d}", v / 60, v % 60);
}

std::string metres(double v) { return std::isfinite(v) ? fmt::format("{:.0f}", v) : std::string("-"); }
std::string climb(double v) { return std::isfinite(v) ? fmt::format("{:+.2f}", v) : std::string("-"); }

std::string wind(double speed, double from) {
  if (!std::isfinite(speed) || !std::isfinite(from)) return "-";
  return fmt::format("{:.1f} m/s from {:03.0f}°", speed, std::fmod(std::round(from), 360.0));
}

std::string place_line(const char* label, const fl::Place& p) {
  return fmt::format("  {:<10} {}  {:.5f}, {:.5f}  {} m\n", label, clock(p.time), p.lat, p.lon, metres(p.alt));
}

std::string summary(const fl::Flight& f) {
  std::string s;
  s += place_line("take-off", f.takeoff);
  s += place_line("landing", f.landing);
  s += fmt::format("  {:<10} {:.1f} km along the track; altitude {} .. {} m\n", "distance", f.distance_m / 1000.0,
                   metres(f.min_alt_m), metres(f.max_alt_m));
  s += fmt::format("  {:<10} {:.0f} % of the time (left {}, right {}); gliding {}", "circling", f.circling_share * 100,
                   long_duration(f.circling_left_s), long_duration(f.circling_right_s), long_duration(f.gliding_s));
  s += f.unknown_s > 0 ? fmt::format("; unknown (gaps) {}\n", long_duration(f.unknown_s)) : "\n";
  s += fmt::format("  {:<10} {}", "thermals", f.thermals.size());
  if (!f.thermals.empty())
    s += fmt::format(", mean climb {} m/s (time-weighted), best 20 s climb {} m/s", climb(f.mean_thermal_climb_ms),
                     climb(f.best_climb_ms));
  s += "\n";
  if (f.best_glide >= 0) {
    const fl::Glide& g = f.glides[static_cast<std::size_t>(f.best_glide)];
    s += fmt::format("  {:<10} L/D {:.1f} over {:.1f} km (glide {})", "best glide", g.glide_ratio,
                     g.distance_m / 1000.0, f.best_glide + 1);
  } else {
    s += fmt::format("  {:<10} none of 2 km or more that lost 100 m", "best glide");
  }
  if (f.longest_glide >= 0)
    s += fmt::format("; longest glide {:.1f} km (glide {})",
                     f.glides[static_cast<std::size_t>(f.longest_glide)].distance_m / 1000.0, f.longest_glide + 1);
  return s + "\n";
}

std::string thermal_table(const fl::Flight& f) {
  if (f.thermals.empty()) return {};
  std::string s =
      fmt::format("\n  {:>3}  {:<8}  {:>7}  {:<5}  {:>13}  {:>6}  {:>6}  {:>7}  {:>5}  {}\n", "#", "thermal", "time",
                  "turn", "entry→exit m", "gain", "mean", "best20s", "turns", "wind (drift)");
  for (std::size_t i = 0; i < f.thermals.size(); ++i) {
    const fl::Thermal& t = f.thermals[i];
    s += fmt::format("  {:>3}  {:<8}  {:>7}  {:<5}  {:>6}→{:<6}  {:>6}  {:>6}  {:>7}  {:>5.1f}  {}{}\n", i + 1,
                     clock(t.start.time), short_duration(t.duration_s),
                     t.direction == fl::Phase::CirclingLeft ? "left" : "right", metres(t.start.alt), metres(t.end.alt),
                     std::isfinite(t.gain_m) ? fmt::format("{:+.0f}", t.gain_m) : "-", climb(t.mean_climb_ms),
                     climb(t.best_climb_ms), t.turns, wind(t.wind_speed_ms, t.wind_from_deg),
                     t.wind_from_centres ? "" : " (start→end)");
  }
  return s;
}

std::string glide_table(const fl::Flight& f) {
  if (f.glides.empty()) return {};
  std::string s = fmt::format("\n  {:>3}  {:<8}  {:>7}  {:>9}  {:>11}  {:>6}  {:>9}\n", "#", "glide", "time",
                              "distance", "height lost", "L/D", "speed");
  for (std::size_t i = 0; i < f.glides.size(); ++i) {
    const fl::Glide& g = f.glides[i];
    s += fmt::format("  {:>3}  {:<8}  {:>7}  {:>6.2f} km  {:>9} m  {:>6}  {:>4.0f} km/h{}\n", i + 1,
                     clock(g.start.time), short_duration(g.duration_s), g.distance_m / 1000.0, metres(g.height_lost_m),
                     std::isfinite(g.glide_ratio) ? fmt::format("{:.1f}", g.glide_ratio) : std::string("-"),
                     g.mean_speed_ms * 3.6, static_cast<int>(i) == f.best_glide ? "  best" : "");
  }
  return s;
}

std::string wind_table(const fl::Flight& f) {
  if (f.wind.empty()) return {};
  std::string s = "\n  wind by altitude (thermals of 2 turns or more, by their mean altitude, weighted by duration)\n";
  for (const fl::WindBand& w : f.wind)
    s += fmt::format("  {:>13}  {:<22}  {} thermal{}\n", fmt::format("{:.0f}-{:.0f} m", w.floor_m, w.ceiling_m),
                     wind(w.speed_ms, w.from_deg), w.thermals, w.thermals == 1 ? "" : "s");
  return s;
}

}  // namespace

std::string flight_file_text(const FileFlights& f, const FlightTask* task) {
  std::string s;
  for (const TrackFlights& t : f.tracks) {
    const auto& flights = t.analysis.flights;
    s += fmt::format("{} ({}), track {}{}: ", f.path, f.format ? track::format_name(*f.format) : "?", t.index + 1,
                     t.name.empty() ? std::string() : " \"" + track::valid_utf8(t.name) + "\"");
    const std::string reason = no_flight_reason(t.analysis);
    if (!reason.empty()) {
      s += reason + "\n";
      continue;
    }
    s += fmt::format("{} flight{}\n", flights.size(), flights.size() == 1 ? "" : "s");
    if (t.fix_interval_s >= kCoarseFixInterval)
      s += fmt::format(
          "note: fixes {:.0f} s apart: circles of under about {:.0f} s cannot be resolved: circling may be "
          "undercounted\n",
          t.fix_interval_s, 3 * t.fix_interval_s);
    for (std::size_t i = 0; i < flights.size(); ++i) {
      const fl::Flight& flight = flights[i];
      s += fmt::format("\nflight {} of {}: {}, {} to {} UTC, {}\n", i + 1, flights.size(), date(flight.takeoff.time),
                       clock(flight.takeoff.time), clock(flight.landing.time), long_duration(flight.duration_s));
      s += summary(flight) + thermal_table(flight) + glide_table(flight) + wind_table(flight);
    }
  }
  if (task != nullptr && f.task)
    s += fmt::format("\nthe task {} ({:.2f} km optimised):\n", task->path,
                     task->distances.optimised.distance_m / 1000.0) +
         task_flight_text(task->task, *f.task);
  return s;
}

}  // namespace trailray::app
