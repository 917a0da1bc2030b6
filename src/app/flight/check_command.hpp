#pragma once
// `trailray check --airspace FILE TRACK...`: which airspaces the tracks entered (see
// track/airspace/infringement.hpp for how each limit is compared). Exit status 1 when any
// infringement is found, 0 when none, 2 for a usage error.

#include "app/flight/airspace_check.hpp"
#include "app/options/terrain_options.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

// What `check` needs of the terrain layer for --terrain (AGL limits against the real ground),
// handed in by the programs that link it (app/command_sets); without it `check` has no terrain
// options (the light `trailray` runs it so, app/program/program_router sends --terrain elsewhere).
struct CheckTerrain {
  void (*add_options)(CLI::App& command, TerrainOptions& options) = nullptr;
  void (*add_ground)(const TerrainOptions& terrain, scene::Diagnostics& diagnostics, bool quiet,
                     std::vector<CheckSegments>& tracks) = nullptr;
};
// check_terrain(): the terrain layer's (airspace_ground.cpp, terrain_options.cpp).
CheckTerrain check_terrain();

void add_check_command(CLI::App& app, int& exit_code, const CheckTerrain& terrain = {});

}  // namespace trailray::app
