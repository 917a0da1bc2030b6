#pragma once
// `trailray render`: a picture of the tracks on the terrain (or of the terrain from a camera) as
// an sRGB PNG.

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

void add_render_command(CLI::App& app, int& exit_code);

}  // namespace trailray::app
