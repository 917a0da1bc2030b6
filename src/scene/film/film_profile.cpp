#include "scene/film/film_profile.hpp"

#include <algorithm>
#include <cmath>

namespace trailray::scene {
namespace {

constexpr glm::u8vec4 kPanelColor{16, 18, 22, 176};  // the legend's
constexpr glm::u8vec3 kGroundColor{120, 110, 96};
constexpr glm::u8vec3 kLineColor{255, 255, 255};
constexpr glm::u8vec3 kNowColor{255, 64, 64};

}  // namespace

FilmProfile film_profile(const Track& t, const TimeSpan& span, int columns) {
  FilmProfile p;
  p.span = span;
  if (columns < 2 || t.altitude_m.empty() || !(span.end > span.start)) return p;
  double low = INFINITY, high = -INFINITY;
  for (int c = 0; c < columns; ++c) {
    const double time = span.start + (span.end - span.start) * c / (columns - 1);
    const TrackPosition at = position_at(t, time);
    const auto value = [&](const std::vector<double>& v) {
      if (!at.valid || at.point >= v.size()) return std::nan("");
      if (at.fraction <= 0.0 || at.point + 1 >= v.size()) return v[at.point];
      return v[at.point] + (v[at.point + 1] - v[at.point]) * at.fraction;
    };
    p.altitude_m.push_back(value(t.altitude_m));
    p.ground_m.push_back(value(t.ground_m));
    for (double h : {p.altitude_m.back(), p.ground_m.back()})
      if (std::isfinite(h)) low = std::min(low, h), high = std::max(high, h);
  }
  if (!(high >= low)) {
    p.altitude_m.clear();
    return p;
  }
  const double margin = std::max(10.0, 0.08 * (high - low));
  p.low_m = low - margin;
  p.high_m = high + margin;
  return p;
}

PixelRect film_profile_panel(std::uint32_t width, std::uint32_t height) {
  const int w = std::max(60, static_cast<int>(width) / 4), h = std::max(24, static_cast<int>(height) / 8);
  const int margin = std::max(8, static_cast<int>(height) / 45);
  return {static_cast<int>(width) - margin - w, static_cast<int>(height) - margin - h, w, h};
}

PixelRect draw_film_profile(RgbaImage& image, const FilmProfile& p, double time_unix_s) {
  if (p.altitude_m.size() < 2) return {};
  const PixelRect panel = film_profile_panel(image.width, image.height);
  fill_rounded_rect(image, panel, 4, kPanelColor);
  const int pad = 4, inner_h = panel.height - 2 * pad;
  const int columns = static_cast<int>(p.altitude_m.size());
  const auto row_of = [&](double h) {
    return panel.y + pad + static_cast<int>(std::lround((p.high_m - h) / (p.high_m - p.low_m) * inner_h));
  };
  const auto column_x = [&](int c) { return panel.x + pad + c * (panel.width - 2 * pad - 1) / (columns - 1); };
  int previous_row = -1;
  for (int c = 0; c < columns; ++c) {
    const int x = column_x(c);
    const double ground = p.ground_m[static_cast<std::size_t>(c)], alt = p.altitude_m[static_cast<std::size_t>(c)];
    if (std::isfinite(ground))
      for (int y = row_of(ground); y < panel.bottom() - pad; ++y) blend_pixel(image, x, y, kGroundColor, 0.9f);
    if (!std::isfinite(alt)) {
      previous_row = -1;
      continue;
    }
    // The altitude line, joined to the previous column's so steep parts stay unbroken.
    const int row = row_of(alt);
    const int from = previous_row < 0 ? row : std::min(row, previous_row),
              to = previous_row < 0 ? row : std::max(row, previous_row);
    for (int y = from - 1; y <= to; ++y) blend_pixel(image, x, y, kLineColor, 1.0f);
    previous_row = row;
  }
  // Now: a vertical line across the panel.
  if (p.span.end > p.span.start) {
    const double f = std::clamp((time_unix_s - p.span.start) / (p.span.end - p.span.start), 0.0, 1.0);
    const int x = panel.x + pad + static_cast<int>(std::lround(f * (panel.width - 2 * pad - 1)));
    for (int y = panel.y + pad; y < panel.bottom() - pad; ++y) {
      blend_pixel(image, x, y, kNowColor, 1.0f);
      blend_pixel(image, x + 1, y, kNowColor, 1.0f);
    }
  }
  return panel;
}

}  // namespace trailray::scene
