#pragma once
// From an OpenAir file (track/airspace) to the scene's volumes (volumes.hpp): each airspace a
// translucent volume coloured by its class, its limits in metres for drawing, culled and
// levelled so that a country's file draws only what matters around the flight.
//
// Heights: metres and feet above MSL are drawn as they are; flight levels are pressure altitudes
// (against 1013.25 hPa) and are drawn where the ICAO standard atmosphere puts them (FL 95 at
// 2896 m), which differs from the true height by the day's QNH (about 8 m per hPa); limits above
// the ground stand on the terrain under each boundary point (volume_shapes.hpp); UNL and
// ceilings above `ceiling_cap_m` are drawn up to the cap, faded out at the top.

#include <glm/glm.hpp>

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geo/bounds.hpp"
#include "scene/volumes/volumes.hpp"
#include "track/airspace/airspace.hpp"

namespace trailray::scene {

// An airspace class's look, following the common practice of pilots' maps (SkyDemon, XCSoar,
// the DFS/ICAO charts):
//   CTR               red           control zones, where a pilot must not stray
//   R, P, GP          red-orange    restricted, prohibited, glider prohibited
//   Q                 orange        danger areas (and the cables of Skytraxx files)
//   A, B              violet        controlled, no VFR without clearance
//   C                 dark blue     controlled (TMAs)
//   D                 blue          controlled (lower TMAs, CTAs)
//   E                 green         controlled, VFR free
//   F, G              olive         uncontrolled
//   TMZ, RMZ          grey          transponder and radio mandatory zones
//   W                 cyan          wave and gliding windows
//   anything else     grey-violet
struct AirspaceClassStyle {
  glm::vec3 color_srgb;
  float opacity;  // of the walls
};
AirspaceClassStyle airspace_class_style(std::string_view airspace_class);

// The class as the legend groups it: upper case, spaces trimmed ("c " -> "C").
std::string normalized_airspace_class(std::string_view airspace_class);

struct AirspaceDrawOptions {
  // Only airspaces whose boundary's box meets this box grown by `margin_m` (nullopt: all).
  std::optional<geo::LatLonBounds> region;
  double margin_m = 15000.0;
  // Airspaces whose floor lies above this (metres, MSL or pressure altitude) are left out: far
  // above the flight they only hide it.
  double max_floor_m = std::numeric_limits<double>::infinity();
  // Ceilings above this and UNL are drawn up to it (at least 1000 m over the floor), faded.
  double ceiling_cap_m = 6000.0;
  // At most this many volumes, the nearest to the region's centre first.
  std::size_t max_volumes = 400;
  // Ring simplification: points closer than this to the simplified ring are dropped; the
  // tolerance grows by `simplify_per_km` metres per kilometre of distance from the region.
  double simplify_m = 25.0;
  double simplify_per_km = 2.0;
  // Limits above the ground follow the terrain: such rings get a point at least this often.
  double ground_step_m = 400.0;
};

struct AirspaceVolumes {
  std::vector<Volume> volumes;
  std::size_t outside_region = 0;                   // left out: away from the region
  std::size_t above_floor = 0;                      // left out: floor above max_floor_m
  std::size_t over_cap = 0;                         // left out: beyond max_volumes
  std::size_t points_before = 0, points_after = 0;  // boundary points of those kept, before and after simplification
};

// The volumes for the airspaces of `file` read from `source` (named in each volume), by the
// options. GL-free and terrain-free: the ground under limits above it is placed later
// (place_volumes_on_ground).
AirspaceVolumes airspace_volumes(const track::airspace::AirspaceFile& file, const std::string& source,
                                 const AirspaceDrawOptions& options);

// A limit's height for drawing (metres): MSL as is, a flight level by the standard atmosphere,
// above the ground as the height over it; nullopt for unlimited.
std::optional<double> drawn_limit_metres(const track::airspace::AltitudeLimit& limit);

// What OpenAir's class code means ("Q": "danger", "C": "class"), empty for codes without a
// common meaning.
std::string_view airspace_class_meaning(std::string_view normalized);

// The classes of the visible airspaces, each once, in the order of the style table above, as
// the legend lists them: "Q danger", "class C", and the colour.
struct AirspaceClassShown {
  std::string label;
  glm::vec3 color_srgb;
};
std::vector<AirspaceClassShown> airspace_classes_shown(const VolumeSet& set);

}  // namespace trailray::scene
