#pragma once
// Where a point of a track is against a surface model (canopy and buildings) beside the terrain
// model (the bare ground): in the open, under cover (a forest, a roof) or below the ground (a
// tunnel, or a bad altitude). A terrain model alone cannot tell a track under trees from one
// behind a ridge; the two models together can (issue "surface model beside the terrain").

#include <cstdint>
#include <optional>
#include <string_view>

namespace trailray::track {

enum class Cover : std::uint8_t { open = 0, covered = 1, below_ground = 2 };

struct CoverOptions {
  // Where the surface is less than this above the ground the two agree: bare ground, a meadow,
  // a road; nothing covers a point there.
  double agree_m = 2.0;
  // A point this far below the surface (or the ground) still counts as on it: GPS and barometric
  // altitudes, and the models themselves, are a few metres off.
  double tolerance_m = 3.0;
};

// The class of a point at elevation `ele_m` (NaN: on the ground, as points without an elevation
// are drawn) over ground `ground_m` under surface `surface_m`; nullopt where either model has
// no height there.
std::optional<Cover> classify_cover(double ele_m, double ground_m, double surface_m, const CoverOptions& options = {});

// "open", "covered", "below_ground" (the spelling of `elevation --json`).
std::string_view cover_name(Cover cover);

}  // namespace trailray::track
