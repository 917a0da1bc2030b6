#pragma once
// The profile chart: a track's altitude and the terrain below it against distance or
// time, the line coloured like the track in the 3D view; an IGC flight with both altitudes has a
// second line, its GNSS and pressure altitudes both shown whichever the 3D track is drawn at, and a
// legend says which that is (`--igc-altitude`). Hovering marks a point (HoverState, read
// by the 3D view), a point hovered in the 3D view is marked here, and a drag selects a range
// whose statistics are shown under the chart.
//
// The mapping between the mouse and the points is pure (below), so tests check it without a
// window; draw_profile_chart only draws and forwards the mouse to it.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "ui/viewer_model.hpp"

namespace trailray::ui {

// A point's position along the chart's x axis: cumulative distance in metres, or seconds since
// the track's first timestamp (NaN for a point without a time).
double chart_x(const scene::Track& track, ChartAxis axis, std::size_t point);

// What the chart spans: x over the points that have an x, y over altitudes (all, when a track
// has a GNSS or pressure altitude) and ground heights (a flat range is widened by 1 m each way). nullopt: no point has
// an x (time axis without times), or no point has an altitude or a ground height.
struct ChartExtent {
  double x_min = 0.0, x_max = 0.0;
  double y_min = 0.0, y_max = 0.0;
};
std::optional<ChartExtent> chart_extent(const scene::Track& track, ChartAxis axis);

// The altitude lines of a track's chart, in drawing order. The altitude the 3D track is drawn at
// (altitude_m) is coloured like it and named after the IGC altitude it is (Track::altitude_source);
// an IGC flight's GNSS and pressure altitudes that are not that one follow, dashed. Empty: no
// altitude at all.
struct AltitudeLine {
  enum class Source { drawn, gnss, pressure };
  Source source = Source::drawn;  // altitude_m, gnss_altitude_m or pressure_altitude_m
  bool in_3d = false;             // the 3D track is drawn at this altitude
  std::string label;              // for the chart's legend
};
std::vector<AltitudeLine> altitude_lines(const scene::Track& track);

// Pixel column <-> x value over a plot `plot_width` pixels wide starting at `plot_left` (the
// mouse is clamped to the plot).
double x_at_pixel(float pixel_x, float plot_left, float plot_width, const ChartExtent& extent);
float pixel_at_x(double x, float plot_left, float plot_width, const ChartExtent& extent);

// The point whose x is nearest to `x` (the first of equals); nullopt when no point has an x.
std::optional<std::size_t> point_at_x(const scene::Track& track, ChartAxis axis, double x);

// The point under the mouse: point_at_x(x_at_pixel(mouse_x)).
std::optional<std::size_t> hover_point(const scene::Track& track, ChartAxis axis, float mouse_x, float plot_left,
                                       float plot_width);

// The colour (sRGB 0..1) the 3D view gives a point: by value through the colormap when the track
// is coloured by a metric and the scale has a range, else the track's solid colour.
glm::vec3 point_color(const scene::Track& track, const ViewerSettings& settings,
                      const std::optional<track::ValueRange>& range, std::size_t point);

// The statistics the chart's selection and the statistics panel show, one line each:
// points and segments, distance (km), duration and moving time (h:mm:ss), climb and descent (m),
// lowest and highest altitude (m), average and top speed (km/h), fastest climb and sink (m/s).
// A figure the track does not have reads "—".
std::vector<std::string> statistics_lines(const track::Statistics& statistics);

// The chart window's contents (call inside an ImGui window): axis toggle, track choice, the plot
// and the selection's statistics.
void draw_profile_chart(ViewerModel& model);

}  // namespace trailray::ui
