#include "app/serve/serve_config.hpp"

#include <CLI/CLI.hpp>

namespace trailray::app::serve {

std::vector<const CLI::Option*> options_added_since(const CLI::App& command, std::size_t before) {
  const std::vector<const CLI::Option*> all = command.get_options();
  return {all.begin() + static_cast<std::ptrdiff_t>(std::min(before, all.size())), all.end()};
}

nlohmann::json given_options(const std::vector<const CLI::Option*>& options) {
  nlohmann::json out = nlohmann::json::object();
  for (const CLI::Option* option : options) {
    if (option->count() == 0 || option->get_lnames().empty()) continue;
    const std::string& name = option->get_lnames().front();
    const CLI::results_t& values = option->results();
    if (option->get_expected_max() == 0)  // a flag
      out[name] = true;
    else if (values.size() == 1)
      out[name] = values.front();
    else
      out[name] = values;
  }
  return out;
}

nlohmann::json tile_layer(const terrain::SourceInfo* info, const std::string& url, int max_zoom, bool heights) {
  if (info == nullptr) return nullptr;
  nlohmann::json layer = {{"url", url}};
  if (heights) layer["encoding"] = "terrarium";
  layer["min_zoom"] = std::min(info->min_zoom, max_zoom);
  layer["max_zoom"] = max_zoom;
  if (info->bounds && !info->bounds->empty())
    layer["bounds"] = {info->bounds->min_lon, info->bounds->min_lat, info->bounds->max_lon, info->bounds->max_lat};
  if (!info->attribution.empty()) layer["attribution"] = info->attribution;
  return layer;
}

nlohmann::json serve_config(const std::vector<ServedTrack>& tracks, nlohmann::json terrain, nlohmann::json imagery,
                            nlohmann::json options, const std::optional<scene::ColorLegend>& overlay_legend,
                            nlohmann::json photos, nlohmann::json places) {
  if (overlay_legend && imagery.is_object()) {
    nlohmann::json ticks = nlohmann::json::array();
    for (const scene::LegendTick& t : overlay_legend->ticks) ticks.push_back({t.position, t.label});
    imagery["legend"] = {{"title", overlay_legend->title},
                         {"colormap", std::string(scene::colormap_name(overlay_legend->map))},
                         {"min", overlay_legend->min_label},
                         {"max", overlay_legend->max_label},
                         {"ticks", std::move(ticks)}};
  }
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t i = 0; i < tracks.size(); ++i)
    list.push_back({{"name", tracks[i].name}, {"url", track_url(i, tracks[i].name)}});
  return {{"tracks", std::move(list)},
          {"terrain", std::move(terrain)},
          {"imagery", std::move(imagery)},
          {"options", std::move(options)},
          {"photos", std::move(photos)},
          {"places", std::move(places)}};
}

}  // namespace trailray::app::serve
