#include "app/heatmap_command.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>

#include "app/output_file.hpp"
#include "app/parallel_jobs.hpp"
#include "app/terminal_diagnostics.hpp"
#include "app/track_arguments.hpp"
#include "app/track_options.hpp"
#include "terrain/count_geotiff.hpp"
#include "track/heatmap.hpp"
#include "track/io/load.hpp"

namespace trailray::app {
namespace {

struct HeatmapArgs {
  std::vector<std::string> files;
  std::string output;
  double cell_m = 50.0;
  std::string bbox;
  bool force = false;
  track::ReadOptions read;
};

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

int run_heatmap(const HeatmapArgs& a) {
  std::string lower = a.output;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (!lower.ends_with(".tif") && !lower.ends_with(".tiff"))
    throw CLI::ValidationError("-o", fmt::format("'{}': a heatmap is written as a GeoTIFF (.tif)", a.output));
  std::optional<std::array<double, 4>> bbox;
  if (!a.bbox.empty()) {
    bbox = parse_bbox(a.bbox);
    if (!bbox)
      throw CLI::ValidationError("--bbox", fmt::format("'{}' is not MIN_LAT,MIN_LON,MAX_LAT,MAX_LON with min < max",
                                                       a.bbox));
  }
  check_output_path(a.output, a.files, a.force);

  TerminalDiagnostics diagnostics(false, isatty(STDERR_FILENO) != 0);
  track::HeatmapCounts counts(a.cell_m);
  std::mutex mutex;
  std::vector<std::optional<std::string>> errors(a.files.size());
  std::vector<std::vector<std::string>> warnings(a.files.size());
  // Each file read, its tracks' cells worked out and counted, then freed: memory follows the grid.
  run_parallel_jobs(
      a.files.size(),
      [&](std::size_t i) {
        track::ReadResult r = track::load_track_file(a.files[i], a.read);
        for (const auto& w : r.warnings) warnings[i].push_back(w.to_string());
        if (r.error) {
          errors[i] = r.error->to_string();
          return true;
        }
        std::vector<std::vector<track::HeatmapCell>> cells;
        for (const track::Track& t : r.file.tracks) cells.push_back(counts.track_cells(t));
        std::lock_guard lock(mutex);
        for (const auto& c : cells) counts.add_cells(c);
        return true;
      },
      {0, [&](std::size_t done, std::size_t n) { diagnostics.progress(fmt::format("[{}/{}] files counted", done, n)); }});
  diagnostics.progress_done();
  int failed = 0;
  for (std::size_t i = 0; i < a.files.size(); ++i) {
    for (const auto& w : warnings[i]) diagnostics.warning(w);
    if (errors[i]) {
      diagnostics.error(*errors[i]);
      ++failed;
    }
  }
  const track::HeatmapWindow window = bbox ? counts.window_of((*bbox)[0], (*bbox)[1], (*bbox)[2], (*bbox)[3])
                                           : counts.extent();
  if (window.empty()) {
    diagnostics.error("no track point to count: nothing written");
    return 1;
  }
  // The raster is made whole in memory (4 bytes a cell): at most 1 GiB of it.
  constexpr std::int64_t kMaxCells = std::int64_t{1} << 28;
  if (window.width() * window.height() > kMaxCells)
    throw std::runtime_error(fmt::format("{}x{} cells is more than one GeoTIFF of a heatmap holds here ({} cells): a "
                                         "larger --cell, or a --bbox around the tracks you want",
                                         window.width(), window.height(), kMaxCells));
  const std::vector<std::uint32_t> raster = counts.raster(window);
  const std::vector<unsigned char> tiff =
      terrain::encode_count_geotiff(raster, static_cast<std::uint32_t>(window.width()),
                                    static_cast<std::uint32_t>(window.height()), counts.geotransform(window));
  write_file_atomically(a.output, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(tiff.data()), static_cast<std::streamsize>(tiff.size()));
  });
  const std::uint32_t most = raster.empty() ? 0 : *std::max_element(raster.begin(), raster.end());
  fmt::print("{}: {} tracks from {} files{}, {} m cells, {}x{} cells, at most {} tracks in a cell\n", a.output,
             counts.tracks(), a.files.size() - static_cast<std::size_t>(failed),
             failed ? fmt::format(" ({} could not be read)", failed) : "", a.cell_m, window.width(), window.height(),
             most);
  return failed > 0 ? 1 : 0;
}

}  // namespace

void add_heatmap_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<HeatmapArgs>();
  CLI::App* cmd = app.add_subcommand("heatmap", "How many tracks passed through each cell of a grid, as a GeoTIFF");
  cmd->footer(
      "A track counts once in every cell it passes through; the line between two consecutive\n"
      "points counts for every cell it crosses (a step over 10 km is a gap: its ends count). The grid\n"
      "is Web Mercator's (EPSG:3857), the same for every run with the same --cell, so heatmaps of\n"
      "different files add up; the cell is in Mercator metres (on the ground: times cos(latitude)).\n"
      "OUT.tif: one band, UInt32, EPSG:3857, the extent of the tracks or --bbox (QGIS and GDAL open\n"
      "it as it is). Files are read and counted one by one; one that cannot be read is reported and\n"
      "counted nowhere. Exit status: 0 written, 1 a file could not be read (the others are counted),\n"
      "2 a usage error.");
  cmd->add_option("TRACK", args->files, "Track files, folders of them or patterns")->required()->type_name("FILE");
  cmd->add_option("-o,--output", args->output, "The GeoTIFF to write (atomically)")->required()->type_name("OUT.tif");
  cmd->add_option("--cell", args->cell_m, "Cell size in Mercator metres (default 50)")
      ->check(CLI::Range(1.0, 100000.0))
      ->type_name("M");
  cmd->add_option("--bbox", args->bbox, "Write this box instead of the tracks' extent (degrees)")
      ->type_name("MIN_LAT,MIN_LON,MAX_LAT,MAX_LON");
  cmd->add_flag("--force", args->force, "Replace OUT when it exists");
  add_read_options(*cmd, args->read);
  cmd->callback([args, &exit_code] {
    args->files = expand_track_arguments(args->files);
    exit_code = run_heatmap(*args);
  });
}

}  // namespace trailray::app
