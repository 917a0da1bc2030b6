#include "app/program/cli.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/common/terminal_diagnostics.hpp"
#include "app/program/option_suggestion.hpp"

namespace trailray::app {

int run_cli(int argc, char** argv, CommandTable commands) {
  CLI::App app{"trailray: GPS tracks (GPX, IGC, TCX, FIT, KML, GeoJSON) in 3D on real terrain", "trailray"};
  app.set_version_flag("--version", std::string("trailray ") + TRAILRAY_VERSION);
  app.require_subcommand(1);
  app.footer("Run `trailray COMMAND --help` for the options of a command.");

  int exit_code = 0;
  commands(app, exit_code);

  // A mistyped option first: otherwise the parser may complain about something else.
  if (const std::optional<std::string> unknown = unknown_option_message(app, argc, argv)) {
    TerminalDiagnostics().error(*unknown);
    fmt::print(stderr, "Run with --help for more information.\n");
    return 2;  // usage error
  }

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
