#pragma once
// Options about reading and cleaning tracks, spelled the same in every command.

#include "track/diagnostics.hpp"
#include "track/summary.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

struct TrackOptions {
  track::ReadOptions read;
  track::AnalysisOptions analysis;
};

// Adds --strict, --igc-altitude, --min-distance, --no-smooth, --smooth-width, --smooth-sigma.
void add_track_options(CLI::App& command, TrackOptions& options);

// Only the reading ones, --strict and --igc-altitude (for commands that use points as recorded).
void add_read_options(CLI::App& command, track::ReadOptions& options);

// Only the cleaning ones: --min-distance, --no-smooth, --smooth-width, --smooth-sigma.
void add_cleaning_options(CLI::App& command, track::AnalysisOptions& options);

}  // namespace trailray::app
