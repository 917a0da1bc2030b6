#include "app/track_options.hpp"

#include <map>

namespace trailray::app {

void add_track_options(CLI::App& cmd, TrackOptions& o) {
  cmd.add_flag("--strict", o.read.strict,
               "Treat reader warnings (cut-off file, invalid points, bad records) as errors");
  const std::map<std::string, track::ReadOptions::IgcAltitude> altitudes{
      {"auto", track::ReadOptions::IgcAltitude::Auto},
      {"gnss", track::ReadOptions::IgcAltitude::Gnss},
      {"pressure", track::ReadOptions::IgcAltitude::Pressure}};
  cmd.add_option("--igc-altitude", o.read.igc_altitude,
                 "IGC altitude used as elevation: auto (GNSS when valid, else pressure), gnss, pressure")
      ->transform(CLI::CheckedTransformer(altitudes, CLI::ignore_case))
      ->default_str("auto");
  cmd.add_option("--min-distance", o.analysis.clean.min_distance_m,
                 "Cleaning: minimum distance between consecutive points, metres (0 = off)")
      ->check(CLI::Range(0.0, 1000.0))
      ->capture_default_str();
  cmd.add_flag("--no-smooth{false}", o.analysis.clean.smooth, "Cleaning: no Gaussian smoothing");
  cmd.add_option("--smooth-width", o.analysis.clean.smooth_half_width,
                 "Cleaning: Gaussian half-width N in points (kernel of 2N+1)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  cmd.add_option("--smooth-sigma", o.analysis.clean.smooth_sigma, "Cleaning: Gaussian sigma in points")
      ->check(CLI::Range(0.1, 100.0))
      ->capture_default_str();
}

}  // namespace trailray::app
