// ViewerSettings to and from what `render` uses: the command line's track style in, the track
// pass's settings out.
#include <cmath>

#include "app/view/viewer_model.hpp"

namespace trailray::app::view {

ViewerSettings settings_from_style(const TrackStyle& style) {
  ViewerSettings s;
  s.color_by = style.metric;
  s.colormap = style.settings.colormap;
  s.range = style.range;
  s.width = style.settings.width;
  s.occlusion = style.settings.occlusion;
  s.curtain = style.settings.curtain;
  s.legend = style.legend;
  return s;
}

std::optional<track::ValueRange> effective_range(const std::vector<ViewerTrack>& tracks,
                                                 const ViewerSettings& settings) {
  if (settings.color_by == track::ColorMetric::solid) return std::nullopt;
  if (settings.range) return settings.range;
  std::vector<std::vector<float>> values;
  for (const ViewerTrack& t : tracks) {
    if (!t.visible || !t.by_value) continue;
    for (const auto& line : t.geometry.segments)
      if (!line.values.empty()) values.push_back(line.values);
  }
  return track::robust_range(values, track::color_metric_is_signed(settings.color_by));
}

render::TrackSceneSettings track_scene_settings(const std::vector<ViewerTrack>& tracks,
                                                const ViewerSettings& settings) {
  render::TrackSceneSettings out;
  out.width = settings.width;
  out.occlusion = settings.occlusion;
  out.curtain = settings.curtain;
  out.colormap = settings.colormap;
  if (const auto range = effective_range(tracks, settings)) {
    out.value_min = static_cast<float>(range->min);
    out.value_max = static_cast<float>(range->max);
  }
  return out;
}

}  // namespace trailray::app::view
