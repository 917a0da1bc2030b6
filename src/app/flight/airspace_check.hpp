#pragma once
// What `trailray check` compares with the airspace limits, per file read: its points with the
// altitudes the limits take (elevation; an IGC flight's pressure altitude for FL/STD limits), how
// those were chosen in words, and the terrain below them for AGL limits. Shared by the command
// and the Python module's Airspaces.check.

#include <string>
#include <vector>

#include "app/flight/check_report.hpp"
#include "app/options/terrain_options.hpp"
#include "scene/diagnostics.hpp"
#include "track/airspace/infringement.hpp"
#include "track/diagnostics.hpp"

namespace trailray::app {

using CheckSegments = std::vector<std::vector<track::airspace::CheckPoint>>;

struct CheckedPoints {
  CheckSegments segments;
  CheckedTrack track;  // path, points and altitudes filled; infringements empty
  std::size_t without_altitude = 0;
};

// The file's points as checked; `display_path` names it in the report.
CheckedPoints checked_points(const std::string& display_path, const track::TrackFile& file,
                             track::ReadOptions::IgcAltitude igc_altitude);

// The terrain of `terrain` under every point (CheckPoint::ground_m), for AGL limits; progress on
// the diagnostics' line unless `quiet`. Nothing without a source. (airspace_ground.cpp)
void add_ground_heights(const TerrainOptions& terrain, scene::Diagnostics& diagnostics, bool quiet,
                        std::vector<CheckSegments>& tracks);

}  // namespace trailray::app
