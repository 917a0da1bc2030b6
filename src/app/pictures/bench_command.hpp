#pragma once
// `trailray bench tracks` the capsules of the track pass against the two
// usual techniques (a screen-space ribbon and an explicit 8-sided tube mesh), on seeded random
// walks of the requested sizes and on the real tracks of a data folder, at one picture size:
// median pass times, their ratios, and the GPU memory each technique spends per point. Prints a
// table, or with --json one document; progress goes to standard error. A benchmark: it prints
// figures and never judges them (the exit status says only whether it ran).

#include <cstddef>
#include <string_view>
#include <vector>

#include "scene/camera/camera.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

inline constexpr std::size_t kMaxBenchPoints = 10'000'000;

void add_bench_command(CLI::App& app, int& exit_code);

// `--points LIST`: comma-separated point counts, each in 2..kMaxBenchPoints ("10000,100000").
// The error quotes the offending item and names the option.
scene::Result<std::vector<std::size_t>> parse_point_counts(std::string_view text);

}  // namespace trailray::app
