#pragma once
// The legend in the live window: the same content as the legend `render` draws into pictures
// (app/track_legend.hpp: a colour bar with the metric, unit and range, or a key of track names),
// drawn with ImGui in a small window of its own, first in the bottom-left corner.

#include <optional>
#include <vector>

#include "scene/text/legend.hpp"

namespace trailray::app::view {

// Call between ImGui::NewFrame and ImGui::Render.
void draw_legend_overlay(const std::optional<scene::ColorLegend>& legend, const std::vector<scene::TrackKeyEntry>& key);
// The --overlay's colour bar (a heatmap's) the same way, in a window of its own first just above
// the tracks' legend (`legend` and `key`, as given to draw_legend_overlay).
void draw_overlay_legend(const scene::ColorLegend& overlay, const std::optional<scene::ColorLegend>& legend,
                         const std::vector<scene::TrackKeyEntry>& key);

// Where draw_legend_overlay first puts its window in a display of that size (the bottom-left
// corner), from the same layout, in whole pixels covering it; empty when it shows nothing. Needs
// an ImGui context, not a frame (the atlas is built if it is not yet).
scene::PixelRect legend_overlay_rect(const std::optional<scene::ColorLegend>& legend,
                                     const std::vector<scene::TrackKeyEntry>& key, float display_width,
                                     float display_height);

}  // namespace trailray::app::view
