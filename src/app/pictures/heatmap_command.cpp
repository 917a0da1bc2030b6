#include "app/pictures/heatmap_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>

#include "app/common/output_file.hpp"
#include "app/common/parallel_jobs.hpp"
#include "app/common/terminal_diagnostics.hpp"
#include "app/common/track_arguments.hpp"
#include "app/options/track_options.hpp"
#include "app/pictures/heatmap_output.hpp"
#include "scene/pictures/colormap.hpp"
#include "scene/pictures/heatmap_colors.hpp"
#include "terrain/writers/count_geotiff.hpp"
#include "track/heatmap.hpp"
#include "track/heatmap_pixels.hpp"
#include "track/io/load.hpp"

namespace trailray::app {
namespace {

struct HeatmapArgs {
  std::vector<std::string> files;
  std::string output;
  double cell_m = 50.0;
  bool cell_given = false;
  std::string of = "tracks";
  std::string bbox;
  std::string zoom;
  std::string colormap = "warm";
  std::string scale = "log";
  bool force = false;
  track::ReadOptions read;
};

// --zoom MIN-MAX (or one level Z)
std::optional<std::pair<int, int>> parse_zoom_range(const std::string& text) {
  int a = -1, b = -1, used = 0;
  if (std::sscanf(text.c_str(), "%d-%d%n", &a, &b, &used) == 2 && static_cast<std::size_t>(used) == text.size())
    return std::pair{a, b};
  if (std::sscanf(text.c_str(), "%d%n", &a, &used) == 1 && static_cast<std::size_t>(used) == text.size())
    return std::pair{a, a};
  return std::nullopt;
}

// --bbox MIN_LAT,MIN_LON,MAX_LAT,MAX_LON
std::optional<std::array<double, 4>> parse_bbox(const std::string& text) {
  std::array<double, 4> v{};
  std::istringstream in(text);
  for (std::size_t i = 0; i < 4; ++i) {
    if (!(in >> v[i])) return std::nullopt;
    if (i < 3 && in.get() != ',') return std::nullopt;
  }
  if (in.peek() != EOF) return std::nullopt;
  if (!(v[0] >= -90 && v[2] <= 90 && v[0] < v[2] && v[1] >= -180 && v[3] <= 180 && v[1] < v[3])) return std::nullopt;
  return v;
}

int run_heatmap(HeatmapArgs a) {
  HeatmapOutputKind kind;
  try {
    kind = heatmap_output_kind(a.output);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("-o", e.what());
  }
  std::optional<std::array<double, 4>> bbox;
  if (!a.bbox.empty()) {
    bbox = parse_bbox(a.bbox);
    if (!bbox)
      throw CLI::ValidationError("--bbox", fmt::format("'{}' is not MIN_LAT,MIN_LON,MAX_LAT,MAX_LON with min < max",
                                                       a.bbox));
  }
  const std::optional<track::HeatmapMeasure> measure = track::parse_heatmap_measure(a.of);
  if (!measure) throw CLI::ValidationError("--of", fmt::format("'{}' is not tracks, thermals or time", a.of));
  HeatmapTileOptions tile_options;
  if (!a.zoom.empty()) {
    const auto range = parse_zoom_range(a.zoom);
    if (!range || range->first < 0 || range->second > 24 || range->first > range->second)
      throw CLI::ValidationError("--zoom", fmt::format("'{}' is not MIN-MAX (or one level) within 0..24", a.zoom));
    tile_options.min_zoom = range->first;
    tile_options.max_zoom = range->second;
  }
  const auto colormap = scene::parse_colormap(a.colormap);
  if (!colormap) throw CLI::ValidationError("--colormap", fmt::format("'{}' is not a colormap", a.colormap));
  const auto scale = scene::parse_heatmap_scale(a.scale);
  if (!scale) throw CLI::ValidationError("--scale", fmt::format("'{}' is not log or linear", a.scale));
  tile_options.palette.colormap = *colormap;
  tile_options.palette.scale = *scale;

  // Heatmaps written before (tile outputs carry their counts) are added as they are; the rest are
  // track files, folders and patterns.
  std::vector<std::string> heatmaps, tracks;
  for (const std::string& f : a.files) (is_heatmap_tiles(f) ? heatmaps : tracks).push_back(f);
  std::vector<track::HeatmapCounts> earlier;
  for (const std::string& h : heatmaps) {
    earlier.push_back(read_heatmap_counts(h));
    const track::HeatmapCounts& e = earlier.back();
    if (!a.cell_given) a.cell_m = earlier.front().cell_m();
    if (e.cell_m() != a.cell_m)
      throw std::runtime_error(fmt::format("{}: its cells are {:g} m, not {:g} m: heatmaps of different cells do not "
                                           "add up",
                                           h, e.cell_m(), a.cell_m));
    if (e.measure() != *measure)
      throw std::runtime_error(fmt::format("{}: it counts {}, not {} (--of)", h, track::heatmap_measure_name(e.measure()),
                                           a.of));
  }
  const std::vector<std::string> files = tracks.empty() ? tracks : expand_track_arguments(tracks);
  if (kind == HeatmapOutputKind::geotiff) check_output_path(a.output, files, a.force);
  if (kind != HeatmapOutputKind::geotiff)
    for (const std::string& h : heatmaps)
      if (std::filesystem::weakly_canonical(h) == std::filesystem::weakly_canonical(a.output))
        throw std::runtime_error(a.output + ": is also an input (write the sum somewhere else)");

  TerminalDiagnostics diagnostics(false, isatty(STDERR_FILENO) != 0);
  track::HeatmapCounts counts(a.cell_m, *measure);
  for (const track::HeatmapCounts& e : earlier) counts.merge(e);
  std::mutex mutex;
  std::vector<std::optional<std::string>> errors(files.size());
  std::vector<std::vector<std::string>> warnings(files.size());
  // Each file read, its tracks' counts worked out and added, then freed: memory follows the grid.
  run_parallel_jobs(
      files.size(),
      [&](std::size_t i) {
        track::ReadResult r = track::load_track_file(files[i], a.read);
        for (const auto& w : r.warnings) warnings[i].push_back(w.to_string());
        if (r.error) {
          errors[i] = r.error->to_string();
          return true;
        }
        std::vector<std::vector<track::HeatmapCellCount>> parts;
        for (const track::Track& t : r.file.tracks) parts.push_back(counts.track_counts(t));
        std::lock_guard lock(mutex);
        for (const auto& part : parts) counts.add_counts(part);
        return true;
      },
      {0, [&](std::size_t done, std::size_t n) { diagnostics.progress(fmt::format("[{}/{}] files counted", done, n)); }});
  diagnostics.progress_done();
  int failed = 0;
  for (std::size_t i = 0; i < files.size(); ++i) {
    for (const auto& w : warnings[i]) diagnostics.warning(w);
    if (errors[i]) {
      diagnostics.error(*errors[i]);
      ++failed;
    }
  }
  const track::HeatmapWindow window = bbox ? counts.window_of((*bbox)[0], (*bbox)[1], (*bbox)[2], (*bbox)[3])
                                           : counts.extent();
  const std::string read_from = fmt::format(
      "{} tracks from {} files{}{}", counts.tracks(), files.size() - static_cast<std::size_t>(failed),
      failed ? fmt::format(" ({} could not be read)", failed) : "",
      heatmaps.empty() ? "" : fmt::format(" and {} heatmaps", heatmaps.size()));
  if (window.empty() || counts.extent().empty()) {
    diagnostics.error(fmt::format("nothing counted ({}): nothing written", read_from));
    return 1;
  }
  if (kind != HeatmapOutputKind::geotiff) {
    const track::HeatmapCounts kept = bbox ? counts.cropped(window) : counts;
    const HeatmapWritten w = write_heatmap_tiles(kept, a.output, kind, tile_options, a.force, [&](int z) {
      diagnostics.progress(fmt::format("zoom {} of {}..{}: colouring tiles", z, tile_options.min_zoom,
                                       tile_options.max_zoom.value_or(track::heatmap_native_zoom(a.cell_m))));
    });
    diagnostics.progress_done();
    fmt::print("{}: {}, {:g} m cells, {} tiles at zoom {}..{}, at most {} {} in a cell\n", a.output, read_from,
               a.cell_m, w.tiles, w.min_zoom, w.max_zoom, w.max_count, a.of == "time" ? "seconds" : a.of);
    return failed > 0 ? 1 : 0;
  }
  // The raster is made whole in memory (4 bytes a cell): at most 1 GiB of it.
  constexpr std::int64_t kMaxCells = std::int64_t{1} << 28;
  if (window.width() * window.height() > kMaxCells)
    throw std::runtime_error(fmt::format("{}x{} cells is more than one GeoTIFF of a heatmap holds here ({} cells): a "
                                         "larger --cell, or a --bbox around the tracks you want (or tiles: -o X.mbtiles)",
                                         window.width(), window.height(), kMaxCells));
  const std::vector<std::uint32_t> raster = counts.raster(window);
  const std::vector<unsigned char> tiff =
      terrain::encode_count_geotiff(raster, static_cast<std::uint32_t>(window.width()),
                                    static_cast<std::uint32_t>(window.height()), counts.geotransform(window),
                                    track::heatmap_measure_name(counts.measure()));
  write_file_atomically(a.output, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(tiff.data()), static_cast<std::streamsize>(tiff.size()));
  });
  const std::uint32_t most = raster.empty() ? 0 : *std::max_element(raster.begin(), raster.end());
  fmt::print("{}: {}, {:g} m cells, {}x{} cells, at most {} {} in a cell\n", a.output, read_from, a.cell_m,
             window.width(), window.height(), most, a.of == "time" ? "seconds" : a.of);
  return failed > 0 ? 1 : 0;
}

}  // namespace

