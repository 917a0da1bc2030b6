#include "scene/text/legend_content.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "scene/volumes/airspace_volumes.hpp"
#include "scene/text/text_raster.hpp"
#include "scene/tracks/track_density.hpp"
#include "track/cover.hpp"

namespace trailray::scene {
namespace {

const TrackSet kNoTracks;

const TrackSet& tracks_of(const Scene& scene) { return scene.tracks != nullptr ? *scene.tracks : kNoTracks; }

// The rows from a panel's top to the image's bottom: what a legend stacked above it leaves free.
int rows_taken(const PixelRect& panel, std::uint32_t height) {
  return panel.empty() ? 0 : static_cast<int>(height) - panel.y;
}

PixelRect united(const PixelRect& a, const PixelRect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  const int x = std::min(a.x, b.x), y = std::min(a.y, b.y);
  return {x, y, std::max(a.right(), b.right()) - x, std::max(a.bottom(), b.bottom()) - y};
}

}  // namespace

std::optional<ColorLegend> color_legend_for(const TrackStyle& style, const std::optional<track::ValueRange>& range) {
  const track::ColorMetric metric = style.color_by;
  // Cover's classes are named in the key (track_key_for), not placed on a scale.
  if (metric == track::ColorMetric::solid || metric == track::ColorMetric::cover || !range) return std::nullopt;
  ColorLegend legend;
  const std::string_view unit =
      metric == track::ColorMetric::time ? std::string_view("h:mm") : track::color_metric_unit(metric);
  legend.title = unit.empty() ? std::string(track::color_metric_label(metric))
                              : fmt::format("{} ({})", track::color_metric_label(metric), unit);
  if (track::counts_neighbours(metric)) legend.title = neighbour_legend_title(metric, neighbour_radius_m(style));
  legend.map = style.colormap;
  legend.min_label = track::format_color_value(metric, range->min);
  legend.max_label = track::format_color_value(metric, range->max);
  // A signed metric's zero (the diverging map's white) is worth a label of its own.
  if (range->min < 0.0 && range->max > 0.0 && track::color_metric_is_signed(metric))
    legend.ticks.push_back({-range->min / (range->max - range->min), "0"});
  return legend;
}

std::vector<TrackKeyEntry> track_key_for(const TrackStyle& style, const TrackSet& tracks) {
  std::vector<TrackKeyEntry> key;
  // Phase: the colours that are not on the climb's bar.
  if (style.color_by == track::ColorMetric::phase)
    return {{"gliding", kCategoryColorSrgb}, {"ground, gaps", kMissingValueColorSrgb}};
  // Cover: its three classes (no colour bar), the canopy cut away along the covered ones.
  if (style.color_by == track::ColorMetric::cover)
    return {{"open", kOpenColorSrgb},
            {"under cover (canopy cut away)", kCoveredColorSrgb},
            {"below the ground", kBelowGroundColorSrgb}};
  if (style.color_by == track::ColorMetric::solid) {
    for (const Track& t : tracks.tracks())
      if (t.visible) key.push_back({t.name, t.color_srgb, t.is_route});
    if (key.size() < 2) key.clear();
  }
  // With a surface model: what the cut through the canopy is (a track behind a ridge is ghosted).
  const auto covered = [](const Track& t) {
    return t.visible && std::find(t.cover.begin(), t.cover.end(), static_cast<std::uint8_t>(track::Cover::covered)) !=
                            t.cover.end();
  };
  if (std::any_of(tracks.tracks().begin(), tracks.tracks().end(), covered))
    key.push_back({"under cover: canopy cut away", kCoveredColorSrgb, true});
  return key;
}

std::vector<TrackKeyEntry> airspace_key_for(const Scene& scene) {
  std::vector<TrackKeyEntry> key;
  if (scene.volumes == nullptr) return key;
  for (const AirspaceClassShown& c : airspace_classes_shown(*scene.volumes)) key.push_back({c.label, c.color_srgb});
  return key;
}

void draw_scene_legend(RgbaImage& image, const Scene& scene) {
  if (!scene.style.legend) return;
  const auto legend = color_legend_for(scene.style.tracks, scene.color_range);
  const auto key = track_key_for(scene.style.tracks, tracks_of(scene));
  const auto airspaces = airspace_key_for(scene);
  if (!legend && key.empty() && airspaces.empty() && !scene.overlay_legend) return;
  TextRasterizer text;
  // Stacked bottom up: the key (several solid tracks' names, or for phase the gliding and no-value
  // colours), the colour bar, the airspaces' classes, the overlay's colour bar.
  PixelRect below;
  const auto stack = [&below](const LegendLayout& drawn) {
    if (drawn.drawn) below = united(below, drawn.panel);
  };
  if (!key.empty()) stack(draw_track_key(image, text, key));
  if (legend) stack(draw_color_legend(image, text, *legend, {0, rows_taken(below, image.height)}));
  if (!airspaces.empty()) stack(draw_track_key(image, text, airspaces, {0, rows_taken(below, image.height)}));
  if (scene.overlay_legend) draw_color_legend(image, text, *scene.overlay_legend, {0, rows_taken(below, image.height)});
}

PixelRect scene_legend_panel(std::uint32_t width, std::uint32_t height, const Scene& scene) {
  if (!scene.style.legend) return {};
  TextRasterizer text;
  return scene_legend_panel(width, height, scene, text);
}

PixelRect scene_legend_panel(std::uint32_t width, std::uint32_t height, const Scene& scene, TextRasterizer& text) {
  if (!scene.style.legend) return {};
  const auto legend = color_legend_for(scene.style.tracks, scene.color_range);
  const auto key = track_key_for(scene.style.tracks, tracks_of(scene));
  const auto airspaces = airspace_key_for(scene);
  // As draw_scene_legend: the key, the colour bar above it, the airspaces' classes above both, the
  // overlay's bar on top.
  PixelRect below;
  if (!key.empty()) below = track_key_panel(width, height, text, key);
  if (legend) below = united(below, color_legend_panel(width, height, text, *legend, {0, rows_taken(below, height)}));
  if (!airspaces.empty())
    below = united(below, track_key_panel(width, height, text, airspaces, {0, rows_taken(below, height)}));
  if (scene.overlay_legend)
    below = united(below, color_legend_panel(width, height, text, *scene.overlay_legend, {0, rows_taken(below, height)}));
  return below;
}

KeptClearCorner legend_clearance(const PixelRect& panel, std::uint32_t height) {
  if (panel.empty()) return {};
  // The gaps the panel keeps from the left and bottom edges, kept again between it and the
  // tracks: a track drawn right up to the panel's edge would look tucked under it.
  const int left_gap = std::max(panel.x, 0);
  const int bottom_gap = std::max(static_cast<int>(height) - panel.bottom(), 0);
  return {ImageCorner::bottom_left, static_cast<double>(panel.right() + left_gap),
          static_cast<double>(static_cast<int>(height) - panel.y + bottom_gap)};
}

}  // namespace trailray::scene
