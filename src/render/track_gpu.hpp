#pragma once
// The tracks of a scene on the GPU. The recorded tracks, shown or hidden, share one TrackBuffer,
// so that a season of 10,000 tracks is drawn in a few draw calls with each track's colour and
// visibility from a small table (TrackDraw::track_styles): uploaded the first frame that draws
// them, reused while every track keeps its (id, revision), rebuilt when one changes, arrives or
// leaves; showing or hiding a track or changing its colour uploads nothing. Routes (few, dashed
// in a shape of their own) get one buffer per (id, revision). Front ends hand the renderer
// tracks, never GPU buffers.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "render/gl/gpu_resource_cache.hpp"
#include "render/passes/track_buffer.hpp"
#include "render/passes/track_pass.hpp"
#include "scene/tracks/track_set.hpp"

namespace trailray::render {

// A route next to the recorded tracks: half their width (never under a pixel), dashed.
inline constexpr float kRouteDashPx = 7.0f;
CapsuleShape route_shape(const scene::TrackStyle& style);

class TrackGpu {
 public:
  void begin_frame() { buffers_.begin_frame(); }
  // The visible tracks as the track pass draws them (by value when `by_value` and the track is;
  // routes in route_shape), uploading what is not on the GPU at its revision yet. The draws (their
  // buffers and styles) stay valid until the next draws or evict.
  std::vector<TrackDraw> draws(const scene::TrackSet& tracks, bool by_value, const scene::TrackStyle& style = {});
  // Between frames: frees the buffers of tracks no longer in `tracks` (nullptr: none is) and of
  // their old revisions. Hidden tracks keep theirs.
  void evict(const scene::TrackSet* tracks);

  // Entries: the recorded tracks' shared buffer counts as one; uploads: its rebuilds count once.
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
  // The recorded tracks' buffer is cached under this key (no track has id 0: TrackSet numbers
  // from 1), its revision counting the rebuilds; `recorded_` is what it holds, in order.
  static constexpr scene::TrackId kRecordedId = 0;
  std::uint64_t recorded_revision_ = 0;
  std::vector<Key> recorded_;
  std::vector<TrackDrawStyle> styles_;  // the frame's, one per recorded track
  // The (id, revision) of each recorded track (not a route) of the set, in order.
  static std::vector<Key> recorded_keys(const scene::TrackSet& tracks);
  // Tracks are never evicted for their size: a scene draws all of its tracks.
  GpuResourceCache<Key, TrackBuffer, KeyHash> buffers_{std::numeric_limits<std::size_t>::max()};
};

}  // namespace trailray::render
