// trailray-full's commands: all of them, in the order `trailray --help` lists them.
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
#include "app/serve/serve_command.hpp"
#include "app/tracks/convert_command.hpp"
#include "app/tracks/stats_command.hpp"
#include "app/video/video_command.hpp"
#include "app/view/view_command.hpp"

namespace trailray::app {

void add_all_commands(CLI::App& app, int& exit_code) {
  add_stats_command(app, exit_code);
  add_elevation_command(app, exit_code);
  add_heatmap_command(app, exit_code);
  add_convert_command(app, exit_code);
  add_check_command(app, exit_code, check_terrain());
  add_render_command(app, exit_code);
  add_view_command(app, exit_code);
  add_video_command(app, exit_code);
  add_score_command(app, exit_code);
  add_flight_command(app, exit_code);
  add_task_command(app, exit_code);
  add_serve_command(app, exit_code);
  add_bench_command(app, exit_code);
}

}  // namespace trailray::app
