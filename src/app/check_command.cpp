#include "app/check_command.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>

#include "app/check_report.hpp"
#include "app/terminal_diagnostics.hpp"
#include "app/terrain_options.hpp"
#include "app/track_arguments.hpp"
#include "app/track_options.hpp"
#include "terrain/height_sampler.hpp"
#include "terrain/source_factory.hpp"
#include "track/airspace/openair_reader.hpp"
#include "track/io/load.hpp"

namespace trailray::app {
namespace {

using track::airspace::CheckPoint;
using IgcAltitude = track::ReadOptions::IgcAltitude;

struct CheckArgs {
  std::string airspace;
  std::vector<std::string> tracks;
  bool json = false, quiet = false, timing = false;
  track::ReadOptions read;
  TerrainOptions terrain;
};

using Segments = std::vector<std::vector<CheckPoint>>;

// The points as checked: their elevation against MSL (and AGL) limits; with `pressure`, an IGC's
// pressure altitude (kept beside the elevation whichever --igc-altitude picked) against FL/STD.
Segments segments_of(const track::TrackFile& f, bool pressure) {
  Segments out;
  for (const auto& t : f.tracks)
    for (const auto& s : t.segments) {
      std::vector<CheckPoint> points;
      points.reserve(s.points.size());
      for (const auto& p : s.points) {
        const double std_m = pressure && p.has_pressure_altitude() ? p.pressure_altitude : track::kMissing;
        points.push_back({p.lat, p.lon, p.time, p.ele, std_m, track::kMissing});
      }
      out.push_back(std::move(points));
    }
  return out;
}

bool any_pressure_altitude(const Segments& segments) {
  for (const auto& s : segments)
    for (const auto& p : s)
      if (!std::isnan(p.std_m)) return true;
  return false;
}

void add_ground(const terrain::TerrainConfig& config, TerminalDiagnostics& diagnostics, bool quiet,
                std::vector<Segments>& tracks) {
  terrain::SourceContext context{config.network, config.cache,
                                 [&diagnostics](std::string w) { diagnostics.warning("terrain: " + w); }};
  std::unique_ptr<terrain::HeightSource> source = terrain::open_height_source(config.terrain, context);
  if (!source) return;
  std::vector<geo::LatLon> where;
  for (const auto& t : tracks)
    for (const auto& s : t)
      for (const auto& p : s) where.push_back({p.lat, p.lon});
  terrain::HeightSampler sampler(*source, {});
  const std::vector<double> heights =
      sampler.sample(where, [&](const terrain::LoadProgress& p, std::size_t, std::size_t) {
        if (!quiet) diagnostics.progress(fmt::format("terrain tiles: {}/{} loaded", p.loaded + p.no_data, p.wanted));
      });
  diagnostics.progress_done();
  std::size_t k = 0;
  for (auto& t : tracks)
    for (auto& s : t)
      for (auto& p : s) p.ground_m = heights[k++];
  if (sampler.report().with_height < where.size())
    diagnostics.warning(fmt::format("terrain: no data at {} of {} points (AGL limits there taken conservatively)",
                                    where.size() - sampler.report().with_height, where.size()));
}

int run_check(const CheckArgs& a) {
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
  std::vector<Segments> tracks;
  int status = 0;
  for (const auto& path : a.tracks) {
    track::ReadResult read = track::load_track_file(path, a.read);
    for (const auto& w : read.warnings) diagnostics.warning(w.to_string());
    if (read.error) {
      diagnostics.error(read.error->to_string());
      status = 2;
      continue;
    }
    const bool igc = read.file.format == track::Format::Igc;
    // GNSS mode: the GNSS altitude for every limit, as asked; otherwise FL/STD limits take the
    // pressure altitude where the file has one (in pressure mode it is the elevation too).
    Segments segments = segments_of(read.file, igc && a.read.igc_altitude != IgcAltitude::Gnss);
    CheckedTrack checked{path == "-" ? "<stdin>" : path, 0, "", {}};
    std::size_t without_altitude = 0;
    for (const auto& s : segments) {
      checked.points += s.size();
      for (const auto& p : s) without_altitude += std::isnan(p.msl_m);
    }
    if (without_altitude > 0)
      diagnostics.warning(fmt::format("{}: {} of {} points have no altitude: they are never found inside an airspace",
                                      checked.path, without_altitude, checked.points));
    if (!igc)
      checked.altitudes =
          "one elevation per point: compared with every limit (FL too, as if it were pressure altitude)";
    else if (a.read.igc_altitude == IgcAltitude::Gnss)
      checked.altitudes = "IGC GNSS altitude for every limit (FL too)";
    else if (a.read.igc_altitude == IgcAltitude::Pressure)
      checked.altitudes = "IGC pressure altitude (--igc-altitude pressure) for every limit";
    else if (!any_pressure_altitude(segments))
      checked.altitudes = "IGC without pressure altitude: FL limits compared with the GNSS altitude";
    else
      checked.altitudes =
          "IGC: FL/STD limits with the pressure altitude (against 1013.25 hPa), MSL/AGL limits with the GNSS altitude";
    report.tracks.push_back(std::move(checked));
    tracks.push_back(std::move(segments));
  }
  if (!a.terrain.terrain.empty()) add_ground(resolve_terrain_config(a.terrain), diagnostics, a.quiet, tracks);
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

void add_check_command(CLI::App& app, int& exit_code) {
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
  add_terrain_options(*cmd, args->terrain);
  add_read_options(*cmd, args->read);
  cmd->callback([args, &exit_code] {
    try {
      args->tracks = expand_track_arguments(args->tracks);
    } catch (const TrackArgumentError& e) {  // as a file that cannot be read: status 2 here
      TerminalDiagnostics().error(e.what());
      exit_code = 2;
      return;
    }
    exit_code = run_check(*args);
  });
}

}  // namespace trailray::app
