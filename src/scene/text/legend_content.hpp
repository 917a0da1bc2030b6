#pragma once
// What the legend says about a scene: for tracks coloured by a metric, a colour bar titled with
// the metric's name and unit ("Speed (km/h)", "Elapsed time (h:mm)"), its range's ends as the
// metric prints them, and a "0" tick for signed metrics; for several solid tracks, a key of their
// names and colours; for flight phases both: the climb in thermals as a bar over a key of the
// gliding and no-value colours; the airspace classes drawn, as a key of their own above it.
// Drawing is scene/text/legend.hpp's; this file decides the content.

#include <cstdint>
#include <optional>
#include <vector>

#include "scene/camera/framing.hpp"
#include "scene/text/legend.hpp"
#include "scene/pictures/rgba_image.hpp"
#include "scene/scene.hpp"

namespace trailray::scene {

// nullopt for solid colours or without a range (no point had a value).
std::optional<ColorLegend> color_legend_for(const TrackStyle& style, const std::optional<track::ValueRange>& range);

// The key of the visible tracks' names: only for several solid tracks (one track needs no key).
// For --color-by phase instead the colours off the climb's bar: "gliding" and "ground, gaps".
std::vector<TrackKeyEntry> track_key_for(const TrackStyle& style, const TrackSet& tracks);

// The key of the airspace classes drawn (airspace_volumes.hpp), stacked above the other legend:
// empty without visible airspaces.
std::vector<TrackKeyEntry> airspace_key_for(const Scene& scene);

// Draws the legend the scene calls for into `image` (nothing with style.legend off).
void draw_scene_legend(RgbaImage& image, const Scene& scene);

// The panel draw_scene_legend will draw into a `width` x `height` picture, measured by the
// legend's own layout; empty when it draws nothing.
PixelRect scene_legend_panel(std::uint32_t width, std::uint32_t height, const Scene& scene);
// The same with a rasterizer of the caller's (none is started for the call).
PixelRect scene_legend_panel(std::uint32_t width, std::uint32_t height, const Scene& scene, TextRasterizer& text);

// What the framing keeps the tracks out of for a legend `panel` in the bottom-left corner of a
// picture `height` pixels tall: the panel with, above and to its right, the gap it keeps from
// the picture's edges. Nothing for an empty panel.
KeptClearCorner legend_clearance(const PixelRect& panel, std::uint32_t height);

}  // namespace trailray::scene
