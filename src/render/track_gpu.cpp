#include "render/track_gpu.hpp"

#include <unordered_set>

namespace trailray::render {

std::vector<TrackDraw> TrackGpu::draws(const scene::TrackSet& tracks, bool by_value) {
  std::vector<TrackDraw> out;
  for (const scene::Track& track : tracks.tracks()) {
    if (!track.visible) continue;
    const Key key{track.id, track.revision};
    TrackBuffer* buffer = buffers_.find(key);
    if (buffer == nullptr) {
      TrackBuffer uploaded(track.geometry);
      const std::size_t bytes = uploaded.gpu_bytes();
      buffer = &buffers_.insert(key, std::move(uploaded), bytes);
    }
    out.push_back({buffer, track.color_srgb, by_value && track.by_value});
  }
  return out;
}

void TrackGpu::evict(const scene::TrackSet* tracks) {
  std::unordered_set<Key, KeyHash> current;
  if (tracks != nullptr)
    for (const scene::Track& track : tracks->tracks()) current.insert({track.id, track.revision});
  buffers_.retain_if([&](const Key& key) { return current.contains(key); });
}

}  // namespace trailray::render
