#include "app/cli.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "app/bench_command.hpp"
#include "app/check_command.hpp"
#include "app/convert_command.hpp"
#include "app/elevation_command.hpp"
#include "app/flight_command.hpp"
#include "app/render_command.hpp"
#include "app/score_command.hpp"
#include "app/serve_command.hpp"
#include "app/stats_command.hpp"
#include "app/task_command.hpp"
#include "app/terminal_diagnostics.hpp"
#include "app/video_command.hpp"
#include "app/view_command.hpp"

namespace trailray::app {

int run_cli(int argc, char** argv) {
  CLI::App app{"trailray: GPS tracks (GPX, IGC, TCX, FIT, KML, GeoJSON) in 3D on real terrain", "trailray"};
  app.set_version_flag("--version", std::string("trailray ") + TRAILRAY_VERSION);
  app.require_subcommand(1);
  app.footer("Run `trailray COMMAND --help` for the options of a command.");

  int exit_code = 0;
  add_stats_command(app, exit_code);
  add_elevation_command(app, exit_code);
  add_convert_command(app, exit_code);
  add_check_command(app, exit_code);
  add_render_command(app, exit_code);
  add_view_command(app, exit_code);
  add_video_command(app, exit_code);
  add_score_command(app, exit_code);
  add_flight_command(app, exit_code);
  add_task_command(app, exit_code);
  add_serve_command(app, exit_code);
  add_bench_command(app, exit_code);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;  // usage error
  } catch (const std::exception& e) {
    TerminalDiagnostics().error(e.what());
    return 1;
  }
  return exit_code;
}

}  // namespace trailray::app
