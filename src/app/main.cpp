// trailray: GPS tracks in 3D on real terrain. The command line is the front door.
#include "app/cli.hpp"

int main(int argc, char** argv) { return trailray::app::run_cli(argc, argv); }
