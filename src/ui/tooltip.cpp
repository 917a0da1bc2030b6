// The numbers of one track point, as the 3D view's tooltip and `--script hover` print them.
#include <fmt/format.h>

#include <cmath>
#include <ctime>

#include "ui/tooltip.hpp"

namespace trailray::ui {
namespace {

constexpr const char* kMissingText = "\u2014";  // em dash

std::string line(const char* label, double value, const char* format_with_unit) {
  if (!std::isfinite(value)) return fmt::format("{}: {}", label, kMissingText);
  std::string text = fmt::format(fmt::runtime(format_with_unit), value);
  // A value that rounds to zero prints without a sign ("-0.0" reads like a bug); units hold no digit.
  if (text.front() == '-' && text.find_first_of("123456789") == std::string::npos) text.erase(0, 1);
  return fmt::format("{}: {}", label, text);
}

}  // namespace

std::string tooltip_time_text(double unix_s) {
  const auto whole = static_cast<std::time_t>(std::floor(unix_s));
  std::tm tm{};
  if (gmtime_r(&whole, &tm) == nullptr) return kMissingText;
  return fmt::format("{:04}-{:02}-{:02} {:02}:{:02}:{:02} UTC", tm.tm_year + 1900, tm.tm_mon + 1, tm.tm_mday,
                     tm.tm_hour, tm.tm_min, tm.tm_sec);
}

std::vector<std::string> tooltip_lines(const scene::Track& t, std::size_t i) {
  if (i >= t.point_count()) return {};
  const double time = t.time_unix_s[i];
  const double agl = t.altitude_m[i] - t.ground_m[i];  // NaN when either is missing
  std::vector<std::string> lines{
      std::isfinite(time) ? fmt::format("time: {}", tooltip_time_text(time)) : fmt::format("time: {}", kMissingText),
      line("altitude", t.altitude_m[i], "{:.0f} m"),
      line("height above ground", agl, "{:.0f} m"),
      line("speed", t.speed_kmh[i], "{:.1f} km/h"),
      line("vertical speed", t.vspeed_ms[i], "{:.1f} m/s"),
      line("heart rate", t.heart_rate(i), "{:.0f} bpm"),
  };
  // Only IGC flights have them: other tracks' tooltips do not list them as missing.
  const double pressure = t.pressure_altitude(i), gnss = t.gnss_altitude(i);
  if (!std::isnan(pressure)) lines.insert(lines.begin() + 2, line("pressure altitude", pressure, "{:.0f} m"));
  if (!std::isnan(gnss)) lines.insert(lines.begin() + 2, line("GNSS altitude", gnss, "{:.0f} m"));
  return lines;
}

}  // namespace trailray::ui
