// trailray-gpu's commands (the GPU bundle, scripts/gpu-bundle.sh): the track pass's benchmark and
// the renderer's profile, on any GPU driver's EGL.
#include "app/pictures/bench_command.hpp"

#include <CLI/CLI.hpp>
#include "app/pictures/render_command.hpp"
#include "app/program/cli.hpp"

namespace trailray::app {

void add_gpu_commands(CLI::App& app, int& exit_code) {
  add_render_command(app, exit_code);
  add_bench_command(app, exit_code);
}

}  // namespace trailray::app
