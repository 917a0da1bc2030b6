#pragma once
// The legend in the live window: the same content as the legend `render` draws into pictures
// (app/track_legend.hpp: a colour bar with the metric, unit and range, or a key of track names),
// drawn with ImGui in a small window of its own, first in the bottom-left corner.

#include <optional>
#include <vector>

#include "render/legend.hpp"

namespace trailray::app::view {

// Call between ImGui::NewFrame and ImGui::Render.
void draw_legend_overlay(const std::optional<render::ColorLegend>& legend,
                         const std::vector<render::TrackKeyEntry>& key);

}  // namespace trailray::app::view
