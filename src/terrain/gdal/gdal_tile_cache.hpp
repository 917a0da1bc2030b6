#pragma once
// The warped tiles a GDAL source keeps: least recently used first out, within a byte budget.
// Thread-safe. Internal to the terrain library.

#include <cstddef>
#include <list>
#include <mutex>
#include <optional>
#include <unordered_map>
#include <utility>

#include "terrain/loading/stop_token.hpp"
#include "terrain/tile.hpp"

namespace trailray::terrain::gdal_detail {

// Tile: HeightTile or ImageTile (anything with an id and byte_size()).
template <class Tile>
class WarpedTileCache {
 public:
  explicit WarpedTileCache(std::size_t budget_bytes) : budget_bytes_(budget_bytes) {}

  // A copy of the cached tile (the caller owns its result; a copy costs far less than a warp).
  std::optional<Tile> find(const TileId& id) {
    std::lock_guard lock(mutex_);
    auto found = index_.find(id);
    if (found == index_.end()) return std::nullopt;
    tiles_.splice(tiles_.begin(), tiles_, found->second);
    return tiles_.front();
  }

  void insert(const Tile& tile) {
    const std::size_t size = tile.byte_size();
    if (size > budget_bytes_) return;
    std::lock_guard lock(mutex_);
    if (auto found = index_.find(tile.id); found != index_.end()) {
      used_bytes_ -= found->second->byte_size();
      tiles_.erase(found->second);
      index_.erase(found);
    }
    tiles_.push_front(tile);
    index_.emplace(tile.id, tiles_.begin());
    used_bytes_ += size;
    while (used_bytes_ > budget_bytes_) {
      used_bytes_ -= tiles_.back().byte_size();
      index_.erase(tiles_.back().id);
      tiles_.pop_back();
    }
  }

 private:
  const std::size_t budget_bytes_;
  std::mutex mutex_;
  std::list<Tile> tiles_;  // most recently used first
  std::unordered_map<TileId, typename std::list<Tile>::iterator> index_;
  std::size_t used_bytes_ = 0;
};

// The load() of both GDAL sources: an invalid id fails, a cancelled request stops, a cached tile
// is returned, a tile the raster cannot cover is no_data, anything else is warped and cached.
// Impl has `raster` (OpenedRaster), `tiles` (WarpedTileCache<Tile>) and warp(id, stop).
template <class Tile, class Impl>
TileResult<Tile> load_warped_tile(Impl& impl, const TileId& tile, StopToken stop) {
  TileResult<Tile> result;
  if (!geo::is_valid(tile)) {
    result.status = TileStatus::failed;
    result.error = impl.raster.tile_error(tile, "invalid tile id");
    return result;
  }
  if (stop.stop_requested()) {
    result.status = TileStatus::cancelled;
    return result;
  }
  if (std::optional<Tile> cached = impl.tiles.find(tile)) {
    result.status = TileStatus::ok;
    result.tile = std::move(*cached);
    return result;
  }
  if (!impl.raster.may_cover(tile)) return result;  // no_data
  result = impl.warp(tile, stop);
  if (result.status == TileStatus::ok) impl.tiles.insert(result.tile);
  return result;
}

}  // namespace trailray::terrain::gdal_detail
