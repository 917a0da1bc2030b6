// The profile chart: pure mapping between points and pixels, and its ImGui drawing.
#include "ui/profile_chart.hpp"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/pictures/colormap.hpp"
#include "scene/tracks/track_building.hpp"
#include "ui/flight_panel.hpp"
#include "ui/waypoint_view.hpp"

namespace trailray::ui {
namespace {

constexpr const char* kMissingText = "\u2014";

std::string hms(const std::optional<double>& seconds) {
  if (!seconds || !std::isfinite(*seconds)) return kMissingText;
  const auto s = static_cast<long long>(std::llround(*seconds));
  return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
}

std::string number(const std::optional<double>& v, int decimals, const char* unit, const char* sign = "") {
  if (!v || !std::isfinite(*v)) return kMissingText;
  return fmt::format("{}{:.{}f} {}", sign, *v, decimals, unit);
}

ImU32 to_imgui(const glm::vec3& srgb, float alpha = 1.0f) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(srgb.r, srgb.g, srgb.b, alpha));
}

// The flat colour value of a point (the geometry's lines are the non-empty segments, in order).
float point_value(const scene::Track& t, std::size_t point) {
  const std::size_t seg = t.segment_of(point);
  if (seg >= t.geometry.segments.size()) return std::numeric_limits<float>::quiet_NaN();
  const auto& values = t.geometry.segments[seg].values;
  const std::size_t i = point - t.segment_first[seg];
  return i < values.size() ? values[i] : std::numeric_limits<float>::quiet_NaN();
}

constexpr ImU32 kTerrainColour = IM_COL32(120, 100, 80, 200);
// The other altitude lines: light and dashed, unlike any track colour or colormap (solid), and
// unlike one another (both show when neither is drawn in 3D).
constexpr ImU32 kPressureColour = IM_COL32(235, 235, 235, 230);
constexpr ImU32 kGnssColour = IM_COL32(150, 215, 255, 230);
constexpr float kDash = 6.0f, kDashGap = 4.0f;  // pixels

// A line from a to b, drawn only where x falls in a dash: the phase follows x, so consecutive
// pieces of a polyline continue one another's pattern.
void add_dashed_line(ImDrawList* draw, ImVec2 a, ImVec2 b, ImU32 colour, float width) {
  if (a.x > b.x) std::swap(a, b);
  const float span = b.x - a.x;
  if (span < 1e-3f) {
    draw->AddLine(a, b, colour, width);
    return;
  }
  const auto at = [&](float x) { return ImVec2(x, a.y + (b.y - a.y) * (x - a.x) / span); };
  const float period = kDash + kDashGap;
  for (float start = std::floor(a.x / period) * period; start < b.x; start += period) {
    const float x0 = std::max(a.x, start), x1 = std::min(b.x, start + kDash);
    if (x0 < x1) draw->AddLine(at(x0), at(x1), colour, width);
  }
}

ImU32 dashed_colour(AltitudeLine::Source source) {
  return source == AltitudeLine::Source::gnss ? kGnssColour : kPressureColour;
}

// A dashed line's altitude at a point.
double line_altitude(const scene::Track& t, AltitudeLine::Source source, std::size_t point) {
  return source == AltitudeLine::Source::gnss ? t.gnss_altitude(point) : t.pressure_altitude(point);
}

// The legend in the plot's top right corner: the altitude lines and the terrain, when there are
// at least two things to tell apart.
void draw_chart_legend(ImDrawList* draw, const std::vector<AltitudeLine>& lines, bool terrain, ImU32 drawn_colour,
                       float right, float top) {
  if (lines.size() + (terrain ? 1 : 0) < 2) return;
  const float row = ImGui::GetTextLineHeight() + 2.0f, swatch = 18.0f, pad = 6.0f;
  float text_w = 0.0f;
  for (const AltitudeLine& l : lines) text_w = std::max(text_w, ImGui::CalcTextSize(l.label.c_str()).x);
  if (terrain) text_w = std::max(text_w, ImGui::CalcTextSize("terrain").x);
  const float w = pad * 3 + swatch + text_w;
  const float h = pad * 2 + row * static_cast<float>(lines.size() + (terrain ? 1 : 0));
  const float left = right - w - 4.0f, y0 = top + 4.0f;
  draw->AddRectFilled(ImVec2(left, y0), ImVec2(left + w, y0 + h), IM_COL32(15, 15, 20, 200), 3.0f);
  float y = y0 + pad;
  const auto entry = [&](const std::string& label) {
    draw->AddText(ImVec2(left + pad * 2 + swatch, y), IM_COL32(230, 230, 230, 255), label.c_str());
    y += row;
  };
  for (const AltitudeLine& l : lines) {
    const ImVec2 a(left + pad, y + row * 0.5f), b(left + pad + swatch, y + row * 0.5f);
    if (l.source == AltitudeLine::Source::drawn)
      draw->AddLine(a, b, drawn_colour, 2.0f);
    else
      add_dashed_line(draw, a, b, dashed_colour(l.source), 1.5f);
    entry(l.label);
  }
  if (terrain) {
    draw->AddRectFilled(ImVec2(left + pad, y + 3.0f), ImVec2(left + pad + swatch, y + row - 3.0f), kTerrainColour);
    entry("terrain");
  }
}

