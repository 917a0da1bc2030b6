#pragma once
// `trailray check --airspace FILE TRACK...`: which airspaces the tracks entered (see
// track/airspace/infringement.hpp for how each limit is compared). Exit status 1 when any
// infringement is found, 0 when none, 2 for a usage error.

#include <CLI/CLI.hpp>

namespace trailray::app {

void add_check_command(CLI::App& app, int& exit_code);

}  // namespace trailray::app
