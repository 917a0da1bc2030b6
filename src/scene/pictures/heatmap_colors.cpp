#include "scene/pictures/heatmap_colors.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace trailray::scene {

std::string_view heatmap_scale_name(HeatmapScale scale) { return scale == HeatmapScale::log ? "log" : "linear"; }

std::optional<HeatmapScale> parse_heatmap_scale(std::string_view name) {
  if (name == "log") return HeatmapScale::log;
  if (name == "linear") return HeatmapScale::linear;
  return std::nullopt;
}

float heatmap_position(const HeatmapPalette& palette, double count) {
  const double most = std::max<double>(palette.max_count, 1.0);
  if (!(count >= 1.0) || most <= 1.0) return count >= 1.0 ? 1.0f : 0.0f;
  const double p = palette.scale == HeatmapScale::log ? std::log(count) / std::log(most) : (count - 1.0) / (most - 1.0);
  return static_cast<float>(std::clamp(p, 0.0, 1.0));
}

glm::u8vec4 heatmap_rgba(const HeatmapPalette& palette, double count) {
  if (!(count > 0.0)) return {0, 0, 0, 0};
  const float p = heatmap_position(palette, std::max(count, 1.0));
  const glm::vec3 c = colormap_color(palette.colormap, p);
  const auto byte = [](float v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  return {byte(c.r), byte(c.g), byte(c.b), byte(0.4f + 0.6f * p)};
}

ColorLegend heatmap_legend(const HeatmapPalette& palette, std::string_view what, double cell_m) {
  ColorLegend legend;
  legend.title = fmt::format("{} per cell ({:g} m)", what, cell_m);
  legend.map = palette.colormap;
  legend.min_label = "1";
  legend.max_label = fmt::format("{}", std::max<std::uint32_t>(palette.max_count, 1));
  if (palette.scale == HeatmapScale::log)
    for (double v = 10.0; v < palette.max_count; v *= 10.0)
      legend.ticks.push_back({heatmap_position(palette, v), fmt::format("{:.0f}", v)});
  return legend;
}

}  // namespace trailray::scene
