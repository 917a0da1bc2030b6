#include "scene/style.hpp"

#include <fast_float/fast_float.h>
#include <fmt/format.h>

#include <cmath>
#include <string>

namespace trailray::scene {

Colormap default_colormap(track::ColorMetric metric) {
  if (metric == track::ColorMetric::phase || metric == track::ColorMetric::thermals) return Colormap::warm;
  if (metric == track::ColorMetric::density) return Colormap::magma;
  if (metric == track::ColorMetric::cover) return Colormap::cover;
  return track::color_metric_is_signed(metric) ? Colormap::diverging : Colormap::turbo;
}

double default_neighbour_radius_m(track::ColorMetric metric) {
  return metric == track::ColorMetric::thermals ? 200.0 : 100.0;
}

double neighbour_radius_m(const TrackStyle& style) {
  return style.neighbour_radius_m.value_or(default_neighbour_radius_m(style.color_by));
}

Result<TrackWidth> parse_track_width(std::string_view text) {
  const auto fail = [&] {
    return Result<TrackWidth>{std::nullopt, fmt::format("--width: '{}' is not a width: a positive number of metres "
                                                        "or pixels, e.g. 8m or 6px",
                                                        text)};
  };
  std::string_view rest = text;
  while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = fast_float::from_chars(rest.data(), rest.data() + rest.size(), value);
  if (ec != std::errc() || end == rest.data()) return fail();
  std::string_view unit(end, static_cast<std::size_t>(rest.data() + rest.size() - end));
  while (!unit.empty() && unit.front() == ' ') unit.remove_prefix(1);
  while (!unit.empty() && unit.back() == ' ') unit.remove_suffix(1);
  TrackWidth width;
  width.value = value;
  if (unit == "m")
    width.unit = TrackWidth::Unit::metres;
  else if (unit == "px")
    width.unit = TrackWidth::Unit::pixels;
  else
    return fail();
  if (!std::isfinite(value) || !(value > 0.0) || value > 1.0e6) return fail();
  return {width, {}};
}

}  // namespace trailray::scene
