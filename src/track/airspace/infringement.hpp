#pragma once
// Which airspaces a flight entered, when, and how deep. A point is inside an airspace when it
// lies within the boundary and between floor and ceiling, each limit compared with the altitude
// it is given in:
//   - FL and STD limits with the pressure altitude (an IGC file's pressure altitude is against
//     1013.25 hPa, as flight levels are, so they compare directly);
//   - MSL limits with the GNSS altitude (or a track's only elevation);
//   - AGL/GND limits with the GNSS altitude minus the ground height, when ground heights are
//     given. Without them the ground is unknown and taken conservatively: a floor above ground
//     as if the ground were at sea level (the lowest that floor can be), a ceiling above ground
//     as never below the aircraft. Such infringements are marked `ground_assumed`.
// Entry and exit times are where the straight line between two fixes (position, altitudes and
// time linear in between) crosses the airspace's surface, found by bisection to 1e-6 of the step.

#include <string>
#include <vector>

#include "track/airspace/airspace_index.hpp"

namespace trailray::track::airspace {

struct CheckPoint {
  double lat = 0, lon = 0;
  double time = kMissing;      // seconds since the epoch (NaN when the track has no times)
  double msl_m = kMissing;     // GNSS altitude, or the elevation of a track without pressure altitude
  double std_m = kMissing;     // pressure altitude against 1013.25 hPa; NaN: msl_m is used instead
  double ground_m = kMissing;  // terrain height below the point; NaN: unknown
};

// One stretch of a track inside one airspace.
struct Infringement {
  std::size_t airspace = 0;     // index into the AirspaceFile
  std::size_t segment = 0;      // which of the given segments
  std::size_t first_point = 0;  // first and last fix inside
  std::size_t last_point = 0;
  double entry_time = kMissing;  // crossing time; the first fix's time when inside from the start
  double exit_time = kMissing;   // crossing time; the last fix's time when inside at the end
  bool inside_at_start = false, inside_at_end = false;
  double max_horizontal_m = 0;            // deepest distance inside the boundary, over the fixes inside
  double max_above_floor_m = kMissing;    // NaN when the floor is unknown (GND without terrain)
  double max_below_ceiling_m = kMissing;  // NaN when the ceiling is unlimited or unknown
  double max_vertical_m = kMissing;       // max over the fixes of min(above floor, below ceiling)
  std::string floor_altitude;             // "pressure", "gnss", "gnss-ground", "none" (the altitude used)
  std::string ceiling_altitude;
  bool ground_assumed = false;  // an AGL limit was used without ground heights
};

// Every infringement of every segment, ordered by segment, then entry.
std::vector<Infringement> find_infringements(const AirspaceIndex& index,
                                             const std::vector<std::vector<CheckPoint>>& segments);

}  // namespace trailray::track::airspace
