#pragma once
// How a scene is drawn: the one struct the command line parses into (app/options) and the
// viewer's panels edit, read by the renderer each frame. Plain values, no GL.

#include <glm/glm.hpp>

#include <optional>
#include <string_view>
#include <vector>

#include "scene/camera/camera.hpp"
#include "scene/pictures/colormap.hpp"
#include "track/color_values.hpp"

namespace trailray::scene {

// A tube's diameter: metres (perspective) or pixels (constant on screen).
struct TrackWidth {
  enum class Unit { metres, pixels };
  double value = 5.0;
  Unit unit = Unit::pixels;
};
// "8m", "8 m", "6px", "6 px" (value > 0, finite, at most 1000 km). The error quotes the text and
// the forms.
Result<TrackWidth> parse_track_width(std::string_view text);

// The parts of tracks the terrain hides: drawn translucent ("ghosts"), fading with depth.
struct TrackOcclusion {
  bool enabled = true;        // false (`--occlusion off`): hidden parts are not drawn at all
  float alpha = 0.45f;        // `--occluded-alpha`
  float fade_near_m = 100.f;  // `--occlusion-fade NEAR:FAR`: constant alpha to NEAR metres behind
  float fade_far_m = 1000.f;  // the terrain, fading to 0 at FAR
};

struct TrackStyle {
  TrackWidth width;
  double min_width_px = 1.5;  // a distant tube never gets thinner than this (no dotted tracks)
  TrackOcclusion occlusion;
  bool curtain = false;  // `--curtain`: a translucent wall down to the ground
  float curtain_alpha = 0.3f;
  bool cast_shadows = true;
  // Colour: by a per-point metric through a colormap over a range, else solid colours.
  track::ColorMetric color_by = track::ColorMetric::solid;
  Colormap colormap = Colormap::turbo;
  std::optional<track::ValueRange> range;  // nullopt: the robust range of the visible tracks' values
  std::vector<glm::vec3> colors;           // `--color`, sRGB: none (the palette), one for all, or one per track
  // `--density-radius`: how near a track must pass to count for density and thermals; nullopt:
  // default_neighbour_radius_m of the metric.
  std::optional<double> neighbour_radius_m;
  // Routes (planned, GPX rte): a solid colour unlike the palette's that reads on terrain
  // (`--route-color`), half the tracks' width, dashed.
  glm::vec3 route_color{1.0f, 0.88f, 0.0f};
};

// Pins: a thin stem from the ground up to a marker (a ball), for waypoints and (smaller) place
// labels. Sizes in pixels, never under the metres given when the camera is near.
struct PinStyle {
  glm::vec3 waypoint_color{0.89f, 0.0f, 0.17f};  // sRGB: the markers of the files' waypoints
  glm::vec3 place_color{0.96f, 0.96f, 0.96f};    // and of place labels
  glm::vec3 thermal_color{1.0f, 0.55f, 0.1f};    // and of thermal markers (`--thermals`)
  glm::vec3 photo_color{0.97f, 0.97f, 0.97f};   // and of photos' pins (`--photos`), under their thumbnail
  glm::vec3 stem_color{0.16f, 0.16f, 0.16f};
  // A photo's thumbnail over its pin: its long side on the picture (pixels at pixel ratio 1), in
  // a white frame.
  double photo_px = 72.0;
  double marker_px = 13.0, place_marker_px = 8.0;  // the ball's diameter
  double marker_m = 6.0, place_marker_m = 4.0;     // ... at least
  double stem_px = 2.0, stem_m = 0.6;              // the stem's diameter, at least
  // The ball rests this high above the marker's position (pixels, at least metres), so a waypoint
  // on the ground still stands on a stem; the labels sit above it.
  double lift_px = 18.0, lift_m = 8.0, place_lift_px = 10.0, place_lift_m = 5.0;
};

// Snow by altitude and slope on the terrain.
struct SnowCover {
  bool enabled = false;
  double snowline_m = 2500.0;
};

struct Shading {
  bool shadows = true;     // cascaded shadow maps of the sun (`--no-shadows`)
  bool ssao = true;        // screen-space ambient occlusion (`--no-ssao`)
  bool atmosphere = true;  // aerial perspective and sky (`--no-atmosphere`: no haze, a flat sky)
  SnowCover snow;          // `--snow`, `--snowline M`
};

// The names drawn over the picture (scene/text/label_layout.hpp, the renderer's labels pass): of
// waypoints, place labels and tracks (at their start).
struct LabelStyle {
  bool enabled = true;  // `--no-labels`
  int size_px = 13;     // `--label-size`: the text's em size at pixel ratio 1 (scaled by the frame's)
  // A label whose point the terrain hides: drawn faint (`--hidden-labels ghost`, with this
  // opacity) or not at all (`hide`).
  bool hide_occluded = false;
  float ghost_alpha = 0.3f;
};
inline constexpr int kMinLabelSizePx = 6, kMaxLabelSizePx = 96;

// The colormap a metric gets unless one is asked for: diverging for signed metrics (vspeed),
// warm for the climb in thermals (phase, and the thermal map: thermals), magma for density (a
// heat map: few tracks dark, many bright), turbo for the rest.
Colormap default_colormap(track::ColorMetric metric);

// The radius of density and thermals unless one is given: 100 m for density (a street, a
// valley's path: runs on the two pavements count together, the next street not), 200 m for
// thermals (a thermal's circles and their drift with the wind).
double default_neighbour_radius_m(track::ColorMetric metric);
// The style's radius for its metric.
double neighbour_radius_m(const TrackStyle& style);

struct Style {
  TrackStyle tracks;
  Shading shading;
  bool legend = true;  // `--legend`: colour bar or key of track names
  PinStyle pins;
  LabelStyle labels;
};

}  // namespace trailray::scene
