#pragma once
// The command line: `trailray <command> [options]`.

namespace trailray::app {

int run_cli(int argc, char** argv);

}  // namespace trailray::app
