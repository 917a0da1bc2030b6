// The viewer model's shared computations: the cached colour scale, colouring every track.
#include <cmath>

#include "scene/scene.hpp"
#include "scene/tracks/track_building.hpp"
#include "scene/tracks/track_density.hpp"
#include "ui/viewer_model.hpp"

namespace trailray::ui {

const std::optional<track::ValueRange>& ColorRangeCache::get(const scene::TrackSet& tracks, const scene::Style& style) {
  Key key{style.tracks.color_by, std::nullopt, {}};
  if (style.tracks.range) key.range = std::pair{style.tracks.range->min, style.tracks.range->max};
  key.tracks.reserve(tracks.size() * 2);
  for (const scene::Track& t : tracks.tracks()) {
    key.tracks.push_back(t.id);
    key.tracks.push_back((t.revision << 2) | (t.visible ? 2u : 0u) | (t.by_value ? 1u : 0u));
  }
  if (!key_ || !(*key_ == key)) {
    value_ = scene::color_range(tracks, style);
    key_ = std::move(key);
  }
  return value_;
}

void apply_color_metric(scene::TrackSet& tracks, track::ColorMetric metric, std::optional<double> neighbour_radius_m,
                        const track::ParallelFor& parallel) {
  for (scene::Track& t : tracks.tracks()) scene::apply_color_metric(t, metric);
  if (track::counts_neighbours(metric))
    scene::apply_neighbour_counts(tracks.tracks(), metric,
                                  neighbour_radius_m.value_or(scene::default_neighbour_radius_m(metric)), parallel);
}

void keep_clock_span(ViewerModel& model) {
  const auto span = common_time_span(model.tracks);
  if (!span) return;
  const auto& current = model.clock.span();
  if (!current || current->start != span->start || current->end != span->end) model.clock.set_span(*span);
}

void apply_curtain(scene::TrackSet& tracks, bool on, double neutral_ground_m) {
  for (scene::Track& t : tracks.tracks()) scene::apply_curtain(t, on, neutral_ground_m);
}

}  // namespace trailray::ui
