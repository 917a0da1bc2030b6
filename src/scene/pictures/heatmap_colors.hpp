#pragma once
// How a heatmap's counts become colours: the tiles `trailray heatmap` writes, the overlay drawn on
// the terrain from a counts GeoTIFF, and the legend beside them all take their colours here, so
// they agree. A scale readable from one track to millions: log by default (1 at the colormap's
// start, the largest count at its end), or linear. Zero is transparent; a count is drawn more
// opaque the higher it is, so the terrain shows through the quiet cells.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include "scene/pictures/colormap.hpp"
#include "scene/text/legend.hpp"

namespace trailray::scene {

enum class HeatmapScale { log, linear };
std::string_view heatmap_scale_name(HeatmapScale scale);                 // "log", "linear"
std::optional<HeatmapScale> parse_heatmap_scale(std::string_view name);  // exact names

struct HeatmapPalette {
  Colormap colormap = Colormap::warm;  // pale yellow for the few to deep red for the most
  HeatmapScale scale = HeatmapScale::log;
  std::uint32_t max_count = 1;  // the count at the colormap's end (larger ones take the end too)
};

// 0..1 along the colormap for a count >= 1 (0 for 1, 1 for max_count and above).
float heatmap_position(const HeatmapPalette& palette, double count);

// sRGB and alpha bytes; transparent for 0 (and NaN), alpha from 40 % at the start to 100 %.
glm::u8vec4 heatmap_rgba(const HeatmapPalette& palette, double count);

// The colour bar of a heatmap: "`what` per cell (`cell` m)" over the range 1..max, ticks at the
// powers of ten in between on a log scale.
ColorLegend heatmap_legend(const HeatmapPalette& palette, std::string_view what, double cell_m);

}  // namespace trailray::scene
