#pragma once
// What the legend says about a rendered track scene (issue 5): for a metric, a colour bar titled
// with the metric's name and unit ("Speed (km/h)", "Elapsed time (h:mm)"), its range's ends as
// the metric prints them, and a "0" tick for signed metrics; for several solid tracks, a key of
// their names and colours. Drawing is render/legend.hpp's; this file only decides the content.

#include <cstdint>
#include <optional>
#include <vector>

#include "app/track_scene.hpp"
#include "app/track_style_options.hpp"
#include "scene/rgba_image.hpp"
#include "scene/framing.hpp"
#include "scene/legend.hpp"

namespace trailray::app {

// nullopt for solid colours or when no point had a value.
std::optional<scene::ColorLegend> color_legend_for(const TrackStyle& style, const TrackScene& scene);

// The key of track names: only for several solid tracks (one track needs no key).
std::vector<scene::TrackKeyEntry> track_key_for(const TrackStyle& style, const TrackScene& scene);

// Draws the legend the scene calls for into `image` (nothing with --legend off).
void draw_scene_legend(scene::RgbaImage& image, const TrackStyle& style, const TrackScene& scene);

// The panel draw_scene_legend will draw into a `width` x `height` picture, measured by the
// legend's own layout; empty when it draws nothing.
scene::PixelRect scene_legend_panel(std::uint32_t width, std::uint32_t height, const TrackStyle& style,
                                     const TrackScene& scene);

// What the framing keeps the tracks out of for a legend `panel` in the bottom-left corner of a
// picture `height` pixels tall: the panel with, above and to its right, the gap it keeps from
// the picture's edges. Nothing for an empty panel.
scene::KeptClearCorner legend_clearance(const scene::PixelRect& panel, std::uint32_t height);

}  // namespace trailray::app
