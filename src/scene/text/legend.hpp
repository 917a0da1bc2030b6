#pragma once
// The legend drawn into the rendered picture: for tracks coloured by a metric, a
// colour bar with the metric's name and unit above it and the range's ends under it; for several
// solid-coloured tracks, a key of track names. Drawn on the CPU into the read-back image
// (RgbaImage: top-down rows, sRGB bytes), so the headless `render` command and the viewer (which
// uploads the same pixels as a texture) show the same legend.
//
// Placement: the bottom-left corner, a margin away from the edges, on a rounded translucent dark
// panel with white text, so it reads on snow as well as on forest. Everything scales with the
// image height (legend_font_px), readable from 640x360 to 3840x2160. Nothing is ever written
// outside the image: a legend that cannot fit is left out (LegendLayout::drawn is false), and a
// key taller than the image lists what fits and ends with "+N more".
//
// The colour bar samples colormap_table, the table the track pass uploads, so the bar
// and the tracks always agree.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/pictures/colormap.hpp"
#include "scene/pictures/rgba_image.hpp"
#include "scene/pictures/image_paint.hpp"
#include "scene/text/text_raster.hpp"

namespace trailray::scene {

// A label inside the colour bar's range, e.g. "0" at the middle of a diverging map.
struct LegendTick {
  double position = 0.0;  // 0 = the bar's left end (the range's minimum), 1 = its right end
  std::string label;
};

struct ColorLegend {
  std::string title;  // the metric and its unit, e.g. "Speed (km/h)"; empty: no title line
  Colormap map = Colormap::turbo;
  std::string min_label, max_label;  // the range's ends, formatted (format_legend_value)
  std::vector<LegendTick> ticks;     // optional; labels that would overlap others are left out
};

struct TrackKeyEntry {
  std::string name;      // UTF-8; cut with "…" past kMaxTrackNameCodePoints or the image's width
  glm::vec3 color_srgb;  // the track's solid colour, sRGB 0..1
  // A planned route: its swatch is dashed, as the route is drawn (rather than a " (route)"
  // after its name, which cut long names such as a score's).
  bool dashed = false;
};

// The dashes of a dashed swatch `width` long: {start, length} pairs, three dashes with two gaps.
std::vector<std::pair<int, int>> swatch_dashes(int width);

inline constexpr std::size_t kMaxTrackKeyRows = 12;  // a longer key ends in a "+N more" row
inline constexpr std::size_t kMaxTrackNameCodePoints = 40;

struct LegendOptions {
  int font_px = 0;          // text size in pixels; 0: legend_font_px(image height)
  int reserved_bottom = 0;  // rows at the image's bottom already taken (by another legend's
                            // panel): this legend goes above them
};

// Where a legend was drawn, in image pixels (for tests and for stacking legends).
struct LegendLayout {
  bool drawn = false;  // false: it did not fit (or had nothing to show); the image is unchanged
  int font_px = 0;
  PixelRect panel;                    // everything drawn lies inside it
  PixelRect bar;                      // the colour bar itself (inside its thin outline)
  std::vector<PixelRect> text_boxes;  // each line of text drawn (title, labels, names, "+N more")
  std::vector<PixelRect> swatches;    // the key's colour swatches, one per listed track, in order
  std::size_t hidden_entries = 0;     // tracks summed up in "+N more"
};

// The legend's text size for an image `image_height` pixels tall: height / 45, within 11..40.
int legend_font_px(std::uint32_t image_height);

// A range end for a legend label: as many decimals as a range `span` wide needs (none from 10
// up, one from 1, two below), a true minus sign (U+2212), no "-0".
std::string format_legend_value(double value, double span);

LegendLayout draw_color_legend(RgbaImage& image, TextRasterizer& text, const ColorLegend& legend,
                               const LegendOptions& options = {});

// Nothing for an empty list.
LegendLayout draw_track_key(RgbaImage& image, TextRasterizer& text, const std::vector<TrackKeyEntry>& entries,
                            const LegendOptions& options = {});

// The panel the functions above would draw in an image of that size, measured by the same
// layout code without drawing anything (so the picture can be framed around the legend before
// it is rendered); empty where they would draw nothing.
PixelRect color_legend_panel(std::uint32_t image_width, std::uint32_t image_height, TextRasterizer& text,
                             const ColorLegend& legend, const LegendOptions& options = {});
PixelRect track_key_panel(std::uint32_t image_width, std::uint32_t image_height, TextRasterizer& text,
                          const std::vector<TrackKeyEntry>& entries, const LegendOptions& options = {});

}  // namespace trailray::scene
