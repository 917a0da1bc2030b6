#include "track/cover.hpp"

#include <cmath>

namespace trailray::track {

std::optional<Cover> classify_cover(double ele_m, double ground_m, double surface_m, const CoverOptions& o) {
  if (std::isnan(ground_m) || std::isnan(surface_m)) return std::nullopt;
  const double ele = std::isnan(ele_m) ? ground_m : ele_m;
  if (ele < ground_m - o.tolerance_m) return Cover::below_ground;
  // A surface below the ground (the two models' noise) is no cover either.
  if (surface_m - ground_m < o.agree_m || ele >= surface_m - o.tolerance_m) return Cover::open;
  return Cover::covered;
}

std::string_view cover_name(Cover cover) {
  switch (cover) {
    case Cover::open:
      return "open";
    case Cover::covered:
      return "covered";
    case Cover::below_ground:
      return "below_ground";
  }
  return "open";
}

}  // namespace trailray::track
