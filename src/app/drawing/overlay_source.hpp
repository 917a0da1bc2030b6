#pragma once
// --overlay SRC opened: a heatmap's counts GeoTIFF coloured here (scene/pictures/heatmap_imagery), a
// heatmap's tiles (.mbtiles, folder) as they are with the legend their metadata describes, or
// any other imagery source as it is, without a legend.

#include <memory>
#include <optional>

#include "app/options/terrain_options.hpp"
#include "scene/text/legend.hpp"
#include "terrain/sources/source_factory.hpp"

namespace trailray::app {

struct OverlaySource {
  std::unique_ptr<terrain::ImagerySource> imagery;
  std::optional<scene::ColorLegend> legend;
};

// Throws terrain::SourceError naming the source, std::runtime_error for a damaged heatmap and
// CLI::ValidationError for an unknown --overlay-colormap.
OverlaySource open_overlay_source(const TerrainOptions& options, const terrain::SourceContext& context);

}  // namespace trailray::app
