// trailray-render: what `trailray` hands render, elevation, bench and check --terrain to
// (app/program/program_router); run on its own it takes the same command lines.
#include "app/program/cli.hpp"

int main(int argc, char** argv) { return trailray::app::run_cli(argc, argv, trailray::app::add_picture_commands); }
