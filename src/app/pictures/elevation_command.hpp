#pragma once
// `trailray elevation`: terrain height and height above ground at every point of a track.

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

void add_elevation_command(CLI::App& app, int& exit_code);

}  // namespace trailray::app
