#pragma once
// /api/config.json of `trailray serve`: what the web page shows at start.
//   {"tracks": [{"name": "flight.igc", "url": "/tracks/0/flight.igc"}, ...],
//    "terrain": {"url": "/tiles/terrain/{z}/{x}/{y}.png", "encoding": "terrarium", "min_zoom": 0,
//                "max_zoom": 14, "bounds": [west, south, east, north], "attribution": "..."} or null,
//    "imagery": {"url": "/tiles/imagery/{z}/{x}/{y}", "min_zoom": 0, "max_zoom": 17, ...} or null,
//    "options": {"color": "#ff00ff", "color-by": "vspeed", "no-ssao": true, ...},
//    "photos": [...], "places": [...]}  (--photos and --places: served_pins.hpp; [] without them)
// "bounds" and "attribution" only when the source says; "options" holds the style, camera, read
// and cleaning options given on the command line, by their long names, exactly as given: a
// string, an array of strings for an option given several times, true for a flag.

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "app/serve/serve_site.hpp"
#include "scene/text/legend.hpp"
#include "terrain/sources/tile_source.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace trailray::app::serve {

// The options a command added between two snapshots of its option list (`before` taken first),
// so that those the page understands are told without naming each one here.
std::vector<const CLI::Option*> options_added_since(const CLI::App& command, std::size_t before);

// The given ones among `options`, as "options" above.
nlohmann::json given_options(const std::vector<const CLI::Option*>& options);

// "terrain" or "imagery" above for a source (null without one); `max_zoom` the level served.
nlohmann::json tile_layer(const terrain::SourceInfo* info, const std::string& url, int max_zoom, bool heights);

// `overlay_legend`: --overlay's colour bar, told as the imagery's "legend" ({"title", "colormap",
// "min", "max", "ticks": [[position, label], ...]}) for the page's `overlay-legend` option.
nlohmann::json serve_config(const std::vector<ServedTrack>& tracks, nlohmann::json terrain, nlohmann::json imagery,
                            nlohmann::json options, const std::optional<scene::ColorLegend>& overlay_legend = {},
                            nlohmann::json photos = nlohmann::json::array(),
                            nlohmann::json places = nlohmann::json::array());

}  // namespace trailray::app::serve
