// trailray's own commands, run in its process: those that read tracks and print numbers. None
// needs the terrain, GL, the encoders, the window or the server, so the program loads none of
// their libraries (app/program/program_router hands every other command line to a program that does).
#include "app/flight/check_command.hpp"

#include <CLI/CLI.hpp>
#include "app/flight/flight_command.hpp"
#include "app/flight/score_command.hpp"
#include "app/flight/task_command.hpp"
#include "app/program/cli.hpp"
#include "app/tracks/convert_command.hpp"
#include "app/tracks/stats_command.hpp"

namespace trailray::app {

void add_track_commands(CLI::App& app, int& exit_code) {
  add_stats_command(app, exit_code);
  add_convert_command(app, exit_code);
  add_check_command(app, exit_code);  // without --terrain: the router sends that to trailray-render
  add_score_command(app, exit_code);
  add_flight_command(app, exit_code);
  add_task_command(app, exit_code);
}

}  // namespace trailray::app
