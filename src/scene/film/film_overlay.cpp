#include "scene/film/film_overlay.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "scene/film/film_profile.hpp"
#include "scene/text/legend.hpp"

namespace trailray::scene {
namespace {

// The legend's look: a dark translucent panel, white text.
constexpr glm::u8vec4 kPanelColor{16, 18, 22, 176};
constexpr glm::u8vec4 kTextColor{255, 255, 255, 255};
constexpr std::size_t kMaxNameCodePoints = 28;

double lerp_at(const std::vector<double>& v, const TrackPosition& at) {
  if (at.point >= v.size()) return std::nan("");
  const double a = v[at.point];
  if (at.fraction <= 0.0 || at.point + 1 >= v.size()) return a;
  const double b = v[at.point + 1];
  if (!std::isfinite(b)) return a;
  return a + (b - a) * at.fraction;
}

// Days since 1970-01-01 to a proleptic Gregorian date (H. Hinnant's civil_from_days).
void civil_from_days(long long z, long long& y, unsigned& m, unsigned& d) {
  z += 719468;
  const long long era = (z >= 0 ? z : z - 146096) / 146097;
  const unsigned doe = static_cast<unsigned>(z - era * 146097);
  const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  y = static_cast<long long>(yoe) + era * 400;
  const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const unsigned mp = (5 * doy + 2) / 153;
  d = doy - (153 * mp + 2) / 5 + 1;
  m = mp < 10 ? mp + 3 : mp - 9;
  y += m <= 2 ? 1 : 0;
}

struct Panel {
  PixelRect rect;
  std::vector<std::string> lines;  // the first in bold
  bool bold_first = false;
  int font_px = 0, pad = 0;
};

// Where everything goes: the clock top left, the gauge panels stacked top right.
std::vector<Panel> layout(std::uint32_t width, std::uint32_t height, TextRasterizer& text, OverlayLevel level,
                          double time_unix_s, const std::vector<GaugeReadings>& gauges,
                          const std::string& attribution) {
  std::vector<Panel> panels;
  if (level == OverlayLevel::none) return panels;
  const int f = legend_font_px(height), pad = std::max(4, f / 2), margin = f;
  const int line = text.measure("Ag", f).height() + f / 4;
  const auto panel_of = [&](std::vector<std::string> lines, bool bold_first, int x_right_or_left, bool right, int y) {
    int w = 0;
    for (std::size_t i = 0; i < lines.size(); ++i)
      w = std::max(w, text.measure(lines[i], f, bold_first && i == 0 ? FontWeight::bold : FontWeight::regular).width);
    const int pw = w + 2 * pad, ph = static_cast<int>(lines.size()) * line + 2 * pad - f / 4;
    const int x = right ? x_right_or_left - pw : x_right_or_left;
    return Panel{{x, y, pw, ph}, std::move(lines), bold_first, f, pad};
  };
  panels.push_back(panel_of({film_clock_text(time_unix_s)}, false, margin, false, margin));
  if (level == OverlayLevel::full) {
    int y = margin;
    for (const GaugeReadings& g : gauges) {
      std::vector<std::string> lines{
          text.ellipsize(g.name, kMaxNameCodePoints, static_cast<int>(width) / 3, f, FontWeight::bold)};
      for (std::string& l : gauge_lines(g)) lines.push_back(std::move(l));
      Panel p = panel_of(std::move(lines), true, static_cast<int>(width) - margin, true, y);
      if (p.rect.bottom() > static_cast<int>(height) - margin) break;  // no more room
      y = p.rect.bottom() + pad;
      panels.push_back(std::move(p));
    }
  }
  if (!attribution.empty()) {
    // Small, bottom right (the legend takes the bottom left), above the profile where there is one.
    const int small = std::max(9, f * 3 / 4), small_pad = std::max(2, small / 3);
    const std::string line_text = text.ellipsize(attribution, 200, static_cast<int>(width) * 2 / 3, small);
    const int w = text.measure(line_text, small).width + 2 * small_pad;
    const int h = text.measure(line_text, small).height() + 2 * small_pad;
    int bottom = static_cast<int>(height) - small_pad;
    if (level == OverlayLevel::full && !gauges.empty()) bottom = film_profile_panel(width, height).y - small_pad;
    panels.push_back({{static_cast<int>(width) - margin - w, bottom - h, w, h}, {line_text}, false, small, small_pad});
  }
  return panels;
}

}  // namespace

Result<OverlayLevel> parse_overlay_level(std::string_view text) {
  if (text == "none") return {OverlayLevel::none, {}};
  if (text == "minimal") return {OverlayLevel::minimal, {}};
  if (text == "full") return {OverlayLevel::full, {}};
  return {std::nullopt, fmt::format("--overlay: '{}' is not none, minimal or full", text)};
}

GaugeReadings gauge_readings(const Track& t, const TrackPosition& at) {
  return {t.name,
          lerp_at(t.altitude_m, at),
          lerp_at(t.ground_m, at),
          lerp_at(t.speed_kmh, at),
          lerp_at(t.vspeed_ms, at),
          lerp_at(t.heart_rate_bpm, at),
          lerp_at(t.cadence_rpm, at),
          lerp_at(t.power_w, at)};
}

std::vector<std::string> gauge_lines(const GaugeReadings& g) {
  std::vector<std::string> lines;
  if (std::isfinite(g.altitude_m)) lines.push_back(fmt::format("Alt {:.0f} m", g.altitude_m));
  if (std::isfinite(g.altitude_m) && std::isfinite(g.ground_m))
    lines.push_back(fmt::format("AGL {:.0f} m", g.altitude_m - g.ground_m));
  if (std::isfinite(g.speed_kmh)) lines.push_back(fmt::format("Speed {:.0f} km/h", g.speed_kmh));
  if (std::isfinite(g.vspeed_ms)) lines.push_back(fmt::format("Vario {:+.1f} m/s", g.vspeed_ms));
  // The glide ratio while sinking (distance flown per height lost); climbing has none.
  if (std::isfinite(g.speed_kmh) && std::isfinite(g.vspeed_ms) && g.vspeed_ms < -0.2)
    lines.push_back(fmt::format("Glide {:.1f}", g.speed_kmh / 3.6 / -g.vspeed_ms));
  if (std::isfinite(g.heart_rate_bpm)) lines.push_back(fmt::format("HR {:.0f} bpm", g.heart_rate_bpm));
  if (std::isfinite(g.cadence_rpm)) lines.push_back(fmt::format("Cadence {:.0f} rpm", g.cadence_rpm));
  if (std::isfinite(g.power_w)) lines.push_back(fmt::format("Power {:.0f} W", g.power_w));
  return lines;
}

std::string film_clock_text(double t) {
  const double whole = std::floor(t);
  const long long days = static_cast<long long>(std::floor(whole / 86400.0));
  const long long of_day = static_cast<long long>(whole) - days * 86400;
  long long y = 0;
  unsigned m = 0, d = 0;
  civil_from_days(days, y, m, d);
  return fmt::format("{:04d}-{:02d}-{:02d} {:02d}:{:02d}:{:02d} UTC", y, m, d, of_day / 3600, (of_day / 60) % 60,
                     of_day % 60);
}

std::vector<PixelRect> draw_film_overlay(RgbaImage& image, TextRasterizer& text, OverlayLevel level, double time_unix_s,
                                         const std::vector<GaugeReadings>& gauges, const std::string& attribution) {
  std::vector<PixelRect> covered;
  for (const Panel& p : layout(image.width, image.height, text, level, time_unix_s, gauges, attribution)) {
    const int f = p.font_px, pad = p.pad;
    const int line = text.measure("Ag", f).height() + f / 4;
    fill_rounded_rect(image, p.rect, std::max(2, pad / 2), kPanelColor);
    int baseline = p.rect.y + pad + text.measure("Ag", f).ascent;
    for (std::size_t i = 0; i < p.lines.size(); ++i, baseline += line)
      text.draw(image, p.lines[i], p.rect.x + pad, baseline,
                {f, p.bold_first && i == 0 ? FontWeight::bold : FontWeight::regular, kTextColor});
    covered.push_back(p.rect);
  }
  return covered;
}

std::vector<PixelRect> film_overlay_panels(std::uint32_t width, std::uint32_t height, TextRasterizer& text,
                                           OverlayLevel level, const std::vector<GaugeReadings>& gauges,
                                           const std::string& attribution) {
  std::vector<PixelRect> rects;
  for (const Panel& p : layout(width, height, text, level, 0.0, gauges, attribution)) rects.push_back(p.rect);
  return rects;
}

}  // namespace trailray::scene
