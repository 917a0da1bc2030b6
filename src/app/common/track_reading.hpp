#pragma once
// Track files read and built on all cores (app/common/parallel_jobs): each file parsed, then each file's
// tracks cleaned, measured and placed, in parallel; the results in the order of the paths, so the
// tracks, their order and their colours are those of a read one file after the other. Progress
// ("reading 120/10000 files") goes to the diagnostics' progress line.

#include <optional>
#include <string>
#include <vector>

#include "scene/diagnostics.hpp"
#include "scene/tracks/track_building.hpp"
#include "scene/tracks/track_files.hpp"
#include "scene/tracks/track_set.hpp"

namespace trailray::app {

struct TrackReadingOptions {
  unsigned threads = 0;  // 0: every core (default_job_threads); 1: one file after the other
  // Stop at the first file that cannot be read (the files after it may be left unread), as a
  // command that gives up there; else every file is read (the viewer: the others still load).
  bool stop_at_first_error = true;
};

// One file's reading: the file, or the error that names it and the position.
struct TrackFileOutcome {
  std::optional<scene::LoadedTrackFile> loaded;
  std::vector<std::string> warnings;  // in the reader's order
  std::optional<std::string> error;   // as scene::read_track_file throws it
  bool read = false;                  // false: left unread after an earlier file's error
};

// Every path read (scene::read_track_file), outcomes in the order of `paths`; progress to
// `progress` (may be null). Never throws for a file that cannot be read.
std::vector<TrackFileOutcome> read_track_file_outcomes(const std::vector<std::string>& paths,
                                                       const track::ReadOptions& read,
                                                       const TrackReadingOptions& options,
                                                       scene::Diagnostics* progress);

// scene::read_track_files on all cores: the files' warnings to `diagnostics` in the order of the
// paths, then the first file in that order that cannot be read throws std::runtime_error naming it.
std::vector<scene::LoadedTrackFile> read_track_files_parallel(const std::vector<std::string>& paths,
                                                              const track::ReadOptions& read,
                                                              scene::Diagnostics& diagnostics, unsigned threads = 0);

// scene::build_tracks on all cores (scene::build_file_tracks per file, then scene::finish_tracks):
// the same tracks in the same order with the same colours; the first file's error in the order of
// the files is thrown.
std::vector<scene::Track> build_tracks_parallel(const std::vector<scene::LoadedTrackFile>& files,
                                                const scene::TrackStyle& style, const scene::TrackBuildOptions& options,
                                                scene::Diagnostics& diagnostics, std::size_t first_palette_index = 0,
                                                unsigned threads = 0);
// The same, freeing each file's track points as soon as its tracks are built (its waypoints and
// name stay): memory peaks at the tracks built rather than at those and every point read.
std::vector<scene::Track> build_tracks_releasing(std::vector<scene::LoadedTrackFile>& files,
                                                 const scene::TrackStyle& style,
                                                 const scene::TrackBuildOptions& options,
                                                 scene::Diagnostics& diagnostics);

}  // namespace trailray::app
