#pragma once
// The tracks of a scene on the GPU: one TrackBuffer per (track id, revision), uploaded the first
// time a frame draws that revision and reused after, freed once the track (or that revision of
// it) has left the scene. Front ends hand the renderer tracks, never GPU buffers.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "render/gl/gpu_resource_cache.hpp"
#include "render/passes/track_buffer.hpp"
#include "render/passes/track_pass.hpp"
#include "scene/track_set.hpp"

namespace trailray::render {

// A route next to the recorded tracks: half their width (never under a pixel), dashed.
inline constexpr float kRouteDashPx = 7.0f;
CapsuleShape route_shape(const scene::TrackStyle& style);

class TrackGpu {
 public:
  void begin_frame() { buffers_.begin_frame(); }
  // The visible tracks as the track pass draws them (by value when `by_value` and the track is;
  // routes in route_shape), uploading the buffers of tracks not seen at their revision yet. The
  // buffers stay valid until the next evict.
  std::vector<TrackDraw> draws(const scene::TrackSet& tracks, bool by_value, const scene::TrackStyle& style = {});
  // Between frames: frees the buffers of tracks no longer in `tracks` (nullptr: none is) and of
  // their old revisions. Hidden tracks keep theirs.
  void evict(const scene::TrackSet* tracks);

  GpuCacheStats stats() const { return buffers_.stats(); }

 private:
  struct Key {
    scene::TrackId id = 0;
    std::uint64_t revision = 0;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const noexcept {
      return std::hash<std::uint64_t>{}(k.id) * 31u + std::hash<std::uint64_t>{}(k.revision);
    }
  };
  // Tracks are never evicted for their size: a scene draws all of its tracks.
  GpuResourceCache<Key, TrackBuffer, KeyHash> buffers_{std::numeric_limits<std::size_t>::max()};
};

}  // namespace trailray::render
