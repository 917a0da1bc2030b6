#pragma once
// `trailray view`: the tracks in a window, to fly around, inspect and replay. The
// window and its loop are app/view/viewer_app.hpp's; this file is the command line.

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

void add_view_command(CLI::App& app, int& exit_code);

}  // namespace trailray::app
