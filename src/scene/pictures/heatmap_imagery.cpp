#include "scene/pictures/heatmap_imagery.hpp"

#include <cstring>
#include <utility>

namespace trailray::scene {

HeatmapImagery::HeatmapImagery(std::unique_ptr<terrain::HeightSource> counts, HeatmapPalette palette)
    : counts_(std::move(counts)), palette_(palette) {
  if (!counts_) throw terrain::SourceError("a heatmap overlay without a source");
}

terrain::TileResult<terrain::ImageTile> HeatmapImagery::load(const terrain::TileId& tile, terrain::StopToken stop) {
  terrain::TileResult<terrain::HeightTile> counts = counts_->load(tile, stop);
  terrain::TileResult<terrain::ImageTile> out;
  out.status = counts.status;
  out.error = std::move(counts.error);
  if (counts.status != terrain::TileStatus::ok) return out;
  const terrain::HeightTile& c = counts.tile;
  out.tile.id = tile;
  out.tile.width = c.width;
  out.tile.height = c.height;
  out.tile.rgba.resize(c.heights.size() * 4);
  bool any = false;
  for (std::size_t i = 0; i < c.heights.size(); ++i) {
    const glm::u8vec4 rgba = heatmap_rgba(palette_, c.heights[i]);  // NaN and 0: transparent
    std::memcpy(&out.tile.rgba[i * 4], &rgba, 4);
    any = any || rgba.a != 0;
  }
  if (!any) {
    out = {};
    out.status = terrain::TileStatus::no_data;
  }
  return out;
}

}  // namespace trailray::scene