// Whether the last left press travelled past ImGui's drag threshold (still known after release).
bool dragged() {
  const ImGuiIO& io = ImGui::GetIO();
  return io.MouseDragMaxDistanceSqr[0] >= io.MouseDragThreshold * io.MouseDragThreshold;
}

int chart_track(const ViewerModel& model) {
  if (model.tracks.empty()) return -1;
  if (model.selected_track >= 0 && model.selected_track < static_cast<int>(model.tracks.size()))
    return model.selected_track;
  return 0;
}

// A range's statistics side by side in two columns where both fit in `width`, else one.
int statistics_columns(const std::vector<std::string>& lines, float width) {
  float widest = 0.0f;
  for (const std::string& line : lines) widest = std::max(widest, ImGui::CalcTextSize(line.c_str()).x);
  return 2.0f * widest + 4.0f * ImGui::GetStyle().ItemSpacing.x <= width ? 2 : 1;
}

// The height of what is drawn under the plot (the hint, or the selection and its statistics),
// kept free of the plot so that it shows in full where the window has room for it.
float below_plot_height(const ViewerModel& model, int track, float width) {
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const ChartSelection& sel = model.selection;
  if (sel.track != track || !sel.statistics) return line;
  const std::vector<std::string> lines = statistics_lines(*sel.statistics);
  const auto columns = static_cast<std::size_t>(statistics_columns(lines, width));
  return line * static_cast<float>(1 + (lines.size() + columns - 1) / columns);
}

void draw_selection_statistics(const ViewerModel& model, int track, float width) {
  const ChartSelection& sel = model.selection;
  if (sel.track != track) {
    ImGui::TextDisabled("Drag across the chart to measure a part of the track.");
    return;
  }
  ImGui::Text("Selection: points %zu to %zu", sel.first + 1, sel.last + 1);
  if (!sel.statistics) return;
  const std::vector<std::string> lines = statistics_lines(*sel.statistics);
  const auto columns = static_cast<std::size_t>(statistics_columns(lines, width));
  const std::size_t rows = (lines.size() + columns - 1) / columns;
  const float second_column = ImGui::GetCursorPosX() + width * 0.5f;
  for (std::size_t row = 0; row < rows; ++row) {
    ImGui::TextUnformatted(lines[row].c_str());
    if (columns == 2 && row + rows < lines.size()) {
      ImGui::SameLine(second_column);
      ImGui::TextUnformatted(lines[row + rows].c_str());
    }
  }
}

}  // namespace

double chart_x(const scene::Track& t, ChartAxis axis, std::size_t point) {
  if (point >= t.point_count()) return std::numeric_limits<double>::quiet_NaN();
  return axis == ChartAxis::distance ? t.distance_m[point] : t.elapsed(point);
}

std::optional<ChartExtent> chart_extent(const scene::Track& t, ChartAxis axis) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  ChartExtent e{inf, -inf, inf, -inf};
  for (std::size_t i = 0; i < t.point_count(); ++i) {
    const double x = chart_x(t, axis, i);
    if (std::isnan(x)) continue;
    e.x_min = std::min(e.x_min, x);
    e.x_max = std::max(e.x_max, x);
    for (double y : {t.altitude_m[i], t.ground_m[i], t.pressure_altitude(i), t.gnss_altitude(i)}) {
      if (std::isnan(y)) continue;
      e.y_min = std::min(e.y_min, y);
      e.y_max = std::max(e.y_max, y);
    }
  }
  if (e.x_min > e.x_max || e.y_min > e.y_max) return std::nullopt;
  if (e.y_max - e.y_min < 2.0) {
    e.y_min -= 1.0;
    e.y_max += 1.0;
  }
  return e;
}

