#include "app/drawing/overlay_source.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/pictures/heatmap_output.hpp"
#include "scene/pictures/heatmap_colors.hpp"
#include "scene/pictures/heatmap_imagery.hpp"

namespace trailray::app {

OverlaySource open_overlay_source(const TerrainOptions& options, const terrain::SourceContext& context) {
  const auto colormap = scene::parse_colormap(options.overlay_colormap);
  if (!colormap)
    throw CLI::ValidationError("--overlay-colormap", fmt::format("'{}' is not a colormap", options.overlay_colormap));
  OverlaySource out;
  if (terrain::CountSource counts = terrain::open_count_source(options.overlay); counts.values) {
    scene::HeatmapPalette palette;
    palette.colormap = *colormap;
    palette.max_count = static_cast<std::uint32_t>(std::clamp(counts.maximum, 1.0, 4294967295.0));
    const std::optional<track::HeatmapMeasure> measure = track::parse_heatmap_measure(counts.what);
    out.legend = scene::heatmap_legend(palette, measure ? heatmap_measure_title(*measure) : "Count", counts.cell_m);
    out.imagery = std::make_unique<scene::HeatmapImagery>(std::move(counts.values), palette);
    return out;
  }
  if (const std::optional<track::HeatmapDescription> heatmap = describe_heatmap_tiles(options.overlay)) {
    // The colours its tiles were painted with (unknown names: the defaults, as the legend is all they change).
    scene::HeatmapPalette palette;
    palette.colormap = scene::parse_colormap(heatmap->colormap).value_or(palette.colormap);
    palette.scale = scene::parse_heatmap_scale(heatmap->scale).value_or(palette.scale);
    palette.max_count = std::max<std::uint32_t>(heatmap->max_count, 1);
    out.legend = scene::heatmap_legend(palette, heatmap_measure_title(heatmap->measure), heatmap->cell_m);
  }
  terrain::SourceSettings settings;
  settings.source = options.overlay;
  out.imagery = terrain::open_imagery_source(settings, context);
  if (!out.imagery) throw terrain::SourceError("--overlay none: give a heatmap or an imagery source");
  return out;
}

}  // namespace trailray::app
