// trailray-render's commands: those that need the terrain and a headless GL context, not the
// films' encoders, the window or the HTTP server (app/program/program_router sends it render, elevation,
// bench and check with --terrain). The track commands come along: they cost nothing more here.
#include "app/flight/check_command.hpp"

#include <CLI/CLI.hpp>
#include "app/flight/flight_command.hpp"
#include "app/flight/score_command.hpp"
#include "app/flight/task_command.hpp"
#include "app/pictures/bench_command.hpp"
#include "app/pictures/elevation_command.hpp"
#include "app/pictures/heatmap_command.hpp"
#include "app/pictures/render_command.hpp"
#include "app/program/cli.hpp"
#include "app/tracks/convert_command.hpp"
#include "app/tracks/stats_command.hpp"

namespace trailray::app {

void add_picture_commands(CLI::App& app, int& exit_code) {
  add_stats_command(app, exit_code);
  add_elevation_command(app, exit_code);
  add_heatmap_command(app, exit_code);
  add_convert_command(app, exit_code);
  add_check_command(app, exit_code, check_terrain());
  add_render_command(app, exit_code);
  add_score_command(app, exit_code);
  add_flight_command(app, exit_code);
  add_task_command(app, exit_code);
  add_bench_command(app, exit_code);
}

}  // namespace trailray::app
