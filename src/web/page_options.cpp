#include "web/page_options.hpp"

#include <fast_float/fast_float.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "scene/pictures/colormap.hpp"
#include "terrain/codecs/height_encoding.hpp"
#include "terrain/sources/source_factory.hpp"
#include "track/color_values.hpp"
#include "track/io/parse_util.hpp"

namespace trailray::web {
namespace {

// The `overlay-legend` JSON (serve writes it from the overlay's own legend: app/serve/serve_config).
std::optional<scene::ColorLegend> parse_overlay_legend(std::string_view text) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return std::nullopt;
  try {
    scene::ColorLegend legend;
    legend.title = j.at("title").get<std::string>();
    const auto map = scene::parse_colormap(j.at("colormap").get<std::string>());
    if (!map) return std::nullopt;
    legend.map = *map;
    legend.min_label = j.at("min").get<std::string>();
    legend.max_label = j.at("max").get<std::string>();
    for (const auto& tick : j.value("ticks", nlohmann::json::array())) {
      const double position = tick.at(0).get<double>();
      if (!(position >= 0.0 && position <= 1.0)) return std::nullopt;
      legend.ticks.push_back({position, tick.at(1).get<std::string>()});
    }
    return legend;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

std::optional<double> number(std::string_view text) {
  double v = 0.0;
  const auto [end, ec] = fast_float::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<bool> flag(std::string_view text) {
  if (text.empty() || text == "1" || text == "true" || text == "on" || text == "yes") return true;
  if (text == "0" || text == "false" || text == "off" || text == "no") return false;
  return std::nullopt;
}

OptionOutcome fail(std::string_view name, std::string_view value, std::string_view expected) {
  return {std::nullopt, fmt::format("{}={}: expected {}", name, value, expected)};
}

scene::LookAt& look_at_of(PageOptions& o) {
  if (!o.look_at) o.look_at = scene::LookAt{};
  return *o.look_at;
}

}  // namespace

PageOptions::PageOptions() {
  const terrain::TerrainConfig defaults = terrain::default_terrain_config();
  terrain = defaults.terrain;
  imagery = defaults.imagery;
  // The same bucket by its own host name (S3's virtual-hosted form), as browser map libraries
  // fetch it: one public configuration reports no CORS headers on the path form the desktop uses.
  const std::string path_form = "https://s3.amazonaws.com/elevation-tiles-prod/";
  if (terrain.source.starts_with(path_form))
    terrain.source = "https://elevation-tiles-prod.s3.amazonaws.com/" + terrain.source.substr(path_form.size());
}

OptionOutcome apply_page_option(PageOptions& o, std::string_view name, std::string_view value) {
  scene::TrackStyle& tracks = o.style.tracks;
  if (name == "color") {
    std::vector<glm::vec3> colors;
    std::string_view rest = value;
    while (true) {
      const std::size_t comma = rest.find(',');
      const auto c = scene::parse_hex_color(rest.substr(0, comma));
      if (!c) return fail(name, value, "#rrggbb colours separated by commas");
      colors.push_back(*c);
      if (comma == std::string_view::npos) break;
      rest.remove_prefix(comma + 1);
    }
    tracks.colors = std::move(colors);
    tracks.color_by = track::ColorMetric::solid;
    return {OptionEffect::tracks, {}};
  }
  if (name == "color-by") {
    const auto metric = track::parse_color_metric(value);
    if (!metric) return fail(name, value, "a metric such as speed, vspeed, elevation, slope, time, solid");
    tracks.color_by = *metric;
    tracks.colormap = scene::default_colormap(*metric);
    return {OptionEffect::tracks, {}};
  }
  if (name == "colormap") {
    const auto map = scene::parse_colormap(value);
    if (!map) return fail(name, value, "a colormap such as turbo, viridis, magma, warm");
    tracks.colormap = *map;
    return {OptionEffect::style, {}};
  }
  if (name == "width") {
    const auto width = scene::parse_track_width(value);
    if (!width.ok()) return {std::nullopt, "width=" + std::string(value) + ": " + width.error};
    tracks.width = *width.value;
    return {OptionEffect::style, {}};
  }
  if (name == "legend") {
    const auto on = flag(value);
    if (!on) return fail(name, value, "on or off");
    o.style.legend = *on;
    return {OptionEffect::style, {}};
  }
  if (name == "curtain" || name == "no-shadows" || name == "no-ssao" || name == "no-atmosphere") {
    const auto on = flag(value);
    if (!on) return fail(name, value, "1 or 0 (true/false, on/off)");
    if (name == "curtain") {
      tracks.curtain = *on;
      return {OptionEffect::tracks, {}};
    }
    bool& setting = name == "no-shadows" ? o.style.shading.shadows
                    : name == "no-ssao"  ? o.style.shading.ssao
                                         : o.style.shading.atmosphere;
    setting = !*on;
    return {OptionEffect::style, {}};
  }
  if (name == "look-at") {
    const auto at = scene::parse_look_at_option(value);
    if (!at.ok()) return {std::nullopt, "look-at=" + std::string(value) + ": " + at.error};
    look_at_of(o).target = *at.value;
    o.camera.reset();
    return {OptionEffect::camera, {}};
  }
  if (name == "distance" || name == "heading" || name == "pitch") {
    const auto v = number(value);
    if (!v) return fail(name, value, "a number");
    if (name == "distance" && !(*v > 0.0)) return fail(name, value, "a distance in metres above 0");
    if (name == "pitch" && (*v < -90.0 || *v > 90.0)) return fail(name, value, "degrees within -90..90");
    scene::LookAt& at = look_at_of(o);
    (name == "distance" ? at.distance_m : name == "heading" ? at.heading_deg : at.pitch_deg) = *v;
    return {OptionEffect::camera, {}};
  }
  if (name == "camera") {
    const auto placement = scene::parse_camera_option(value);
    if (!placement.ok()) return {std::nullopt, "camera=" + std::string(value) + ": " + placement.error};
    o.camera = *placement.value;
    o.look_at.reset();
    return {OptionEffect::camera, {}};
  }
  if (name == "time") {
    const auto t = track::parse_iso8601(value);
    if (!t) return fail(name, value, "an ISO 8601 time such as 2024-06-18T15:30:00Z");
    o.time_unix_s = *t;
    return {OptionEffect::sun, {}};
  }
  if (name == "terrain" || name == "imagery") {
    terrain::SourceSettings& source = name == "terrain" ? o.terrain : o.imagery;
    const std::string text(value);
    if (text != "none" && !text.starts_with("http://") && !text.starts_with("https://"))
      return fail(name, value, "none or a URL template with {z}, {x} and {y} (the page reads tiles over HTTP)");
    source = terrain::SourceSettings{};
    source.source = text;
    if (name == "terrain") source.encoding = terrain::encoding_from_name(text);
    return {OptionEffect::terrain, {}};
  }
  if (name == "overlay-legend") {
    const auto legend = parse_overlay_legend(value);
    if (!legend) return fail(name, value, R"(JSON {"title", "colormap", "min", "max", "ticks": [[0.5, "10"]]})");
    o.overlay_legend = *legend;
    return {OptionEffect::style, {}};
  }
  if (name == "terrain-encoding") {
    const auto encoding = terrain::parse_height_encoding(value);
    if (!encoding) return fail(name, value, "terrarium, mapbox or alpinemaps");
    o.terrain.encoding = *encoding;
    return {OptionEffect::terrain, {}};
  }
  if (name == "terrain-max-zoom" || name == "imagery-max-zoom") {
    const auto v = number(value);
    if (!v || *v < 0 || *v > 22 || *v != std::floor(*v)) return fail(name, value, "a zoom level 0..22");
    (name == "terrain-max-zoom" ? o.terrain : o.imagery).max_zoom = static_cast<int>(*v);
    return {OptionEffect::terrain, {}};
  }
  return {std::nullopt, fmt::format("{}: not an option of the page (color, color-by, colormap, width, curtain, "
                                    "look-at, distance, heading, pitch, camera, time, no-shadows, no-ssao, "
                                    "no-atmosphere, legend, terrain, terrain-encoding, terrain-max-zoom, imagery, "
                                    "imagery-max-zoom)",
                                    name)};
}

std::vector<std::pair<std::string, std::string>> style_option_changes(const scene::Style& before,
                                                                      const scene::Style& after) {
  std::vector<std::pair<std::string, std::string>> out;
  const scene::TrackStyle &a = before.tracks, &b = after.tracks;
  const auto on_off = [](bool on) { return std::string(on ? "1" : "0"); };
  if (a.color_by != b.color_by) out.emplace_back("color-by", std::string(track::color_metric_name(b.color_by)));
  if (a.colormap != b.colormap || a.color_by != b.color_by)
    out.emplace_back("colormap", std::string(scene::colormap_name(b.colormap)));
  if (a.width.value != b.width.value || a.width.unit != b.width.unit)
    out.emplace_back(
        "width", fmt::format("{:g}{}", b.width.value, b.width.unit == scene::TrackWidth::Unit::pixels ? "px" : "m"));
  if (a.curtain != b.curtain) out.emplace_back("curtain", on_off(b.curtain));
  if (before.legend != after.legend) out.emplace_back("legend", after.legend ? "on" : "off");
  if (before.shading.shadows != after.shading.shadows) out.emplace_back("no-shadows", on_off(!after.shading.shadows));
  if (before.shading.ssao != after.shading.ssao) out.emplace_back("no-ssao", on_off(!after.shading.ssao));
  if (before.shading.atmosphere != after.shading.atmosphere)
    out.emplace_back("no-atmosphere", on_off(!after.shading.atmosphere));
  return out;
}

std::string address_value(std::string_view value) {
  static constexpr std::string_view kKept = "-_.~!$'()*,;:@/?{}#=[]";
  std::string out;
  out.reserve(value.size());
  for (const char ch : value) {
    const auto byte = static_cast<unsigned char>(ch);
    const bool alnum = (byte >= '0' && byte <= '9') || (byte >= 'a' && byte <= 'z') || (byte >= 'A' && byte <= 'Z');
    if (alnum || kKept.find(ch) != std::string_view::npos)
      out += ch;
    else
      out += fmt::format("%{:02X}", byte);
  }
  return out;
}

std::vector<std::string_view> options_reset_by(std::string_view name) {
  if (name == "terrain") return {"terrain-encoding", "terrain-max-zoom"};
  if (name == "imagery") return {"imagery-max-zoom", "overlay-legend"};
  return {};
}

}  // namespace trailray::web
