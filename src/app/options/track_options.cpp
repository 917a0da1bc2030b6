#include "app/options/track_options.hpp"

#include <CLI/CLI.hpp>
#include <cctype>
#include <map>

namespace trailray::app {

void add_track_options(CLI::App& cmd, TrackOptions& o) {
  add_read_options(cmd, o.read);
  add_cleaning_options(cmd, o.analysis);
}

void add_read_options(CLI::App& cmd, track::ReadOptions& read) {
  cmd.add_flag("--strict", read.strict, "Treat reader warnings (cut-off file, invalid points, bad records) as errors");
  const std::map<std::string, track::ReadOptions::IgcAltitude> altitudes{
      {"auto", track::ReadOptions::IgcAltitude::Auto},
      {"gnss", track::ReadOptions::IgcAltitude::Gnss},
      {"pressure", track::ReadOptions::IgcAltitude::Pressure}};
  cmd.add_option_function<std::string>(
         "--igc-altitude",
         [&read, altitudes](const std::string& v) {
           std::string key = v;
           for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
           read.igc_altitude = altitudes.at(key);
         },
         "IGC altitude used as elevation (the 3D track's, the statistics'): auto (GNSS when the fix is valid, "
         "else pressure), gnss, pressure. The viewer's chart shows both whichever is picked")
      ->check(CLI::IsMember({"auto", "gnss", "pressure"}, CLI::ignore_case))
      ->type_name("auto|gnss|pressure");
}

void add_cleaning_options(CLI::App& cmd, track::AnalysisOptions& analysis) {
  cmd.add_option("--min-distance", analysis.clean.min_distance_m,
                 "Cleaning: minimum distance between consecutive points, metres (0 = off; default 3)")
      ->check(CLI::Range(0.0, 1000.0))
      ->type_name("M");
  cmd.add_flag_callback(
      "--no-smooth", [&analysis] { analysis.clean.smooth = false; }, "Cleaning: no Gaussian smoothing");
  cmd.add_option("--smooth-width", analysis.clean.smooth_half_width,
                 "Cleaning: Gaussian half-width in points, kernel of 2N+1 (default 5)")
      ->check(CLI::Range(1, 100))
      ->type_name("N");
  cmd.add_option("--smooth-sigma", analysis.clean.smooth_sigma, "Cleaning: Gaussian sigma in points (default 1)")
      ->check(CLI::Range(0.1, 100.0))
      ->type_name("S");
}

}  // namespace trailray::app
