#pragma once
// Decoded tiles kept in memory under a byte budget, least recently used evicted first. Tiles are
// shared (shared_ptr<const Tile>), so evicting one that a renderer still holds only drops the
// cache's reference. Not thread-safe by itself: TileLoader guards it.

#include <cstddef>
#include <list>
#include <memory>
#include <unordered_map>

#include "terrain/tile.hpp"

namespace trailray::terrain {

template <class Tile>
class TileMemoryCache {
 public:
  explicit TileMemoryCache(std::size_t budget_bytes) : budget_(budget_bytes) {}

  // The tile, marked as just used; nullptr when absent.
  std::shared_ptr<const Tile> get(const TileId& id) {
    auto it = entries_.find(id);
    if (it == entries_.end()) return nullptr;
    order_.splice(order_.begin(), order_, it->second.position);
    return it->second.tile;
  }

  bool contains(const TileId& id) const { return entries_.contains(id); }

  // Inserts (or replaces) a tile, then evicts the least recently used ones while over budget,
  // except pinned tiles (those the current view still wants: evicting them would only load them
  // again) and the new one: a view that wants more than the budget holds goes over it.
  template <class Pinned>
  void put(const TileId& id, std::shared_ptr<const Tile> tile, const Pinned& pinned) {
    erase(id);
    const std::size_t bytes = tile->byte_size();
    order_.push_front(id);
    entries_.emplace(id, Entry{std::move(tile), bytes, order_.begin()});
    used_ += bytes;
    for (auto it = order_.end(); used_ > budget_ && it != std::next(order_.begin());) {
      --it;
      if (pinned(*it)) continue;
      const TileId victim = *it;
      it = std::next(it);  // erase() invalidates only the victim's position
      erase(victim);
    }
  }
  void put(const TileId& id, std::shared_ptr<const Tile> tile) {
    put(id, std::move(tile), [](const TileId&) { return false; });
  }

  void erase(const TileId& id) {
    auto it = entries_.find(id);
    if (it == entries_.end()) return;
    used_ -= it->second.bytes;
    order_.erase(it->second.position);
    entries_.erase(it);
  }

  std::size_t used_bytes() const { return used_; }
  std::size_t budget_bytes() const { return budget_; }
  std::size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    std::shared_ptr<const Tile> tile;
    std::size_t bytes;
    typename std::list<TileId>::iterator position;
  };
  std::size_t budget_;
  std::size_t used_ = 0;
  std::list<TileId> order_;  // most recently used first
  std::unordered_map<TileId, Entry> entries_;
};

}  // namespace trailray::terrain
