#pragma once
// Options about reading and cleaning tracks, spelled the same in every command.

#include <CLI/CLI.hpp>

#include "track/diagnostics.hpp"
#include "track/summary.hpp"

namespace trailray::app {

struct TrackOptions {
  track::ReadOptions read;
  track::AnalysisOptions analysis;
};

// Adds --strict, --igc-altitude, --min-distance, --no-smooth, --smooth-width, --smooth-sigma.
void add_track_options(CLI::App& command, TrackOptions& options);

}  // namespace trailray::app