std::vector<AltitudeLine> altitude_lines(const scene::Track& t) {
  using Source = AltitudeLine::Source;
  const bool any_altitude =
      std::any_of(t.altitude_m.begin(), t.altitude_m.end(), [](double a) { return !std::isnan(a); });
  const bool gnss = t.has_gnss_altitude(), pressure = t.has_pressure_altitude();
  const scene::Track::AltitudeSource drawn = t.altitude_source();
  std::vector<AltitudeLine> lines;
  if (any_altitude) {
    std::string label = "altitude";
    if (drawn == scene::Track::AltitudeSource::gnss) label = "GNSS altitude (3D track)";
    if (drawn == scene::Track::AltitudeSource::pressure) label = "pressure altitude (3D track)";
    if (drawn == scene::Track::AltitudeSource::none && (gnss || pressure)) label = "altitude (3D track)";
    lines.push_back(AltitudeLine{Source::drawn, true, label});
  }
  const char* suffix = any_altitude ? "" : " (not in 3D)";
  if (gnss && drawn != scene::Track::AltitudeSource::gnss)
    lines.push_back(AltitudeLine{Source::gnss, false, std::string("GNSS altitude") + suffix});
  if (pressure && drawn != scene::Track::AltitudeSource::pressure)
    lines.push_back(AltitudeLine{Source::pressure, false, std::string("pressure altitude") + suffix});
  return lines;
}

double x_at_pixel(float pixel_x, float plot_left, float plot_width, const ChartExtent& e) {
  if (!(plot_width > 0.0f)) return e.x_min;
  const double f = std::clamp(static_cast<double>(pixel_x - plot_left) / plot_width, 0.0, 1.0);
  return e.x_min + f * (e.x_max - e.x_min);
}

float pixel_at_x(double x, float plot_left, float plot_width, const ChartExtent& e) {
  const double span = e.x_max - e.x_min;
  const double f = span > 0.0 ? (x - e.x_min) / span : 0.0;
  return plot_left + static_cast<float>(f) * plot_width;
}

std::optional<std::size_t> point_at_x(const scene::Track& t, ChartAxis axis, double x) {
  std::optional<std::size_t> best;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < t.point_count(); ++i) {
    const double d = std::fabs(chart_x(t, axis, i) - x);
    if (d < best_d) {  // NaN compares false: points without an x are skipped
      best_d = d;
      best = i;
    }
  }
  return best;
}

std::optional<std::size_t> hover_point(const scene::Track& t, ChartAxis axis, float mouse_x, float plot_left,
                                       float plot_width) {
  const auto extent = chart_extent(t, axis);
  if (!extent) return std::nullopt;
  return point_at_x(t, axis, x_at_pixel(mouse_x, plot_left, plot_width, *extent));
}

glm::vec3 point_color(const scene::Track& t, const ViewerSettings& settings,
                      const std::optional<track::ValueRange>& range, std::size_t point) {
  if (settings.style.tracks.color_by == track::ColorMetric::solid || !t.by_value || !range) return t.color_srgb;
  const float v = point_value(t, point);
  if (std::isnan(v)) return scene::kMissingValueColorSrgb;
  if (track::is_category_value(v)) return scene::kCategoryColorSrgb;
  const double span = range->max - range->min;
  const double f = span > 0.0 ? (v - range->min) / span : 0.5;
  return scene::colormap_color(settings.style.tracks.colormap, static_cast<float>(f));
}

std::vector<std::string> statistics_lines(const track::Statistics& s) {
  return {
      fmt::format("points: {}, segments: {}", s.points, s.segments),
      fmt::format("distance: {:.3f} km", s.distance_2d_m / 1000.0),
      fmt::format("duration: {}, moving: {}", hms(s.duration_s), hms(s.moving_time_s)),
      fmt::format("climb: {}, descent: {}", number(s.elevation_gain_m, 0, "m", "+"),
                  number(s.elevation_loss_m, 0, "m", "-")),
      fmt::format("altitude: {} to {}", number(s.min_elevation_m, 0, "m"), number(s.max_elevation_m, 0, "m")),
      fmt::format("speed: {} average, {} top", number(s.avg_speed_kmh, 1, "km/h"), number(s.max_speed_kmh, 1, "km/h")),
      fmt::format("vertical: {} fastest climb, {} fastest sink", number(s.max_climb_ms, 1, "m/s"),
                  number(s.max_sink_ms, 1, "m/s")),
  };
}

