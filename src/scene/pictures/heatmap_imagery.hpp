#pragma once
// A raster of counts (the GeoTIFF `trailray heatmap -o X.tif` writes, or any one-band count
// raster) as imagery for --overlay: its tiles (warped with the largest count under each pixel,
// GdalResampling::max) coloured by heatmap_colors, transparent where nothing was counted.

#include <memory>

#include "scene/pictures/heatmap_colors.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::scene {

class HeatmapImagery final : public terrain::ImagerySource {
 public:
  explicit HeatmapImagery(std::unique_ptr<terrain::HeightSource> counts, HeatmapPalette palette);

  const terrain::SourceInfo& info() const override { return counts_->info(); }
  terrain::TileResult<terrain::ImageTile> load(const terrain::TileId& tile, terrain::StopToken stop) override;

 private:
  std::unique_ptr<terrain::HeightSource> counts_;
  HeatmapPalette palette_;
};

}  // namespace trailray::scene
