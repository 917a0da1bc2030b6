#include "scene/pictures/overlaid_imagery.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace trailray::scene {

using terrain::ImageTile;
using terrain::TileResult;
using terrain::TileStatus;

namespace {

// The pixel of `image` at (u, v) in 0..1 over its extent (nearest), RGBA.
const std::uint8_t* pixel_at(const ImageTile& image, double u, double v) {
  const auto col = std::min<std::uint32_t>(image.width - 1, static_cast<std::uint32_t>(std::max(0.0, u * image.width)));
  const auto row = std::min<std::uint32_t>(image.height - 1, static_cast<std::uint32_t>(std::max(0.0, v * image.height)));
  return &image.rgba[(std::size_t{row} * image.width + col) * 4];
}

}  // namespace

TileResult<ImageTile> load_or_enlarge(terrain::ImagerySource& source, const terrain::TileId& tile,
                                      terrain::StopToken stop) {
  const terrain::SourceInfo& info = source.info();
  if (tile.zoom <= info.max_zoom) return source.load(tile, stop);
  std::optional<terrain::TileId> ancestor = tile;
  while (ancestor && ancestor->zoom > info.max_zoom) ancestor = geo::parent(*ancestor);
  if (!ancestor) return {};
  TileResult<ImageTile> coarse = source.load(*ancestor, stop);
  if (coarse.status != TileStatus::ok || coarse.tile.width == 0 || coarse.tile.height == 0) return coarse;
  // The tile covers [x0, x0 + span] x [y0, y0 + span] of the ancestor (0..1).
  const double span = std::ldexp(1.0, -(tile.zoom - ancestor->zoom));
  const double x0 = (tile.x - (static_cast<double>(ancestor->x) / span)) * span;
  const double y0 = (tile.y - (static_cast<double>(ancestor->y) / span)) * span;
  TileResult<ImageTile> out;
  out.status = TileStatus::ok;
  out.tile.id = tile;
  out.tile.width = coarse.tile.width;
  out.tile.height = coarse.tile.height;
  out.tile.rgba.resize(coarse.tile.rgba.size());
  for (std::uint32_t r = 0; r < out.tile.height; ++r)
    for (std::uint32_t c = 0; c < out.tile.width; ++c) {
      const std::uint8_t* p = pixel_at(coarse.tile, x0 + (c + 0.5) / out.tile.width * span,
                                       y0 + (r + 0.5) / out.tile.height * span);
      std::copy(p, p + 4, &out.tile.rgba[(std::size_t{r} * out.tile.width + c) * 4]);
    }
  return out;
}

OverlaidImagery::OverlaidImagery(std::unique_ptr<terrain::ImagerySource> base,
                                 std::unique_ptr<terrain::ImagerySource> overlay, float opacity)
    : base_(std::move(base)), overlay_(std::move(overlay)), opacity_(std::clamp(opacity, 0.0f, 1.0f)) {
  if (!overlay_) throw terrain::SourceError("an overlay without a source");
  const terrain::SourceInfo& over = overlay_->info();
  info_ = base_ ? base_->info() : over;
  info_.name = base_ ? base_->info().name + " + " + over.name : over.name;
  info_.min_zoom = base_ ? std::min(info_.min_zoom, over.min_zoom) : over.min_zoom;
  info_.max_zoom = base_ ? std::max(info_.max_zoom, over.max_zoom) : over.max_zoom;
  if (base_ && info_.bounds && over.bounds) {
    info_.bounds->min_lat = std::min(info_.bounds->min_lat, over.bounds->min_lat);
    info_.bounds->min_lon = std::min(info_.bounds->min_lon, over.bounds->min_lon);
    info_.bounds->max_lat = std::max(info_.bounds->max_lat, over.bounds->max_lat);
    info_.bounds->max_lon = std::max(info_.bounds->max_lon, over.bounds->max_lon);
  } else if (base_) {
    info_.bounds.reset();  // one of them covers everywhere
  }
  info_.format = "png";
  if (base_ && !over.attribution.empty())
    info_.attribution = info_.attribution.empty() ? over.attribution : info_.attribution + "; " + over.attribution;
}

TileResult<ImageTile> OverlaidImagery::load(const terrain::TileId& tile, terrain::StopToken stop) {
  TileResult<ImageTile> base;
  if (base_ && tile.zoom >= base_->info().min_zoom) {
    base = load_or_enlarge(*base_, tile, stop);
    if (base.status == TileStatus::cancelled) return base;
  }
  TileResult<ImageTile> over;
  if (tile.zoom >= overlay_->info().min_zoom) over = load_or_enlarge(*overlay_, tile, stop);
  if (over.status == TileStatus::failed || over.status == TileStatus::cancelled) return over;
  if (over.status != TileStatus::ok) return base;
  // Without the base's tile (none there, offline, a failure) the overlay is drawn over the tint:
  // what it shows matters more than the imagery under it.
  if (base.status != TileStatus::ok) {
    if (opacity_ < 1.0f)
      for (std::size_t i = 3; i < over.tile.rgba.size(); i += 4)
        over.tile.rgba[i] = static_cast<std::uint8_t>(std::lround(over.tile.rgba[i] * opacity_));
    over.tile.id = tile;
    return over;
  }
  // Over the base, pixel by pixel at the base's size ("over" in sRGB, as map overlays are drawn).
  ImageTile& out = base.tile;
  for (std::uint32_t r = 0; r < out.height; ++r)
    for (std::uint32_t c = 0; c < out.width; ++c) {
      const std::uint8_t* o = pixel_at(over.tile, (c + 0.5) / out.width, (r + 0.5) / out.height);
      std::uint8_t* b = &out.rgba[(std::size_t{r} * out.width + c) * 4];
      const float a = o[3] / 255.0f * opacity_;
      if (a <= 0.0f) continue;
      for (int k = 0; k < 3; ++k) b[k] = static_cast<std::uint8_t>(std::lround(o[k] * a + b[k] * (1.0f - a)));
      b[3] = static_cast<std::uint8_t>(std::lround(255.0f * (a + b[3] / 255.0f * (1.0f - a))));
    }
  out.id = tile;
  return base;
}

}  // namespace trailray::scene
