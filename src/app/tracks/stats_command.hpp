#pragma once
// `trailray stats [--json] TRACK...`: distance, time, climb and speeds per track.

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

// Registers the subcommand; sets `exit_code` when it has run.
void add_stats_command(CLI::App& app, int& exit_code);

}  // namespace trailray::app
