#include "app/tracks/convert_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

#include "app/common/output_file.hpp"
#include "app/common/terminal_diagnostics.hpp"
#include "app/options/track_options.hpp"
#include "track/clean.hpp"
#include "track/io/csv_writer.hpp"
#include "track/io/geojson_writer.hpp"
#include "track/io/gpx_writer.hpp"
#include "track/io/kml_writer.hpp"
#include "track/io/load.hpp"

namespace trailray::app {
namespace {

enum class OutputFormat { Gpx, GeoJson, Csv, Kml };

const std::map<std::string, OutputFormat> kFormats{{"gpx", OutputFormat::Gpx},
                                                   {"geojson", OutputFormat::GeoJson},
                                                   {"json", OutputFormat::GeoJson},
                                                   {"csv", OutputFormat::Csv},
                                                   {"kml", OutputFormat::Kml}};

struct ConvertArgs {
  std::vector<std::string> inputs;
  std::string output;
  std::string format;
  bool force = false;
  bool cleaned = false;
  TrackOptions track;
};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

OutputFormat output_format(const ConvertArgs& a) {
  if (!a.format.empty()) return kFormats.at(lower(a.format));
  if (a.output == "-")
    throw CLI::ValidationError("-o -", "writing to standard output needs --format gpx|geojson|csv|kml");
  const std::string ext = lower(std::filesystem::path(a.output).extension().string());
  const auto it = ext.empty() ? kFormats.end() : kFormats.find(ext.substr(1));
  if (it == kFormats.end())
    throw CLI::ValidationError(
        "-o", fmt::format("{}: cannot tell the format from the extension '{}': use .gpx, .geojson (or .json), .csv or "
                          ".kml, or give --format",
                          a.output, ext));
  return it->second;
}

void write(OutputFormat format, const track::TrackFile& file, std::ostream& out) {
  switch (format) {
    case OutputFormat::Gpx:
      track::write_gpx(file, out);
      break;
    case OutputFormat::GeoJson:
      track::write_geojson(file, out);
      break;
    case OutputFormat::Csv:
      track::write_csv(file, out);
      break;
    case OutputFormat::Kml:
      track::write_kml(file, out);
      break;
  }
}

// Tracks, and routes, cleaned as `stats` and `render` clean them: a route's points are planned,
// not measured, so they are never smoothed (render draws them so: scene/tracks/track_building).
void clean(track::TrackFile& file, const track::CleanOptions& options, std::size_t& dropped) {
  track::CleanReport report;
  for (track::Track& t : file.tracks) t = track::clean_track(t, options, report);
  track::CleanOptions route_options = options;
  route_options.smooth = false;
  for (track::Route& r : file.routes) {
    track::Track as_track;
    as_track.segments.push_back({std::move(r.points)});
    track::Track cleaned = track::clean_track(as_track, route_options, report);
    r.points = cleaned.segments.empty() ? std::vector<track::TrackPoint>{} : std::move(cleaned.segments.front().points);
  }
  dropped += report.total_dropped();
}

int run_convert(const ConvertArgs& a) {
  const OutputFormat format = output_format(a);
  const std::size_t stdin_inputs = static_cast<std::size_t>(std::count(a.inputs.begin(), a.inputs.end(), "-"));
  if (stdin_inputs > 1) throw CLI::ValidationError("IN", "standard input (-) can be read only once");
  if (a.output != "-") check_output_path(a.output, a.inputs, a.force);

  TerminalDiagnostics diagnostics(false);
  track::TrackFile merged;
  int failed = 0;
  for (std::size_t i = 0; i < a.inputs.size(); ++i) {
    track::ReadResult r = track::load_track_file(a.inputs[i], a.track.read);
    for (const auto& w : r.warnings) diagnostics.warning(w.to_string());
    if (r.error) {
      diagnostics.error(r.error->to_string());
      ++failed;
      continue;
    }
    track::TrackFile& f = r.file;
    if (merged.tracks.empty() && merged.routes.empty() && merged.waypoints.empty() && i == 0)
      merged.metadata = f.metadata;
    std::move(f.tracks.begin(), f.tracks.end(), std::back_inserter(merged.tracks));
    std::move(f.routes.begin(), f.routes.end(), std::back_inserter(merged.routes));
    std::move(f.waypoints.begin(), f.waypoints.end(), std::back_inserter(merged.waypoints));
  }
  if (failed > 0) {
    diagnostics.error(fmt::format("{} of {} input files could not be read; nothing written", failed, a.inputs.size()));
    return 1;
  }
  if (a.cleaned) {
    std::size_t dropped = 0;
    clean(merged, a.track.analysis.clean, dropped);
    if (dropped > 0) diagnostics.info(fmt::format("cleaning dropped {} point{}", dropped, dropped == 1 ? "" : "s"));
  }
  if (a.output == "-") {
    write(format, merged, std::cout);
    std::cout.flush();
    if (!std::cout) throw std::runtime_error("<stdout>: cannot write");
  } else {
    write_file_atomically(a.output, [&](std::ostream& out) { write(format, merged, out); });
    // What was written, on standard error (standard output stays the file's when it is "-").
    std::size_t points = 0;
    for (const track::Track& t : merged.tracks) points += t.point_count();
    const auto count = [](std::size_t n, const char* what) {
      return fmt::format("{} {}{}", n, what, n == 1 ? "" : "s");
    };
    diagnostics.info(fmt::format("wrote {}: {} ({}), {}, {}", a.output, count(merged.tracks.size(), "track"),
                                 count(points, "point"), count(merged.routes.size(), "route"),
                                 count(merged.waypoints.size(), "waypoint")));
  }
  return 0;
}

}  // namespace

void add_convert_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ConvertArgs>();
  CLI::App* cmd =
      app.add_subcommand("convert", "Convert track files to GPX, GeoJSON, CSV or KML (several merge into one)");
  cmd->footer(
      "All tracks, routes and waypoints of the inputs are written in order into one file. The output\n"
      "format follows OUT's extension: .gpx (GPX 1.1, channels in Garmin TrackPointExtension), .geojson\n"
      "or .json (togeojson's conventions: coordinateProperties times/heart/cads/powers/atemps/speeds),\n"
      ".csv (one row per point; header kind,track,segment,name,lat,lon,ele,time,hr,cad,power,temp,speed),\n"
      ".kml (gx:Track with ExtendedData arrays). OUT is written atomically (a temporary file renamed\n"
      "into place), never over an input, and replaces an existing file only with --force.\n"
      "Exit status: 0 written, 1 when an input could not be read or OUT not written (nothing is\n"
      "written then), 2 for a usage error.");
  cmd->add_option("IN", args->inputs,
                  "Track files: GPX, IGC, TCX, FIT, KML, KMZ, GeoJSON (gzip too), or - for standard input")
      ->required()
      ->type_name("FILE");
  cmd->add_option("-o,--output", args->output,
                  "Output file (.gpx, .geojson, .json, .csv, .kml), or - for standard output")
      ->required()
      ->type_name("OUT");
  cmd->add_option("--format", args->format, "Output format, instead of OUT's extension (needed with -o -)")
      ->check(CLI::IsMember({"gpx", "geojson", "json", "csv", "kml"}, CLI::ignore_case))
      ->type_name("gpx|geojson|csv|kml");
  cmd->add_flag("--force", args->force, "Replace OUT when it exists (never an input file)");
  cmd->add_flag("--cleaned", args->cleaned,
                "Write the tracks and routes cleaned as stats and render clean them (timestamps repaired, "
                "--min-distance, smoothing; routes never smoothed) instead of as recorded");
  add_track_options(*cmd, args->track);
  cmd->callback([args, &exit_code] { exit_code = run_convert(*args); });
}

}  // namespace trailray::app
