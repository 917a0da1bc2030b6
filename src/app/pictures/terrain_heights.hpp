#pragma once
// The terrain's height under places, from the source of the terrain options (`trailray elevation`'s
// sampling: tiles loaded in parallel, progress, the warnings for tiles that failed and places without
// data). Shared by the command and the Python module's trailray.elevation.

#include <string>
#include <vector>

#include "app/options/terrain_options.hpp"
#include "geo/web_mercator.hpp"
#include "scene/diagnostics.hpp"

namespace trailray::app {

struct TerrainHeights {
  std::vector<double> heights;  // one per place; NaN where the source has no data (all NaN without a source)
  std::string source_name;      // the source's display name, "none" without one
  std::size_t tiles_failed = 0;  // tiles that could not be had (a server down, offline, a broken file)
};

// `file` names what the places belong to in the warnings. Throws terrain::ConfigError and the
// source's errors for a source that cannot be opened.
TerrainHeights terrain_heights(const std::vector<geo::LatLon>& places, const TerrainOptions& terrain,
                               scene::Diagnostics& diagnostics, const std::string& file);

// The surface model's height (`terrain.surface`: canopy and buildings) under the same places,
// sampled as the terrain is, with the terrain options' settings; empty heights and name without
// a surface model.
TerrainHeights surface_heights(const std::vector<geo::LatLon>& places, const TerrainOptions& terrain,
                               scene::Diagnostics& diagnostics, const std::string& file);

}  // namespace trailray::app
