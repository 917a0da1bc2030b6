// trailray's own commands, run in its process: those that read tracks and print numbers. None
// needs the terrain, GL, the encoders, the window or the server, so the program loads none of
// their libraries (app/program_router hands every other command line to a program that does).
#include "app/check_command.hpp"
#include "app/cli.hpp"
#include "app/convert_command.hpp"
#include "app/flight_command.hpp"
#include "app/score_command.hpp"
#include "app/stats_command.hpp"
#include "app/task_command.hpp"

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
