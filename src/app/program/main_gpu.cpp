// trailray-gpu: `render` and `bench` for the GPU bundle (scripts/gpu-bundle.sh), linked with terrain
// openers that need neither GDAL nor libcurl (terrain/sources/source_openers_tiles.cpp).
#include "app/program/cli.hpp"

int main(int argc, char** argv) { return trailray::app::run_cli(argc, argv, trailray::app::add_gpu_commands); }
