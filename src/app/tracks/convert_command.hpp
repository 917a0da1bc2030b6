#pragma once
// `trailray convert IN... -o OUT`: reads track files (any format trailray reads) and writes them
// as one GPX, GeoJSON, CSV or KML file, chosen by OUT's extension (or --format).

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

// Registers the subcommand; sets `exit_code` when it has run.
void add_convert_command(CLI::App& app, int& exit_code);

}  // namespace trailray::app
