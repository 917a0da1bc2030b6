#include "app/scene_frames.hpp"

#include "scene/sun_position.hpp"

namespace trailray::app {

render::SceneRenderOptions SceneFrames::options_for(const scene::Scene& s) {
  render::SceneRenderOptions o;
  const scene::Style& style = s.style;
  o.sun_direction_ecef = scene::sun_direction_ecef(s.sun_time_unix_s);
  o.neutral_ground_height_m = s.neutral_ground_m;
  o.ssao = style.shading.ssao;
  o.shadows = style.shading.shadows;
  o.atmosphere = style.shading.atmosphere;
  o.snow = {style.shading.snow.enabled, style.shading.snow.snowline_m};
  render::TrackSceneSettings& t = o.track_settings;
  const scene::TrackStyle& ts = style.tracks;
  t.width = ts.width;
  t.min_width_px = ts.min_width_px;
  t.occlusion = {ts.occlusion.enabled, ts.occlusion.alpha, ts.occlusion.fade_near_m, ts.occlusion.fade_far_m};
  t.curtain = ts.curtain;
  t.curtain_alpha = ts.curtain_alpha;
  t.colormap = ts.colormap;
  t.cast_shadows = ts.cast_shadows;
  if (s.color_range) {
    t.value_min = static_cast<float>(s.color_range->min);
    t.value_max = static_cast<float>(s.color_range->max);
  }
  if (s.tracks == nullptr) return o;
  std::map<scene::TrackId, std::pair<std::uint64_t, std::unique_ptr<render::TrackBuffer>>> kept;
  for (const scene::Track& track : s.tracks->tracks()) {
    auto& slot = kept[track.id];
    if (auto it = buffers_.find(track.id); it != buffers_.end() && it->second.first == track.revision)
      slot = std::move(it->second);
    else
      slot = {track.revision, std::make_unique<render::TrackBuffer>(track.geometry)};
    if (track.visible) o.tracks.push_back({slot.second.get(), track.color_srgb, s.color_range && track.by_value});
  }
  buffers_ = std::move(kept);
  return o;
}

}  // namespace trailray::app
