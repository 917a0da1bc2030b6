#include "render/track_gpu.hpp"

#include <algorithm>
#include <unordered_set>

namespace trailray::render {

CapsuleShape route_shape(const scene::TrackStyle& style) {
  CapsuleShape shape;
  shape.width = scene::TrackWidth{0.5 * style.width.value, style.width.unit};
  shape.min_width_px = std::max(1.0, 0.5 * style.min_width_px);
  shape.dash_px = kRouteDashPx;
  return shape;
}

std::vector<TrackDraw> TrackGpu::draws(const scene::TrackSet& tracks, bool by_value, const scene::TrackStyle& style) {
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
    out.push_back({buffer, track.color_srgb, by_value && track.by_value && !track.is_route,
                   track.is_route ? route_shape(style) : CapsuleShape{}, false});
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
