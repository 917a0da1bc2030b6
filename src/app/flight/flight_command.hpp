#pragma once
namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

// Registers `trailray flight`; sets `exit_code` when it has run.
void add_flight_command(CLI::App& app, int& exit_code);

}  // namespace trailray::app
