// trailray-full: every command (app/program/program_router hands it view, video, serve and the help).
#include "app/program/cli.hpp"

int main(int argc, char** argv) { return trailray::app::run_cli(argc, argv, trailray::app::add_all_commands); }
