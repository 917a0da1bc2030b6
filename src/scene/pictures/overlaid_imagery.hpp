#pragma once
// An overlay drawn over the ground's imagery (`--overlay`: a heatmap, a map of trails, any
// imagery with transparency): one ImagerySource whose tiles are the overlay's composited over the
// base imagery's, so every front end (render, view, video, the page through `serve`) draws it with
// nothing new in the renderer. Without base imagery the overlay's tiles go out alone, transparent
// around it, and the terrain pass shows its tint by height through them.
//
// The two sources need not have the same zoom levels: where one has no tile that fine, its finest
// ancestor is cut and enlarged (nearest pixel: a heatmap's cells stay crisp).

#include <memory>

#include "terrain/sources/tile_source.hpp"

namespace trailray::scene {

class OverlaidImagery final : public terrain::ImagerySource {
 public:
  // `base` may be nullptr (the tint). `opacity` (0..1) scales the overlay's own alpha.
  OverlaidImagery(std::unique_ptr<terrain::ImagerySource> base, std::unique_ptr<terrain::ImagerySource> overlay,
                  float opacity = 1.0f);

  const terrain::SourceInfo& info() const override { return info_; }

  // ok with the composite where either has a tile (the overlay alone where the base failed:
  // offline, say); the base's failure where the overlay has nothing there; the overlay's failure
  // always (a broken overlay is not silently left out).
  terrain::TileResult<terrain::ImageTile> load(const terrain::TileId& tile, terrain::StopToken stop) override;

 private:
  std::unique_ptr<terrain::ImagerySource> base_, overlay_;
  float opacity_;
  terrain::SourceInfo info_;
};

// The tile of `source` covering `tile`: its own, or where `tile` is finer than the source's
// finest level, the part of the finest ancestor over it, enlarged to the ancestor's pixel size.
terrain::TileResult<terrain::ImageTile> load_or_enlarge(terrain::ImagerySource& source, const terrain::TileId& tile,
                                                        terrain::StopToken stop);

}  // namespace trailray::scene
