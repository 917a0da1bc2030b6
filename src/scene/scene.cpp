#include "scene/scene.hpp"

#include "scene/sun_position.hpp"

namespace trailray::scene {

std::optional<track::ValueRange> color_range(const TrackSet& tracks, const Style& style) {
  const track::ColorMetric metric = style.tracks.color_by;
  if (metric == track::ColorMetric::solid) return std::nullopt;
  if (style.tracks.range) return style.tracks.range;
  std::vector<std::vector<float>> values;
  for (const Track& t : tracks.tracks()) {
    if (!t.visible || !t.by_value) continue;
    for (const TrackPolyline& line : t.geometry.segments)
      if (!line.values.empty()) values.push_back(line.values);
  }
  return track::robust_range(values, track::color_metric_is_signed(metric));
}

glm::dvec3 sun_direction(const Scene& scene) {
  return scene.sun_direction_ecef ? *scene.sun_direction_ecef : sun_direction_ecef(scene.sun_time_unix_s);
}

}  // namespace trailray::scene
