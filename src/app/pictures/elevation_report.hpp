#pragma once
// The numbers of `trailray elevation`: per point the recorded elevation, the terrain height and
// their difference (height above ground), and a summary of the differences. Formatting as JSON,
// CSV and a short table.

#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "track/cover.hpp"

namespace trailray::app {

struct ElevationPoint {
  std::size_t track = 0, segment = 0;  // indices in the file (routes follow the tracks)
  double lat = 0.0, lon = 0.0;
  double ele_m = 0.0;      // recorded; NaN when absent
  double terrain_m = 0.0;  // NaN where the source has no data
  double surface_m = std::numeric_limits<double>::quiet_NaN();  // --surface: canopy and buildings
  double agl_m() const { return ele_m - terrain_m; }  // NaN unless both are known
  double canopy_m() const { return surface_m - terrain_m; }  // the surface above the ground
  std::optional<track::Cover> cover() const { return track::classify_cover(ele_m, terrain_m, surface_m); }
};

struct ElevationSummary {
  std::size_t points = 0, with_elevation = 0, with_terrain = 0, compared = 0;
  double mean_offset_m = 0.0, median_offset_m = 0.0, rmse_m = 0.0;  // NaN when nothing to compare
  double min_offset_m = 0.0, max_offset_m = 0.0;
  std::size_t points_below_ground = 0;
  // With --surface: points classed open, under cover, below the ground (track/cover.hpp).
  std::size_t open = 0, covered = 0, cover_below_ground = 0;
  double covered_share() const;  // covered of the classed points; NaN when none is
};

ElevationSummary summarize(const std::vector<ElevationPoint>& points);

struct ElevationReport {
  std::string path;     // the track file as given
  std::string terrain;  // the source's display name
  std::string surface;  // --surface's display name; empty without one
  std::vector<ElevationPoint> points;
  ElevationSummary summary;
};

nlohmann::ordered_json elevation_json(const ElevationReport& report);
// The document's "summary" alone (the Python module's trailray.elevation: without every point).
nlohmann::ordered_json elevation_summary_json(const ElevationSummary& summary, bool with_surface = false);
std::string elevation_csv(const ElevationReport& report);
std::string elevation_table(const ElevationReport& report);

}  // namespace trailray::app
