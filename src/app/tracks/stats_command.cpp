#include "app/common/terminal_diagnostics.hpp"
#include "app/tracks/stats_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <memory>

#include "app/common/ordered_jobs.hpp"
#include "app/common/track_arguments.hpp"
#include "app/options/photo_options.hpp"
#include "app/options/places_options.hpp"
#include "app/options/track_options.hpp"
#include "app/tracks/stats_report.hpp"

namespace trailray::app {
namespace {

struct StatsArgs {
  std::vector<std::string> files;
  bool json = false;
  std::string places_file;  // --places
  PhotoArgs photos;         // --photos, --photo-tz, --photo-time-offset
  TrackOptions track;
};

int run_stats(const StatsArgs& a) {
  // Progress only where it does not mix with the tables: several files, tables to a file or pipe.
  const bool progress = !a.json && a.files.size() > 1 && isatty(STDERR_FILENO) && !isatty(STDOUT_FILENO);
  TerminalDiagnostics diagnostics(false, progress);
  nlohmann::json doc;
  doc["files"] = nlohmann::json::array();
  int failed = 0;
  // --places: read once, before the tracks (an unreadable file fails here, naming it).
  std::vector<track::places::Place> places;
  if (!a.places_file.empty()) places = read_visit_places(a.places_file);
  // --photos: read once (a photo that cannot be read is a warning), placed on each file's tracks.
  StatsPhotos photos;
  if (a.photos.any()) {
    photos.photos = read_photo_files(expand_photo_arguments(a.photos.paths), diagnostics);
    photos.options = photo_placement_options(a.photos);
  }
  UnplacedPhotos unplaced(photos.photos.size());
  const auto compute = [&](std::size_t i) {
    return compute_file_stats(a.files[i], a.track.read, a.track.analysis, a.places_file.empty() ? nullptr : &places,
                              a.photos.any() ? &photos : nullptr);
  };
  const auto consume = [&](std::size_t i, FileStats& f) {
    diagnostics.progress_done();
    for (const auto& w : f.warnings) diagnostics.warning(w);
    if (f.photos) unplaced.add_file(*f.photos);
    if (f.error) {
      diagnostics.error(*f.error);
      ++failed;
    }
    if (a.json) {
      doc["files"].push_back(file_stats_json(f));
    } else if (!f.error) {
      fmt::print("{}{}", i > 0 ? "\n" : "", file_stats_table(f));
      std::fflush(stdout);
    }
  };
  OrderedJobsOptions jobs;
  jobs.threads = file_job_threads(a.files);
  jobs.progress = [&](std::size_t done, std::size_t count) {
    diagnostics.progress(fmt::format("[{}/{}] files read", done, count));
  };
  run_ordered_jobs<FileStats>(a.files.size(), compute, consume, jobs);
  if (a.json) std::cout << doc.dump(2) << '\n';
  if (a.photos.any()) unplaced.report(photos.photos, diagnostics);
  if (failed > 0 && a.files.size() > 1)
    diagnostics.error(fmt::format("{} of {} files could not be read", failed, a.files.size()));
  return failed > 0 ? 1 : 0;
}

}  // namespace

void add_stats_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<StatsArgs>();
  CLI::App* cmd = app.add_subcommand("stats", "Distance, time, climb and speeds per track and segment");
  cmd->footer(
      "Each track is measured twice: `raw` as recorded, and `clean` after repairing timestamps\n"
      "(duplicates, same-second runs, backward jumps), enforcing --min-distance and Gaussian\n"
      "smoothing. The table shows clean figures; --json prints both, per track and per segment.\n"
      "Exit status: 0 all read, 1 when any file could not be read, 2 for a usage error.");
  cmd->add_option("TRACK", args->files,
                  "Track files: GPX, IGC, TCX, FIT, KML, KMZ, GeoJSON (gzip too), folders of them, patterns, or - for "
                  "standard input")
      ->required()
      ->type_name("FILE");
  cmd->add_flag("--json", args->json, "Print one JSON document instead of tables");
  add_places_option(*cmd, args->places_file, PlacesUse::visits);
  add_photo_options(*cmd, args->photos);
  add_track_options(*cmd, args->track);
  cmd->callback([args, &exit_code] {
    args->files = expand_track_arguments(args->files);
    exit_code = run_stats(*args);
  });
}

}  // namespace trailray::app
