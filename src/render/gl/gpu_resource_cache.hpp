#pragma once
// GPU resources (tile meshes, imagery textures) kept across frames under a byte budget, the least
// recently used evicted first, so a viewer flying for hours holds a bounded amount of GPU memory
// and a place seen again a moment ago is still uploaded.
//
// "Used" is counted in frames: a resource used in the current frame is never evicted (the frame's
// draw list points at it), so a frame that needs more than the budget keeps all it uses, and the
// surplus goes once later frames stop using it. Eviction runs only between frames
// (evict_to_budget after the frame is drawn). No GL here: evicting destroys the Value, whose
// destructor frees its GL objects; the tests use plain values.

#include <cstddef>
#include <functional>
#include <list>
#include <unordered_map>
#include <utility>

namespace trailray::render {

// A cache's figures after a frame (FrameReport).
struct GpuCacheStats {
  std::size_t entries = 0;         // held now
  std::size_t bytes = 0;           // held now (estimated GPU memory)
  std::size_t budget_bytes = 0;    // evicted down to this between frames, except the frame's own
  std::size_t frame_entries = 0;   // used by the last frame
  std::size_t frame_bytes = 0;     // of those
  std::size_t uploads = 0;         // by the last frame
  std::size_t uploaded_bytes = 0;  // by the last frame
  std::size_t evictions = 0;       // after the last frame
};

template <class Key, class Value, class Hash = std::hash<Key>>
class GpuResourceCache {
 public:
  explicit GpuResourceCache(std::size_t budget_bytes) : budget_(budget_bytes) {}

  // Starts a frame: what was used before it may be evicted after it; the frame's counters restart.
  void begin_frame() {
    ++frame_;
    frame_entries_ = frame_bytes_ = uploads_ = uploaded_bytes_ = evictions_ = 0;
  }

  // The value, marked as used in this frame; nullptr when absent. The pointer stays valid until
  // the entry is replaced or evicted (never within the frame that used it).
  Value* find(const Key& key) {
    auto it = entries_.find(key);
    if (it == entries_.end()) return nullptr;
    touch(it->second);
    return &it->second.value;
  }

  // Inserts (or replaces) a value of `bytes` GPU memory, marked as used in this frame (counted as
  // an upload). Never evicts: that waits for the end of the frame.
  Value& insert(const Key& key, Value value, std::size_t bytes) {
    erase(key);
    order_.push_front(key);
    auto& entry = entries_.emplace(key, Entry{std::move(value), bytes, frame_, order_.begin()}).first->second;
    used_ += bytes;
    frame_entries_ += 1;
    frame_bytes_ += bytes;
    uploads_ += 1;
    uploaded_bytes_ += bytes;
    return entry.value;
  }

  // Evicts the least recently used entries not used in this frame while over the budget.
  void evict_to_budget() {
    while (used_ > budget_ && !order_.empty()) {
      const auto victim = entries_.find(order_.back());
      // Most recently used first: from here on everything was used in this frame.
      if (victim->second.last_frame == frame_) break;
      used_ -= victim->second.bytes;
      order_.pop_back();
      entries_.erase(victim);
      ++evictions_;
    }
  }

  // Erases every entry whose key `keep` rejects (counted as evictions), whenever it was used.
  template <class Keep>
  void retain_if(Keep keep) {
    for (auto it = order_.begin(); it != order_.end();) {
      const Key key = *it++;
      if (keep(key)) continue;
      erase(key);
      ++evictions_;
    }
  }

  void erase(const Key& key) {
    auto it = entries_.find(key);
    if (it == entries_.end()) return;
    used_ -= it->second.bytes;
    if (it->second.last_frame == frame_) {
      frame_entries_ -= 1;
      frame_bytes_ -= it->second.bytes;
    }
    order_.erase(it->second.position);
    entries_.erase(it);
  }
  void clear() {
    entries_.clear();
    order_.clear();
    used_ = frame_entries_ = frame_bytes_ = 0;
  }

  void set_budget(std::size_t budget_bytes) { budget_ = budget_bytes; }
  std::size_t budget_bytes() const { return budget_; }
  std::size_t used_bytes() const { return used_; }
  std::size_t size() const { return entries_.size(); }
  bool contains(const Key& key) const { return entries_.contains(key); }
  bool used_this_frame(const Key& key) const {
    auto it = entries_.find(key);
    return it != entries_.end() && it->second.last_frame == frame_;
  }

  GpuCacheStats stats() const {
    return {entries_.size(), used_, budget_, frame_entries_, frame_bytes_, uploads_, uploaded_bytes_, evictions_};
  }

 private:
  struct Entry {
    Value value;
    std::size_t bytes;
    std::size_t last_frame;
    typename std::list<Key>::iterator position;
  };

  void touch(Entry& entry) {
    if (entry.last_frame != frame_) {
      entry.last_frame = frame_;
      frame_entries_ += 1;
      frame_bytes_ += entry.bytes;
    }
    order_.splice(order_.begin(), order_, entry.position);
  }

  std::size_t budget_;
  std::size_t used_ = 0;
  std::size_t frame_ = 0;
  std::size_t frame_entries_ = 0, frame_bytes_ = 0, uploads_ = 0, uploaded_bytes_ = 0, evictions_ = 0;
  std::list<Key> order_;  // most recently used first
  std::unordered_map<Key, Entry, Hash> entries_;
};

}  // namespace trailray::render
