#pragma once
// The command line: `trailray <command> [options]`. One parser (run_cli) over a table of commands;
// each program of the split (app/program/program_router) runs the table of the commands it links.

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

using CommandTable = void (*)(CLI::App& app, int& exit_code);

int run_cli(int argc, char** argv, CommandTable commands);

// The tables (command_sets.cpp would link every command into every program: one file each).
void add_track_commands(CLI::App& app, int& exit_code);    // command_set_tracks.cpp: trailray itself
void add_picture_commands(CLI::App& app, int& exit_code);  // command_set_pictures.cpp: trailray-render
void add_all_commands(CLI::App& app, int& exit_code);      // command_set_all.cpp: trailray-full
void add_gpu_commands(CLI::App& app, int& exit_code);      // command_set_gpu.cpp: trailray-gpu (the GPU bundle)

}  // namespace trailray::app
