#include "app/flight/task_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "app/common/terminal_diagnostics.hpp"
#include "app/common/track_arguments.hpp"
#include "app/flight/task_report.hpp"
#include "track/io/load.hpp"
#include "track/task/task_reader.hpp"

namespace trailray::app {
namespace {

struct TaskArgs {
  std::string task;
  std::vector<std::string> tracks;
  double tolerance_percent = 0.0;
  bool json = false;
};

int run_task(const TaskArgs& a) {
  namespace tt = track::task;
  TerminalDiagnostics diagnostics;
  const tt::TaskReadResult read = tt::read_task_file(a.task);
  for (const auto& w : read.warnings) diagnostics.warning(w.to_string());
  if (read.error) {
    diagnostics.error(read.error->to_string());
    return 1;
  }
  const tt::Task& task = *read.task;
  const tt::TaskDistances distances = tt::measure_task(task);
  int status = 0;
  std::vector<TaskFlightReport> flights;
  for (const std::string& path : a.tracks) {
    const track::ReadResult r = track::load_track_file(path);
    for (const auto& w : r.warnings) diagnostics.warning(w.to_string());
    TaskFlightReport f;
    if (r.error) {
      f.file = path;
      f.error = r.error->to_string();
    } else {
      f = task_flight_report(path, r.file, task, distances, a.tolerance_percent / 100.0);
    }
    if (f.error) {
      diagnostics.error(*f.error);
      status = 1;
    }
    flights.push_back(std::move(f));
  }
  if (a.json)
    std::cout << task_json(a.task, task, distances, flights).dump(2) << '\n';
  else
    fmt::print("{}", task_table(a.task, task, distances, flights));
  return status;
}

}  // namespace

void add_task_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<TaskArgs>();
  CLI::App* cmd = app.add_subcommand(
      "task", "A competition task: its turnpoints and distances, and which turnpoints flights reached and when");
  cmd->footer(
      "TASKFILE: an XCTrack task (.xctsk JSON, or the XCTSK: text of its QR code) or an IGC file\n"
      "with a task declaration (C records; radii are not part of that format: 400 m, the FAI\n"
      "badge cylinder). Distances are on the task's earth model (WGS84 unless it names the FAI\n"
      "sphere): through the centres, and optimised (the shortest route touching each cylinder in\n"
      "order, from the take-off's centre to a goal line's centre or a goal cylinder's edge).\n"
      "Per TRACK: each turnpoint's first crossing after the previous one (the start in its\n"
      "direction after the first gate; a restart before the next turnpoint replaces it), times\n"
      "interpolated between fixes; a race's start time is its gate.\n"
      "Exit status: 0 done, 1 when the task or a track cannot be read, 2 for a usage error.");
  cmd->add_option("TASKFILE", args->task, "Task file")->required()->type_name("FILE");
  cmd->add_option("TRACK", args->tracks, "Flights to check against the task (files, folders of them, patterns)")
      ->type_name("FILE");
  cmd->add_option("--tolerance", args->tolerance_percent,
                  "Cylinder tolerance in percent of the radius (CIVL GAP allows e.g. 0.1)")
      ->type_name("PERCENT")
      ->check(CLI::Range(0.0, 10.0))
      ->default_str("0");
  cmd->add_flag("--json", args->json, "Print one JSON document instead of a table");
  cmd->callback([args, &exit_code] {
    args->tracks = expand_track_arguments(args->tracks);
    exit_code = run_task(*args);
  });
}

}  // namespace trailray::app
