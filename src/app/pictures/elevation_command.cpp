#include "app/common/terminal_diagnostics.hpp"
#include "app/pictures/elevation_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "app/options/terrain_options.hpp"
#include "app/options/track_options.hpp"
#include "app/pictures/elevation_report.hpp"
#include "app/pictures/terrain_heights.hpp"
#include "track/io/gpx_writer.hpp"
#include "track/io/load.hpp"

namespace trailray::app {
namespace {

struct ElevationArgs {
  std::string file;
  bool json = false, csv = false, replace = false, force = false, quiet = false;
  std::string output;
  track::ReadOptions read;
  TerrainOptions terrain;  // with --surface (terrain.surface): empty without
};

// Every point the heights are wanted for, in file order: track points, then route points, then
// waypoints (those only for --replace: the report is about the way travelled).
std::vector<track::TrackPoint*> points_of(track::TrackFile& f, bool with_waypoints) {
  std::vector<track::TrackPoint*> out;
  for (auto& t : f.tracks)
    for (auto& s : t.segments)
      for (auto& p : s.points) out.push_back(&p);
  for (auto& r : f.routes)
    for (auto& p : r.points) out.push_back(&p);
  if (with_waypoints)
    for (auto& w : f.waypoints) out.push_back(&w.point);
  return out;
}

std::vector<ElevationPoint> report_points(const track::TrackFile& f, const std::vector<double>& terrain,
                                          const std::vector<double>& surface) {
  std::vector<ElevationPoint> out;
  std::size_t k = 0;
  auto add = [&](std::size_t track, std::size_t segment, const track::TrackPoint& p) {
    ElevationPoint point{track, segment, p.lat, p.lon, p.ele, terrain[k]};
    if (k < surface.size()) point.surface_m = surface[k];
    ++k;
    out.push_back(point);
  };
  for (std::size_t t = 0; t < f.tracks.size(); ++t)
    for (std::size_t s = 0; s < f.tracks[t].segments.size(); ++s)
      for (const auto& p : f.tracks[t].segments[s].points) add(t, s, p);
  for (std::size_t r = 0; r < f.routes.size(); ++r)
    for (const auto& p : f.routes[r].points) add(f.tracks.size() + r, 0, p);
  return out;
}

// Writes next to the target and renames, so OUT is never half written.
void write_gpx_atomically(const track::TrackFile& f, const std::filesystem::path& out) {
  std::filesystem::path tmp = out;
  tmp += fmt::format(".tmp-{}", ::getpid());
  {
    std::ofstream s(tmp, std::ios::binary | std::ios::trunc);
    if (!s) throw std::runtime_error(out.string() + ": cannot write (" + std::strerror(errno) + ")");
    track::write_gpx(f, s);
    s.flush();
    if (!s) {
      std::filesystem::remove(tmp);
      throw std::runtime_error(out.string() + ": write failed");
    }
  }
  std::filesystem::rename(tmp, out);
}

int run_elevation(const ElevationArgs& a) {
  if (a.replace && a.output.empty())
    throw CLI::ValidationError("--replace", "needs -o OUT.gpx (the input is never modified)");
  if (!a.output.empty() && !a.replace) throw CLI::ValidationError("-o", "is for --replace");
  if (a.replace) {
    std::error_code ec;
    if (a.file != "-" && std::filesystem::equivalent(a.file, a.output, ec))
      throw std::runtime_error(a.output + ": is the input file; trailray never modifies its input");
    if (std::filesystem::exists(a.output) && !a.force)
      throw std::runtime_error(a.output + ": already exists (--force replaces it)");
  }

  TerminalDiagnostics diagnostics(false, !a.quiet && isatty(STDERR_FILENO) != 0);
  track::ReadResult read = track::load_track_file(a.file, a.read);
  for (const auto& w : read.warnings) diagnostics.warning(w.to_string());
  if (read.error) {
    diagnostics.error(read.error->to_string());
    return 1;
  }
  track::TrackFile& file = read.file;

  const std::vector<track::TrackPoint*> points = points_of(file, a.replace);
  std::vector<geo::LatLon> where;
  where.reserve(points.size());
  for (const auto* p : points) where.push_back({p->lat, p->lon});
  const TerrainHeights sampled = terrain_heights(where, a.terrain, diagnostics, a.file);
  const std::vector<double>& heights = sampled.heights;
  const std::string& source_name = sampled.source_name;
  // Nothing had and tiles failed: the terrain could not be reached, which is not an answer.
  if (!heights.empty() && sampled.tiles_failed > 0 &&
      std::none_of(heights.begin(), heights.end(), [](double h) { return !std::isnan(h); })) {
    diagnostics.error(fmt::format("{}: no terrain height could be had for any point ({} tile{} failed): nothing written",
                                  a.file, sampled.tiles_failed, sampled.tiles_failed == 1 ? "" : "s"));
    return 1;
  }

  if (a.replace) {
    for (std::size_t i = 0; i < points.size(); ++i)
      if (!std::isnan(heights[i])) points[i]->ele = heights[i];
    write_gpx_atomically(file, a.output);
    return 0;
  }

  // The surface model (canopy and buildings) at the same places, from any source --terrain takes.
  const TerrainHeights surface = surface_heights(where, a.terrain, diagnostics, a.file);
  ElevationReport report{a.file == "-" ? "<stdin>" : a.file, source_name, surface.source_name,
                         report_points(file, heights, surface.heights), {}};
  report.summary = summarize(report.points);
  if (a.json)
    std::cout << elevation_json(report).dump(2) << '\n';
  else if (a.csv)
    std::cout << elevation_csv(report);
  else
    std::cout << elevation_table(report);
  return 0;
}

}  // namespace

void add_elevation_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ElevationArgs>();
  CLI::App* cmd = app.add_subcommand("elevation", "Terrain height and height above ground at every point of a track");
  cmd->footer(
      "Per point: lat, lon, ele_m (recorded), terrain_m (from --terrain), agl_m = ele_m - terrain_m;\n"
      "with --surface also surface_m, canopy_m = surface_m - terrain_m and cover: open (above the surface,\n"
      "or where the two agree within 2 m), covered (below the surface, at or above the ground, 3 m\n"
      "tolerance) or below_ground (a tunnel, or a bad altitude); a point without an elevation is on the ground.\n"
      "The summary's mean/median offset is how far a barometer drifted (hikes) or how high a flight\n"
      "was above the ground. Heights are bilinear between the source's samples: a raster file's own\n"
      "grid, or a tile source's finest level (see README, \"Terrain sources\").\n"
      "--replace -o OUT.gpx writes a copy with the terrain heights as elevations (GPX 1.1).\n"
      "Exit status: 0 done, 1 a file or source could not be read (also: every tile failed), 2 a usage error.");
  cmd->add_option("TRACK", args->file, "Track file: GPX, IGC, TCX, FIT, KML, KMZ, GeoJSON (gzip too), or - for standard input")
      ->required()
      ->type_name("FILE");
  auto* json = cmd->add_flag("--json", args->json, "Print one JSON document: path, points, summary");
  auto* csv = cmd->add_flag("--csv", args->csv, "Print one CSV row per point");
  json->excludes(csv);
  auto* replace =
      cmd->add_flag("--replace", args->replace, "Write a copy of the track with terrain elevations (needs -o)");
  replace->excludes(json)->excludes(csv);
  cmd->add_option("-o,--output", args->output, "Output GPX file for --replace")->type_name("OUT.gpx");
  cmd->add_flag("--force", args->force, "Let --replace overwrite an existing OUT");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress display");
  add_terrain_options(*cmd, args->terrain);
  cmd->add_option("--surface", args->terrain.surface,
                  "Surface model (canopy and buildings, e.g. a DSM beside a DTM): any source --terrain takes. Adds "
                  "per point surface_m, canopy_m and cover (open, covered, below_ground), and the share under cover")
      ->type_name("SRC")
      ->excludes(replace);
  add_read_options(*cmd, args->read);
  cmd->callback([args, &exit_code] { exit_code = run_elevation(*args); });
}

}  // namespace trailray::app
