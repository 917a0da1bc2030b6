#include "scene/scene.hpp"

#include <algorithm>
#include <cmath>

#include "scene/camera/sun_position.hpp"

namespace trailray::scene {

std::optional<track::ValueRange> color_range(const TrackSet& tracks, const Style& style) {
  const track::ColorMetric metric = style.tracks.color_by;
  if (metric == track::ColorMetric::solid) return std::nullopt;
  // Three classes, each always in its own colour (Colormap::cover's bands).
  if (metric == track::ColorMetric::cover) return track::ValueRange{0.0, 2.0};
  if (style.tracks.range) return style.tracks.range;
  std::vector<std::vector<float>> values;
  for (const Track& t : tracks.tracks()) {
    if (!t.visible || !t.by_value) continue;
    for (const TrackPolyline& line : t.geometry.segments)
      if (!line.values.empty()) values.push_back(line.values);
  }
  const auto range = track::robust_range(values, track::color_metric_is_signed(metric));
  if (track::counts_neighbours(metric) && range) {
    // Counts are whole numbers: whole ends, at least one apart. Thermals start at 0 (no flight
    // climbed here); a density count is at least 1 (the point's own track).
    const double low = metric == track::ColorMetric::thermals ? 0.0 : std::max(1.0, std::floor(range->min));
    return track::ValueRange{low, std::max(std::ceil(range->max), low + 1.0)};
  }
  if (metric != track::ColorMetric::phase) return range;
  // The climb in thermals starts at zero (a circle that loses height is as good as none) and
  // shows at least 1 m/s; gliding alone (no circling value) still gets a scale for the legend.
  if (range) return track::ValueRange{0.0, std::max(range->max, 1.0)};
  for (const auto& v : values)
    if (std::any_of(v.begin(), v.end(), track::is_category_value)) return track::ValueRange{0.0, 3.0};
  return std::nullopt;
}

glm::dvec3 sun_direction(const Scene& scene) {
  return scene.sun_direction_ecef ? *scene.sun_direction_ecef : sun_direction_ecef(scene.sun_time_unix_s);
}

}  // namespace trailray::scene
