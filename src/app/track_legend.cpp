#include "app/track_legend.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "scene/text_raster.hpp"

namespace trailray::app {

std::optional<scene::ColorLegend> color_legend_for(const TrackStyle& style, const TrackScene& scene) {
  if (style.metric == track::ColorMetric::solid || !scene.range) return std::nullopt;
  scene::ColorLegend legend;
  const std::string_view unit =
      style.metric == track::ColorMetric::time ? std::string_view("h:mm") : track::color_metric_unit(style.metric);
  legend.title = unit.empty() ? std::string(track::color_metric_label(style.metric))
                              : fmt::format("{} ({})", track::color_metric_label(style.metric), unit);
  legend.map = style.settings.colormap;
  legend.min_label = track::format_color_value(style.metric, scene.range->min);
  legend.max_label = track::format_color_value(style.metric, scene.range->max);
  // A signed metric's zero (the diverging map's white) is worth a label of its own.
  if (scene.range->min < 0.0 && scene.range->max > 0.0 && track::color_metric_is_signed(style.metric))
    legend.ticks.push_back({-scene.range->min / (scene.range->max - scene.range->min), "0"});
  return legend;
}

std::vector<scene::TrackKeyEntry> track_key_for(const TrackStyle& style, const TrackScene& scene) {
  std::vector<scene::TrackKeyEntry> key;
  if (style.metric != track::ColorMetric::solid || scene.tracks.size() < 2) return key;
  for (const SceneTrack& t : scene.tracks) key.push_back({t.name, t.color_srgb});
  return key;
}

void draw_scene_legend(scene::RgbaImage& image, const TrackStyle& style, const TrackScene& scene) {
  if (!style.legend) return;
  const auto legend = color_legend_for(style, scene);
  const auto key = track_key_for(style, scene);
  if (!legend && key.empty()) return;
  scene::TextRasterizer text;
  if (legend) scene::draw_color_legend(image, text, *legend);
  if (!key.empty()) scene::draw_track_key(image, text, key);
}

scene::PixelRect scene_legend_panel(std::uint32_t width, std::uint32_t height, const TrackStyle& style,
                                     const TrackScene& scene) {
  if (!style.legend) return {};
  const auto legend = color_legend_for(style, scene);
  const auto key = track_key_for(style, scene);
  // As draw_scene_legend: a colour bar or a key, never both (one is for a metric, the other for
  // solid colours).
  scene::TextRasterizer text;
  if (legend) return scene::color_legend_panel(width, height, text, *legend);
  if (!key.empty()) return scene::track_key_panel(width, height, text, key);
  return {};
}

scene::KeptClearCorner legend_clearance(const scene::PixelRect& panel, std::uint32_t height) {
  if (panel.empty()) return {};
  // The gaps the panel keeps from the left and bottom edges, kept again between it and the
  // tracks: a track drawn right up to the panel's edge would look tucked under it.
  const int left_gap = std::max(panel.x, 0);
  const int bottom_gap = std::max(static_cast<int>(height) - panel.bottom(), 0);
  return {scene::ImageCorner::bottom_left, static_cast<double>(panel.right() + left_gap),
          static_cast<double>(static_cast<int>(height) - panel.y + bottom_gap)};
}

}  // namespace trailray::app
