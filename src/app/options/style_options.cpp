#include "app/options/style_options.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <charconv>
#include <cmath>

#include "track/density.hpp"
#include "track/io/parse_util.hpp"

namespace trailray::app {
namespace {

bool parse_on_off(const std::string& text, const char* option) {
  if (text == "on") return true;
  if (text == "off") return false;
  throw CLI::ValidationError(option, fmt::format("'{}' is neither on nor off", text));
}

}  // namespace

void add_track_style_options(CLI::App& command, StyleArgs& args) {
  const std::string metrics = fmt::format("{}", fmt::join(track::color_metric_names(), "|"));
  command
      .add_option("--width", args.width,
                  "Tube diameter: metres (perspective, e.g. 8m) or pixels (constant on screen, e.g. 6px); "
                  "never under 1.5 px on screen (default 5px)")
      ->type_name("W{m|px}");
  command
      .add_option("--color-by", args.color_by,
                  "Colour tracks by a per-point metric: speed km/h, vspeed m/s, slope %, altitude m, agl m "
                  "(height above the terrain), hr bpm, cadence rpm, power W, time (elapsed), phase (flights: the climb "
                  "in m/s where circling in thermals, gliding in blue, the ground grey), density (many tracks: how "
                  "many passed within --density-radius of each point, its own included), thermals (many flights: "
                  "how many climbed in a thermal within --density-radius); default solid")
      ->type_name(metrics);
  command
      .add_option("--colormap", args.colormap,
                  "Colormap for --color-by (default turbo; diverging for vspeed: sink blue, zero white, climb red; "
                  "warm for phase and thermals: weak climb or few flights yellow, strong or many dark red; magma "
                  "for density: few tracks dark, many bright)")
      ->type_name("turbo|viridis|magma|cividis|diverging|warm");
  command
      .add_option("--range", args.range,
                  "Colour scale range in the metric's unit (default: 2nd to 98th percentile of the values)")
      ->type_name("MIN:MAX");
  command
      .add_option("--density-radius", args.density_radius,
                  fmt::format("How near (horizontally) a track must pass a point to count for --color-by density "
                              "or thermals, metres, {:g}..{:g} (default 100 for density, 200 for thermals)",
                              track::kMinNeighbourRadiusM, track::kMaxNeighbourRadiusM))
      ->type_name("M");
  command
      .add_option("--color", args.colors,
                  "Solid colour: one for every track, or one per track in order (default: a qualitative palette)")
      ->type_name("'#rrggbb'")
      ->allow_extra_args(false);  // one value per --color: the words after it are tracks
  command
      .add_option("--route-color", args.route_color,
                  "Colour of routes (planned, GPX rte), drawn dashed at half the tracks' width (default '#ffe000')")
      ->type_name("'#rrggbb'");
  command.add_option("--legend", args.legend, "Legend (colour bar, or key of track names) in the image (default on)")
      ->type_name("on|off");
  command
      .add_option("--occlusion", args.occlusion,
                  "Draw the parts of tracks hidden by terrain translucent (on, default) or not at all (off)")
      ->type_name("on|off");
  command.add_option("--occluded-alpha", args.occluded_alpha, "Opacity of hidden track parts, 0..1 (default 0.45)")
      ->type_name("A");
  command
      .add_option("--occlusion-fade", args.occlusion_fade,
                  "Hidden parts keep their opacity to NEAR metres behind the terrain, then fade out by FAR "
                  "(default 100:1000)")
      ->type_name("NEAR:FAR");
  command.add_flag("--curtain", args.curtain,
                   "A translucent wall from the track down to the terrain, coloured like the track (for flights)");
}

void add_shading_options(CLI::App& cmd, StyleArgs& args) {
  cmd.add_option("--time", args.time, "Date and time for the sun, ISO 8601 (e.g. 2024-06-18T12:00:00Z)")
      ->type_name("ISO8601");
  cmd.add_flag("--no-ssao", args.no_ssao, "No ambient occlusion (valleys and hollows not darkened)");
  cmd.add_flag("--no-atmosphere", args.no_atmosphere, "No aerial perspective or sky gradient (no haze, a flat sky)");
  cmd.add_flag("--no-shadows", args.no_shadows, "No cast shadows (slopes still shaded by their angle to the sun)");
  cmd.add_flag("--snow", args.snow,
               "Snow cover: white from the snowline up, on slopes under about 40-50 degrees (rock faces stay bare)");
  cmd.add_option("--snowline", args.snowline_m, "Altitude of the snowline for --snow, metres (default 2500)")
      ->check(CLI::Range(-500.0, 9000.0))
      ->type_name("M");
}

void add_label_options(CLI::App& cmd, StyleArgs& args) {
  cmd.add_flag("--no-labels", args.no_labels, "No names over the picture (of waypoints, places and tracks)");
  cmd.add_option("--label-size", args.label_size_px,
                 fmt::format("Label text size in pixels, scaled by the pixel ratio (default 13, {}..{})",
                             scene::kMinLabelSizePx, scene::kMaxLabelSizePx))
      ->type_name("PX");
  cmd.add_option("--hidden-labels", args.hidden_labels,
                 "Labels whose point the terrain hides: drawn faint (ghost, default) or not at all (hide)")
      ->type_name("ghost|hide");
}

scene::Style parse_style(const StyleArgs& args) {
  scene::Style out;
  scene::TrackStyle& style = out.tracks;
  auto width = scene::parse_track_width(args.width);
  if (!width.ok()) throw CLI::ValidationError(width.error);
  style.width = *width.value;

  const auto metric = track::parse_color_metric(args.color_by);
  if (!metric)
    throw CLI::ValidationError("--color-by", fmt::format("'{}' is not one of {}", args.color_by,
                                                         fmt::join(track::color_metric_names(), ", ")));
  style.color_by = *metric;
  style.colormap = scene::default_colormap(*metric);
  if (!args.colormap.empty()) {
    const auto map = scene::parse_colormap(args.colormap);
    if (!map)
      throw CLI::ValidationError(
          "--colormap",
          fmt::format("'{}' is not one of turbo, viridis, magma, cividis, diverging, warm", args.colormap));
    style.colormap = *map;
  }
  if (!args.range.empty()) {
    style.range = track::parse_value_range(args.range);
    if (!style.range)
      throw CLI::ValidationError(
          "--range", fmt::format("'{}' is not MIN:MAX with finite numbers and MIN < MAX, e.g. 0:30", args.range));
  }
  if (!args.density_radius.empty()) {
    const std::string& text = args.density_radius;
    double radius = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), radius);
    if (ec != std::errc() || end != text.data() + text.size() ||
        !(radius >= track::kMinNeighbourRadiusM && radius <= track::kMaxNeighbourRadiusM))
      throw CLI::ValidationError("--density-radius",
                                 fmt::format("'{}' is not a radius in {:g}..{:g} metres", args.density_radius,
                                             track::kMinNeighbourRadiusM, track::kMaxNeighbourRadiusM));
    style.neighbour_radius_m = radius;
  }
  for (const std::string& text : args.colors) {
    const auto color = scene::parse_hex_color(text);
    if (!color)
      throw CLI::ValidationError("--color", fmt::format("'{}' is not a colour like '#e6194b' or '#f80'", text));
    style.colors.push_back(*color);
  }
  if (!args.route_color.empty()) {
    const auto color = scene::parse_hex_color(args.route_color);
    if (!color)
      throw CLI::ValidationError("--route-color",
                                 fmt::format("'{}' is not a colour like '#ffe000' or '#fe0'", args.route_color));
    style.route_color = *color;
  }
  out.legend = parse_on_off(args.legend, "--legend");
  style.occlusion.enabled = parse_on_off(args.occlusion, "--occlusion");
  if (!(args.occluded_alpha >= 0.0 && args.occluded_alpha <= 1.0))
    throw CLI::ValidationError("--occluded-alpha", fmt::format("'{}' is not an opacity in 0..1", args.occluded_alpha));
  style.occlusion.alpha = static_cast<float>(args.occluded_alpha);
  const auto fade = track::parse_value_range(args.occlusion_fade);
  if (!fade || fade->min < 0.0)
    throw CLI::ValidationError(
        "--occlusion-fade",
        fmt::format("'{}' is not NEAR:FAR in metres with 0 <= NEAR < FAR, e.g. 100:1000", args.occlusion_fade));
  style.occlusion.fade_near_m = static_cast<float>(fade->min);
  style.occlusion.fade_far_m = static_cast<float>(fade->max);
  style.curtain = args.curtain;
  out.shading.ssao = !args.no_ssao;
  out.shading.atmosphere = !args.no_atmosphere;
  out.shading.shadows = !args.no_shadows;
  out.shading.snow = {args.snow, args.snowline_m};
  out.labels.enabled = !args.no_labels;
  if (args.label_size_px < scene::kMinLabelSizePx || args.label_size_px > scene::kMaxLabelSizePx)
    throw CLI::ValidationError("--label-size", fmt::format("'{}' is not a size in {}..{} pixels", args.label_size_px,
                                                           scene::kMinLabelSizePx, scene::kMaxLabelSizePx));
  out.labels.size_px = args.label_size_px;
  if (args.hidden_labels != "ghost" && args.hidden_labels != "hide")
    throw CLI::ValidationError("--hidden-labels", fmt::format("'{}' is neither ghost nor hide", args.hidden_labels));
  out.labels.hide_occluded = args.hidden_labels == "hide";
  return out;
}

std::optional<double> parse_sun_time(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const auto t = track::parse_iso8601(text);
  if (!t)
    throw CLI::ValidationError("--time", "'" + text + "' is not an ISO 8601 date and time, e.g. 2024-06-18T12:00:00Z");
  return *t;
}

}  // namespace trailray::app
