#pragma once
// `trailray serve`: the web app, the tracks of the command line and the terrain and imagery
// sources as tiles, over HTTP (app/serve/), until SIGINT or SIGTERM.

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

void add_serve_command(CLI::App& app, int& exit_code);

}  // namespace trailray::app
