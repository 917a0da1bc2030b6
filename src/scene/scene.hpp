#pragma once
// A scene: what the renderer draws from a camera (render::Renderer::draw). The terrain (a view
// onto the height and imagery sources that hands out the tiles a camera needs), the tracks, the
// style, the sun's time. Front ends (render, view, and later video and the browser) build one and
// keep it; nothing in it touches GL.

#include <glm/glm.hpp>

#include <limits>
#include <optional>
#include <vector>

#include "scene/pictures/image_paint.hpp"
#include "scene/text/legend.hpp"
#include "scene/style.hpp"
#include "scene/tracks/track_set.hpp"
#include "scene/volumes/volumes.hpp"
#include "scene/pins/waypoints.hpp"
#include "track/color_values.hpp"

namespace trailray::scene {

class TerrainView;

struct Scene {
  // The terrain: nullptr draws the neutral ground everywhere. Not const: asking it for a camera's
  // tiles requests the missing ones.
  TerrainView* terrain = nullptr;
  const TrackSet* tracks = nullptr;        // nullptr: no tracks
  const WaypointSet* waypoints = nullptr;  // nullptr: no waypoints or place labels
  const VolumeSet* volumes = nullptr;      // nullptr: no airspaces or task cylinders
  Style style;
  // The colour scale in use (color_range(*tracks, style)); nullopt: solid colours.
  std::optional<track::ValueRange> color_range;
  // The colour bar of what --overlay draws on the terrain (a heatmap), drawn above the tracks'.
  std::optional<ColorLegend> overlay_legend;
  double sun_time_unix_s = 0.0;  // where the sun stands (scene/camera/sun_position.hpp)
  // A light from a fixed direction instead (unit, towards it, ECEF): a sun placed by azimuth and
  // elevation rather than by time.
  std::optional<glm::dvec3> sun_direction_ecef;
  // Where no source has terrain the neutral ground is drawn at this height; NaN: at the lowest
  // terrain loaded for the view (0 where there is none).
  double neutral_ground_m = std::numeric_limits<double>::quiet_NaN();
  // Parts of the picture no label may cover besides the legend the picture gets (which labels
  // always avoid): the viewer's legend window. Picture pixels, y down.
  std::vector<PixelRect> label_keep_out;
};

// The colour scale: style.tracks.range, else the robust range over the values of the visible
// tracks coloured by value (nullopt: solid, or no value anywhere): 2nd to 98th percentile; the
// counts of density and thermals to whole ends (thermals from 0, density from at least 1).
std::optional<track::ValueRange> color_range(const TrackSet& tracks, const Style& style);

// Unit vector towards the sun in ECEF: the fixed direction when there is one, else the sun's at
// sun_time_unix_s.
glm::dvec3 sun_direction(const Scene& scene);

}  // namespace trailray::scene
