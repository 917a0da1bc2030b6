#pragma once
// `trailray video`: a film of tracks replayed on the terrain (MP4, WebM or PNG frames).

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

void add_video_command(CLI::App& app, int& exit_code);

}  // namespace trailray::app