void add_heatmap_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<HeatmapArgs>();
  CLI::App* cmd = app.add_subcommand("heatmap", "How many tracks passed through each cell of a grid: GeoTIFF or map tiles");
  cmd->footer(
      "A track counts once in every cell it passes through; the line between two consecutive\n"
      "points counts for every cell it crosses (a step over 10 km is a gap: its ends count). The grid\n"
      "is Web Mercator's (EPSG:3857), the same for every run with the same --cell, so heatmaps of\n"
      "different files add up; the cell is in Mercator metres (on the ground: times cos(latitude)).\n"
      "--of thermals counts the flights that climbed in a thermal there (as `trailray flight` finds\n"
      "them); --of time the seconds spent there (each step's time shared among its cells by length).\n"
      "OUT.tif: the counts, one band, UInt32, EPSG:3857, the extent of the tracks or --bbox (QGIS and\n"
      "GDAL open it as it is). OUT.mbtiles or OUT/: coloured map tiles (PNG, --zoom, --colormap,\n"
      "--scale) with the counts beside them; such a heatmap may be given as a TRACK to add it to\n"
      "others exactly, and drawn on the terrain by render, view, video and serve (--overlay).\n"
      "Files are read and counted one by one; one that cannot be read is reported and counted\n"
      "nowhere. Exit status: 0 written, 1 a file could not be read (the others are counted), 2 a usage\n"
      "error.");
  cmd->add_option("TRACK", args->files, "Track files, folders of them or patterns; heatmaps (.mbtiles, folders) to add")
      ->required()
      ->type_name("FILE");
  cmd->add_option("-o,--output", args->output, "OUT.tif (counts), OUT.mbtiles or OUT/ (coloured tiles), atomically")
      ->required()
      ->type_name("OUT");
  cmd->add_option("--cell", args->cell_m, "Cell size in Mercator metres (default 50, or the added heatmaps')")
      ->check(CLI::Range(1.0, 100000.0))
      ->type_name("M")
      ->each([args](const std::string&) { args->cell_given = true; });
  cmd->add_option("--of", args->of, "What a cell counts: tracks, thermals (flights climbing there), time (seconds)")
      ->type_name("tracks|thermals|time");
  cmd->add_option("--bbox", args->bbox, "Only this box instead of the tracks' extent (degrees)")
      ->type_name("MIN_LAT,MIN_LON,MAX_LAT,MAX_LON");
  cmd->add_option("--zoom", args->zoom, "Tile zoom levels (default 0 to the one whose pixels match the cell)")
      ->type_name("MIN-MAX");
  cmd->add_option("--colormap", args->colormap, "Tile colours: warm (default), magma, viridis, turbo, cividis")
      ->type_name("NAME");
  cmd->add_option("--scale", args->scale, "Tile colour scale: log (default: readable from 1 to millions) or linear")
      ->type_name("log|linear");
  cmd->add_flag("--force", args->force, "Replace OUT when it exists");
  add_read_options(*cmd, args->read);
  cmd->callback([args, &exit_code] { exit_code = run_heatmap(*args); });
}

}  // namespace trailray::app