void draw_profile_chart(ViewerModel& model) {
  const int ti = chart_track(model);
  if (ti < 0) {
    ImGui::TextDisabled("No track loaded.");
    return;
  }
  scene::Track& t = model.tracks[static_cast<std::size_t>(ti)];
  ViewerSettings& settings = model.settings;

  int axis = settings.chart_axis == ChartAxis::distance ? 0 : 1;
  ImGui::RadioButton("distance", &axis, 0);
  ImGui::SameLine();
  ImGui::RadioButton("time", &axis, 1);
  settings.chart_axis = axis == 0 ? ChartAxis::distance : ChartAxis::time;
  ImGui::SameLine();
  ImGui::Text("  %s", t.name.c_str());

  const auto extent = chart_extent(t, settings.chart_axis);
  if (!extent) {
    ImGui::TextDisabled(settings.chart_axis == ChartAxis::time ? "This track has no times."
                                                               : "This track has no altitudes.");
    return;
  }

  // The plot: the window's width, its height less what is shown below it (the hint, or a range's
  // statistics; the window opens sized from the screen: no scroll bar on a small one), a margin
  // for the axis labels.
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = std::max(50.0f, ImGui::GetContentRegionAvail().x);
  const float height =
      std::clamp(ImGui::GetContentRegionAvail().y - below_plot_height(model, ti, width), 100.0f, 600.0f);
  const float label_w = 48.0f;
  const float left = origin.x + label_w, top = origin.y + 4.0f;
  const float plot_w = width - label_w, plot_h = height - 20.0f;
  const float bottom = top + plot_h;
  ImGui::InvisibleButton("##profile", ImVec2(width, height));
  const bool hovered = ImGui::IsItemHovered();
  const bool active = ImGui::IsItemActive();

  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(ImVec2(left, top), ImVec2(left + plot_w, bottom), IM_COL32(25, 25, 30, 255));
  const auto y_px = [&](double y) {
    return bottom - static_cast<float>((y - extent->y_min) / (extent->y_max - extent->y_min)) * plot_h;
  };
  const auto x_px = [&](std::size_t i) {
    return pixel_at_x(chart_x(t, settings.chart_axis, i), left, plot_w, *extent);
  };

  // Axis labels: altitude at the ends, distance (km) or time (h:mm) at the ends.
  draw->AddText(ImVec2(origin.x, top), IM_COL32(200, 200, 200, 255), fmt::format("{:.0f} m", extent->y_max).c_str());
  draw->AddText(ImVec2(origin.x, bottom - 14.0f), IM_COL32(200, 200, 200, 255),
                fmt::format("{:.0f} m", extent->y_min).c_str());
  const auto x_label = [&](double x) {
    return settings.chart_axis == ChartAxis::distance ? fmt::format("{:.1f} km", x / 1000.0)
                                                      : hms(x).substr(0, hms(x).rfind(':'));
  };
  draw->AddText(ImVec2(left, bottom + 2.0f), IM_COL32(200, 200, 200, 255), x_label(extent->x_min).c_str());
  const std::string right_label = x_label(extent->x_max);
  draw->AddText(ImVec2(left + plot_w - ImGui::CalcTextSize(right_label.c_str()).x, bottom + 2.0f),
                IM_COL32(200, 200, 200, 255), right_label.c_str());

  // The selection behind the lines.
  const ChartSelection& sel = model.selection;
  if (sel.track == ti && sel.last < t.point_count())
    draw->AddRectFilled(ImVec2(x_px(sel.first), top), ImVec2(std::max(x_px(sel.last), x_px(sel.first) + 1.0f), bottom),
                        IM_COL32(255, 255, 255, 40));

  shade_thermals(draw, t, x_px, top, bottom);

  // Terrain and altitudes, one vertex per pixel column at most (a million points stay cheap),
  // never joined across a segment gap.
  const auto range = model.color_range();
  const std::vector<AltitudeLine> lines = altitude_lines(t);
  std::vector<AltitudeLine::Source> dashed;
  for (const AltitudeLine& l : lines)
    if (l.source != AltitudeLine::Source::drawn) dashed.push_back(l.source);
  bool terrain = false;
  for (std::size_t seg = 0; seg < t.segment_first.size(); ++seg) {
    const std::size_t first = t.segment_first[seg];
    const std::size_t end = seg + 1 < t.segment_first.size() ? t.segment_first[seg + 1] : t.point_count();
    std::optional<std::size_t> prev;
    for (std::size_t i = first; i < end; ++i) {
      if (std::isnan(chart_x(t, settings.chart_axis, i))) continue;
      if (prev && i + 1 < end && std::fabs(x_px(i) - x_px(*prev)) < 1.0f) continue;
      if (prev) {
        const float x0 = x_px(*prev), x1 = x_px(i);
        const double g0 = t.ground_m[*prev], g1 = t.ground_m[i];
        if (!std::isnan(g0) && !std::isnan(g1))
          draw->AddQuadFilled(ImVec2(x0, y_px(g0)), ImVec2(x1, y_px(g1)), ImVec2(x1, bottom), ImVec2(x0, bottom),
                              kTerrainColour);
        terrain = terrain || (!std::isnan(g0) && !std::isnan(g1));
        for (const AltitudeLine::Source source : dashed) {
          const double p0 = line_altitude(t, source, *prev), p1 = line_altitude(t, source, i);
          if (!std::isnan(p0) && !std::isnan(p1))
            add_dashed_line(draw, ImVec2(x0, y_px(p0)), ImVec2(x1, y_px(p1)), dashed_colour(source), 1.5f);
        }
        const double a0 = t.altitude_m[*prev], a1 = t.altitude_m[i];
        if (!std::isnan(a0) && !std::isnan(a1))
          draw->AddLine(ImVec2(x0, y_px(a0)), ImVec2(x1, y_px(a1)), to_imgui(point_color(t, settings, range, i)), 2.0f);
      }
      prev = i;
    }
  }

  const ImU32 drawn_colour = settings.style.tracks.color_by == track::ColorMetric::solid || !t.by_value || !range
                                 ? to_imgui(t.color_srgb)
                                 : to_imgui(scene::colormap_color(settings.style.tracks.colormap, 0.5f));
  draw_chart_legend(draw, lines, terrain, drawn_colour, left + plot_w, top);

  // Waypoints near the track: a small pin at their nearest point, with the name.
  for (const ChartWaypoint& c : chart_waypoints(t, model.waypoints)) {
    const scene::Waypoint& w = model.waypoints.points[c.waypoint];
    const float x = x_px(c.point);
    const double a = !std::isnan(t.altitude_m[c.point]) ? t.altitude_m[c.point] : t.ground_m[c.point];
    const float y = std::isnan(a) ? top + 12.0f : y_px(a);
    const ImU32 colour = to_imgui(w.kind == scene::WaypointKind::Place ? settings.style.pins.place_color
                                                                       : settings.style.pins.waypoint_color);
    draw->AddLine(ImVec2(x, y), ImVec2(x, y - 10.0f), IM_COL32(230, 230, 230, 220), 1.0f);
    draw->AddCircleFilled(ImVec2(x, y - 12.0f), 3.5f, colour);
    if (!w.name.empty()) draw->AddText(ImVec2(x + 5.0f, y - 24.0f), IM_COL32(235, 235, 235, 255), w.name.c_str());
  }

  // Hover: the chart sets it; a hover from the 3D view is only drawn.
  if (hovered) {
    if (const auto p = hover_point(t, settings.chart_axis, ImGui::GetIO().MousePos.x, left, plot_w))
      model.hover = {ti, *p, true};
  } else if (model.hover.from_chart && model.hover.track == ti) {
    model.hover = {};
  }
  if (model.hover.track == ti && model.hover.point < t.point_count()) {
    const float x = x_px(model.hover.point);
    draw->AddLine(ImVec2(x, top), ImVec2(x, bottom), IM_COL32(255, 255, 255, 200), 1.0f);
    const double a = t.altitude_m[model.hover.point];
    if (!std::isnan(a)) draw->AddCircleFilled(ImVec2(x, y_px(a)), 4.0f, IM_COL32(255, 255, 255, 255));
    for (const AltitudeLine::Source source : dashed) {
      const double p = line_altitude(t, source, model.hover.point);
      if (!std::isnan(p)) draw->AddCircle(ImVec2(x, y_px(p)), 4.0f, dashed_colour(source), 0, 1.5f);
    }
  }

  // Drag: select from where the button went down to the mouse; a click without a drag clears.
  if (active && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
    const auto a = hover_point(t, settings.chart_axis, ImGui::GetIO().MouseClickedPos[0].x, left, plot_w);
    const auto b = hover_point(t, settings.chart_axis, ImGui::GetIO().MousePos.x, left, plot_w);
    if (a && b) model.selection = {ti, std::min(*a, *b), std::max(*a, *b), std::nullopt};
  }
  if (ImGui::IsItemDeactivated()) {
    if (model.selection.track == ti && !model.selection.statistics && model.selection.last > model.selection.first)
      model.selection.statistics =
          scene::range_statistics(t, model.selection.first, model.selection.last, model.analysis);
    else if (!dragged())
      model.selection = {};
  }
  draw_selection_statistics(model, ti, width);
}

}  // namespace trailray::ui
