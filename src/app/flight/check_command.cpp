#include "app/flight/check_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>

#include "app/common/terminal_diagnostics.hpp"
#include "app/common/track_arguments.hpp"
#include "app/flight/airspace_check.hpp"
#include "app/flight/check_report.hpp"
#include "app/options/terrain_options.hpp"
#include "app/options/track_options.hpp"
#include "track/airspace/openair_reader.hpp"
#include "track/io/load.hpp"

namespace trailray::app {
namespace {

struct CheckArgs {
  std::string airspace;
  std::vector<std::string> tracks;
  bool json = false, quiet = false, timing = false;
  track::ReadOptions read;
  TerrainOptions terrain;
};

int run_check(const CheckArgs& a, const CheckTerrain& terrain) {
  TerminalDiagnostics diagnostics(false, !a.quiet && isatty(STDERR_FILENO) != 0);
  const auto start = std::chrono::steady_clock::now();
  const track::airspace::AirspaceReadResult air = track::airspace::load_openair_file(a.airspace, a.read);
  for (const auto& w : air.warnings) diagnostics.warning(w.to_string());
  if (air.error) {
    diagnostics.error(air.error->to_string());
    return 2;
  }
  const auto read_done = std::chrono::steady_clock::now();
  const track::airspace::AirspaceIndex index(air.file);

  CheckReport report{a.airspace == "-" ? "<stdin>" : a.airspace, &air.file, !a.terrain.terrain.empty(), {}};
  std::vector<CheckSegments> tracks;
  int status = 0;
  for (const auto& path : a.tracks) {
    track::ReadResult read = track::load_track_file(path, a.read);
    for (const auto& w : read.warnings) diagnostics.warning(w.to_string());
    if (read.error) {
      diagnostics.error(read.error->to_string());
      status = 2;
      continue;
    }
    CheckedPoints checked = checked_points(path == "-" ? "<stdin>" : path, read.file, a.read.igc_altitude);
    if (checked.without_altitude > 0)
      diagnostics.warning(fmt::format("{}: {} of {} points have no altitude: they are never found inside an airspace",
                                      checked.track.path, checked.without_altitude, checked.track.points));
    report.tracks.push_back(std::move(checked.track));
    tracks.push_back(std::move(checked.segments));
  }
  if (terrain.add_ground != nullptr) terrain.add_ground(a.terrain, diagnostics, a.quiet, tracks);
  const auto check_start = std::chrono::steady_clock::now();
  for (std::size_t t = 0; t < tracks.size(); ++t)
    report.tracks[t].infringements = track::airspace::find_infringements(index, tracks[t]);
  const auto check_done = std::chrono::steady_clock::now();

  if (a.json)
    std::cout << check_json(report).dump(2) << '\n';
  else
    std::cout << check_text(report);
  if (a.timing) {
    auto ms = [](auto d) { return std::chrono::duration<double, std::milli>(d).count(); };
    std::cerr << fmt::format("timing: airspace read {:.1f} ms, index + check {:.1f} ms\n", ms(read_done - start),
                             ms(check_done - check_start));
  }
  if (status != 0) return status;
  return report.total() > 0 ? 1 : 0;
}

}  // namespace

void add_check_command(CLI::App& app, int& exit_code, const CheckTerrain& terrain) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* cmd = app.add_subcommand("check", "Airspace infringements of tracks (OpenAir airspace file)");
  cmd->footer(
      "A fix is inside an airspace when it lies within the boundary and between floor and ceiling:\n"
      "FL/STD limits are compared with the IGC pressure altitude (recorded against 1013.25 hPa, as\n"
      "flight levels are), MSL limits with the GNSS altitude, AGL/GND limits with the GNSS altitude\n"
      "minus the ground from --terrain. Without --terrain the ground is unknown and taken\n"
      "conservatively (an AGL floor as if the ground were at sea level, an AGL ceiling as never below\n"
      "the aircraft); such findings say 'ground unknown'. Tracks without pressure altitude (GPX, ...)\n"
      "compare every limit with their one elevation.\n"
      "Exit status: 0 no infringement, 1 at least one, 2 a usage error or a file that cannot be read.");
  cmd->add_option("--airspace", args->airspace, "OpenAir airspace file (UTF-8 or Latin-1)")
      ->required()
      ->type_name("FILE");
  cmd->add_option("TRACK", args->tracks,
                  "Track files (GPX, IGC, TCX, FIT, KML, KMZ, GeoJSON), folders of them, patterns, or - for stdin")
      ->required()
      ->type_name("FILE");
  cmd->add_flag("--json", args->json, "Print one JSON document");
  cmd->add_flag("--timing", args->timing, "Print the time the airspace read and the check took (stderr)");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress display");
  if (terrain.add_options != nullptr) terrain.add_options(*cmd, args->terrain);
  add_read_options(*cmd, args->read);
  cmd->callback([args, &exit_code, terrain] {
    try {
      args->tracks = expand_track_arguments(args->tracks);
    } catch (const TrackArgumentError& e) {  // as a file that cannot be read: status 2 here
      TerminalDiagnostics().error(e.what());
      exit_code = 2;
      return;
    }
    exit_code = run_check(*args, terrain);
  });
}

}  // namespace trailray::app
