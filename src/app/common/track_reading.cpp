#include "app/common/track_reading.hpp"

#include <algorithm>
#include <exception>
#include <stdexcept>

#include <fmt/format.h>

#include "app/common/parallel_jobs.hpp"

namespace trailray::app {
namespace {

// A progress line for `what` ("reading {}/{} files"), only for more than one file (a single
// file's line would only flash).
std::function<void(std::size_t, std::size_t)> progress_line(scene::Diagnostics* diagnostics, const char* what) {
  if (diagnostics == nullptr) return {};
  return [diagnostics, what](std::size_t done, std::size_t count) {
    if (count > 1) diagnostics->progress(fmt::format(fmt::runtime(what), done, count));
  };
}

}  // namespace

std::vector<TrackFileOutcome> read_track_file_outcomes(const std::vector<std::string>& paths,
                                                       const track::ReadOptions& read,
                                                       const TrackReadingOptions& options,
                                                       scene::Diagnostics* progress) {
  std::vector<TrackFileOutcome> out(paths.size());
  const auto job = [&](std::size_t i) {
    TrackFileOutcome& o = out[i];
    scene::CollectedDiagnostics collected;  // this file's warnings, replayed in order by the caller
    try {
      o.loaded = scene::read_track_file(paths[i], read, collected);
    } catch (const std::exception& e) {
      o.error = e.what();
    }
    o.warnings = std::move(collected.warnings);
    o.read = true;
    return !(o.error && options.stop_at_first_error);
  };
  // Standard input named twice is read once whole and then found empty, as one file after the
  // other would: never by two threads at once.
  const bool stdin_twice = std::count(paths.begin(), paths.end(), "-") > 1;
  run_parallel_jobs(paths.size(), job,
                    {stdin_twice ? 1u : options.threads, progress_line(progress, "reading {}/{} files")});
  if (progress != nullptr && paths.size() > 1) progress->progress_done();
  return out;
}

std::vector<scene::LoadedTrackFile> read_track_files_parallel(const std::vector<std::string>& paths,
                                                              const track::ReadOptions& read,
                                                              scene::Diagnostics& diagnostics, unsigned threads) {
  std::vector<TrackFileOutcome> outcomes = read_track_file_outcomes(paths, read, {threads, true}, &diagnostics);
  std::vector<scene::LoadedTrackFile> files;
  files.reserve(outcomes.size());
  for (TrackFileOutcome& o : outcomes) {
    for (const std::string& w : o.warnings) diagnostics.warning(w);
    if (o.error) throw std::runtime_error(*o.error);
    files.push_back(std::move(*o.loaded));
  }
  return files;
}

namespace {

// `release`: the same files, whose tracks are freed once built (nullptr: kept).
std::vector<scene::Track> build_tracks(const std::vector<scene::LoadedTrackFile>& files,
                                       std::vector<scene::LoadedTrackFile>* release, const scene::TrackStyle& style,
                                       const scene::TrackBuildOptions& options, scene::Diagnostics& diagnostics,
                                       std::size_t first_palette_index, unsigned threads) {
  // Without files, the checks of the style alone (agl without terrain) and nothing else.
  if (files.empty()) return scene::build_tracks(files, style, options, diagnostics, first_palette_index);
  std::vector<std::vector<scene::Track>> built(files.size());
  std::vector<std::exception_ptr> errors(files.size());
  const auto job = [&](std::size_t i) {
    try {
      built[i] = scene::build_file_tracks(files[i], style, options);
      if (release != nullptr) std::vector<track::Track>().swap((*release)[i].file.tracks);
      return true;
    } catch (...) {
      errors[i] = std::current_exception();
      return false;
    }
  };
  run_parallel_jobs(files.size(), job, {threads, progress_line(&diagnostics, "preparing the tracks of {}/{} files")});
  if (files.size() > 1) diagnostics.progress_done();
  std::vector<scene::Track> tracks;
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (errors[i]) std::rethrow_exception(errors[i]);
    for (scene::Track& t : built[i]) tracks.push_back(std::move(t));
  }
  // Density and thermals count over every track: the targets spread over the same threads.
  scene::finish_tracks(tracks, style, diagnostics, first_palette_index, parallel_for(threads));
  return tracks;
}

}  // namespace

std::vector<scene::Track> build_tracks_parallel(const std::vector<scene::LoadedTrackFile>& files,
                                                const scene::TrackStyle& style, const scene::TrackBuildOptions& options,
                                                scene::Diagnostics& diagnostics, std::size_t first_palette_index,
                                                unsigned threads) {
  return build_tracks(files, nullptr, style, options, diagnostics, first_palette_index, threads);
}

std::vector<scene::Track> build_tracks_releasing(std::vector<scene::LoadedTrackFile>& files,
                                                 const scene::TrackStyle& style,
                                                 const scene::TrackBuildOptions& options,
                                                 scene::Diagnostics& diagnostics) {
  return build_tracks(files, &files, style, options, diagnostics, 0, 0);
}

}  // namespace trailray::app
