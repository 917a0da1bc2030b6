#include "render/track_gpu.hpp"

#include <algorithm>
#include <span>
#include <unordered_set>
#include <vector>

namespace trailray::render {

CapsuleShape route_shape(const scene::TrackStyle& style) {
  CapsuleShape shape;
  shape.width = scene::TrackWidth{0.5 * style.width.value, style.width.unit};
  shape.min_width_px = std::max(1.0, 0.5 * style.min_width_px);
  shape.dash_px = kRouteDashPx;
  return shape;
}

std::vector<TrackGpu::Key> TrackGpu::recorded_keys(const scene::TrackSet& tracks) {
  std::vector<Key> keys;
  for (const scene::Track& track : tracks.tracks())
    if (!track.is_route) keys.push_back({track.id, track.revision});
  return keys;
}

std::vector<TrackDraw> TrackGpu::draws(const scene::TrackSet& tracks, bool by_value, const scene::TrackStyle& style) {
  std::vector<TrackDraw> out;
  std::vector<Key> recorded = recorded_keys(tracks);
  std::vector<const scene::TrackGeometry*> geometries;
  styles_.clear();
  bool any_shown = false;
  for (const scene::Track& track : tracks.tracks()) {
    if (track.is_route) continue;
    geometries.push_back(&track.geometry);
    styles_.push_back({track.color_srgb, by_value && track.by_value, track.visible});
    any_shown = any_shown || track.visible;
  }
  if (recorded != recorded_) {
    recorded_ = std::move(recorded);
    ++recorded_revision_;
  }
  if (!recorded_.empty()) {
    const Key key{kRecordedId, recorded_revision_};
    TrackBuffer* buffer = buffers_.find(key);
    if (buffer == nullptr) {
      TrackBuffer uploaded{std::span<const scene::TrackGeometry* const>(geometries)};
      const std::size_t bytes = uploaded.gpu_bytes();
      buffer = &buffers_.insert(key, std::move(uploaded), bytes);
    }
    if (any_shown) {
      TrackDraw draw;
      draw.buffer = buffer;
      draw.track_styles = styles_;
      out.push_back(draw);
    }
  }
  for (const scene::Track& track : tracks.tracks()) {
    if (!track.is_route || !track.visible) continue;
    const Key key{track.id, track.revision};
    TrackBuffer* buffer = buffers_.find(key);
    if (buffer == nullptr) {
      TrackBuffer uploaded(track.geometry);
      const std::size_t bytes = uploaded.gpu_bytes();
      buffer = &buffers_.insert(key, std::move(uploaded), bytes);
    }
    out.push_back({buffer, track.color_srgb, false, route_shape(style), false, {}});
  }
  return out;
}

void TrackGpu::evict(const scene::TrackSet* tracks) {
  std::unordered_set<Key, KeyHash> current;
  if (tracks != nullptr)
    for (const scene::Track& track : tracks->tracks())
      if (track.is_route) current.insert({track.id, track.revision});
  // The recorded tracks' buffer while the set still holds exactly what it was built from.
  if (tracks != nullptr && !recorded_.empty() && recorded_keys(*tracks) == recorded_)
    current.insert({kRecordedId, recorded_revision_});
  buffers_.retain_if([&](const Key& key) { return current.contains(key); });
}

}  // namespace trailray::render
