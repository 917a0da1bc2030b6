#pragma once
namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

// Registers `trailray score`; sets `exit_code` when it has run.
void add_score_command(CLI::App& app, int& exit_code);

}  // namespace trailray::app
