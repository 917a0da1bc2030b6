#pragma once
namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

// Registers `trailray task`; sets `exit_code` when it has run.
void add_task_command(CLI::App& app, int& exit_code);

}  // namespace trailray::app
