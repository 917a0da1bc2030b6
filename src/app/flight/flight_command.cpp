#include "app/flight/flight_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "app/common/ordered_jobs.hpp"
#include "app/common/terminal_diagnostics.hpp"
#include "app/common/track_arguments.hpp"
#include "app/flight/flight_report.hpp"
#include "app/options/track_options.hpp"
#include "track/task/task_reader.hpp"

namespace trailray::app {
namespace {

struct FlightArgs {
  std::vector<std::string> files;
  bool json = false;
  std::string task;  // --task FILE
  double tolerance_percent = 0.0;
  track::ReadOptions read;
};

// The task of --task, read and measured once; nullopt (after an error) when it cannot be read.
std::optional<FlightTask> read_flight_task(const FlightArgs& a, TerminalDiagnostics& diagnostics) {
  namespace tt = track::task;
  const tt::TaskReadResult read = tt::read_task_file(a.task);
  for (const auto& w : read.warnings) diagnostics.warning(w.to_string());
  if (read.error) {
    diagnostics.error(read.error->to_string());
    return std::nullopt;
  }
  FlightTask t{a.task, *read.task, tt::measure_task(*read.task), a.tolerance_percent / 100.0};
  return t;
}

int run_flight(const FlightArgs& a) {
  TerminalDiagnostics diagnostics;
  const track::flight::FlightOptions options;
  std::optional<FlightTask> task;
  if (!a.task.empty()) {
    task = read_flight_task(a, diagnostics);
    if (!task) return 1;
  }
  const FlightTask* checked = task ? &*task : nullptr;
  nlohmann::json doc;
  doc["files"] = nlohmann::json::array();
  int failed = 0;
  const auto compute = [&](std::size_t i) { return analyse_flight_file(a.files[i], a.read, options, checked); };
  const auto consume = [&](std::size_t i, FileFlights& f) {
    for (const auto& w : f.warnings) diagnostics.warning(w);
    if (f.error) {
      diagnostics.error(*f.error);
      ++failed;
    } else if (f.tracks.empty()) {
      diagnostics.warning(fmt::format("{}: no tracks (flight analysis needs a track with times)", f.path));
    }
    if (a.json) {
      doc["files"].push_back(flight_file_json(f, checked));
    } else if (!f.error && !f.tracks.empty()) {
      fmt::print("{}{}", i > 0 ? "\n" : "", flight_file_text(f, checked));
      std::fflush(stdout);
    }
  };
  OrderedJobsOptions jobs;
  jobs.threads = file_job_threads(a.files);
  run_ordered_jobs<FileFlights>(a.files.size(), compute, consume, jobs);
  if (a.json) {
    doc["settings"] = flight_settings_json(options);
    if (task) doc["task"] = task_json(task->path, task->task, task->distances, {});
    std::cout << doc.dump(2) << '\n';
  }
  if (failed > 0 && a.files.size() > 1)
    diagnostics.error(fmt::format("{} of {} files could not be read", failed, a.files.size()));
  return failed > 0 ? 1 : 0;
}

}  // namespace

void add_flight_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<FlightArgs>();
  CLI::App* cmd =
      app.add_subcommand("flight", "Thermals, glides and wind of a flight: take-off, landing and phases per flight");
  cmd->footer(
      "Per track, every flight (take-off to landing; several in one file when the pilot landed in\n"
      "between) with: a summary (duration, distance, share of time circling, mean thermal climb\n"
      "weighted by time, best 20 s climb, best glide = the highest L/D among glides of at least\n"
      "2 km that lost at least 100 m), a table of thermals (entry and exit altitude, gain, mean and\n"
      "best 20 s climb, turns, and the wind their drift implies: FROM that direction, as in weather\n"
      "reports), a table of glides (distance along the track, height lost, L/D, speed) and the wind\n"
      "per 500 m altitude band (duration-weighted mean of the thermals in the band of 2 turns or more).\n"
      "How: take-off and landing from 10 s averages of ground and vertical speed (as `score` does,\n"
      "then trimmed to where the pilot stops walking); circling where the heading turns by 7 deg/s\n"
      "or more over 20 s (until below 4 deg/s), for at least 40 s; the wind from the drift of the\n"
      "centres of the full circles. Altitudes are the points' elevations (--igc-altitude picks\n"
      "which IGC altitude). Times are UTC. A track without times or elevations has no flight; a\n"
      "drive or a fast ride downhill can look like one (made for flight logs: IGC, or GPX from a vario).\n"
      "\n"
      "--json prints one document: {\"files\": [{\"path\", \"format\", \"warnings\", \"error\" (when\n"
      "unreadable), \"tracks\": [{\"name\", \"index\", \"points\", \"points_used\", \"has_altitude\",\n"
      "\"fix_interval_s\" (median time between fixes),\n"
      "\"note\" (why no flight, or null), \"flights\": [{\"takeoff\": PLACE, \"landing\": PLACE,\n"
      "\"duration_s\", \"distance_m\", \"max_alt_m\", \"min_alt_m\", \"circling_share\" (0..1),\n"
      "\"circling_s\", \"circling_left_s\", \"circling_right_s\", \"gliding_s\", \"unknown_s\",\n"
      "\"thermal_count\", \"mean_thermal_climb_ms\", \"best_climb_ms\", \"best_glide\" and\n"
      "\"longest_glide\" (indexes into glides, or null), \"phases\": [{\"phase\", \"start\", \"end\",\n"
      "\"duration_s\", \"start_point\", \"end_point\"}], \"thermals\": [{\"start\": PLACE, \"end\": PLACE,\n"
      "\"direction\" (left|right), \"duration_s\", \"entry_alt_m\", \"exit_alt_m\", \"gain_m\",\n"
      "\"mean_climb_ms\", \"best_climb_ms\", \"turns\", \"drift_m\", \"drift_to_deg\", \"wind_speed_ms\",\n"
      "\"wind_from_deg\", \"wind_from_centres\", \"phase\"}], \"glides\": [{\"start\": PLACE, \"end\": PLACE,\n"
      "\"duration_s\", \"distance_m\", \"height_lost_m\", \"glide_ratio\" (null when it lost no height),\n"
      "\"mean_speed_ms\", \"phase\"}], \"wind\": [{\"floor_m\", \"ceiling_m\", \"speed_ms\", \"from_deg\",\n"
      "\"thermals\"}]}]}]}], \"settings\": {the analysis constants}}, with PLACE = {\"time\" (ISO 8601\n"
      "UTC), \"lat\", \"lon\", \"alt_m\", \"point\" (index among the track's points)}; unknown figures are null.\n"
      "With --task, each file's result against the task follows its report (JSON: \"task\" per file, as\n"
      "in `trailray task --json`'s \"flights\", and the task itself as the document's \"task\").\n"
      "Exit status: 0 all read, 1 when any file (or the task) could not be read, 2 for a usage error.");
  cmd->add_option("TRACK", args->files,
                  "Track files: IGC (or GPX, TCX, FIT, KML, GeoJSON with times), folders of them, patterns, - for "
                  "standard input")
      ->required()
      ->type_name("FILE");
  cmd->add_flag("--json", args->json, "Print one JSON document instead of the report");
  cmd->add_option("--task", args->task,
                  "Also check the flights against a task (.xctsk, XCTSK: text, IGC C records): the turnpoints "
                  "reached and when, as `trailray task` prints them")
      ->type_name("FILE");
  cmd->add_option("--tolerance", args->tolerance_percent, "With --task: cylinder tolerance in percent of the radius")
      ->type_name("PERCENT")
      ->check(CLI::Range(0.0, 10.0))
      ->default_str("0");
  add_read_options(*cmd, args->read);
  cmd->callback([args, &exit_code] {
    args->files = expand_track_arguments(args->files);
    exit_code = run_flight(*args);
  });
}

}  // namespace trailray::app
