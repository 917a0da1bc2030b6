#pragma once
// `trailray heatmap TRACK... -o OUT.tif`: how many tracks passed through each cell of a Web
// Mercator grid (track/heatmap.hpp), as a GeoTIFF.

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

void add_heatmap_command(CLI::App& app, int& exit_code);

}  // namespace trailray::app
