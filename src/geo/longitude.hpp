#pragma once
// Longitudes of shapes that may cross the antimeridian (an oceanic airspace east of New Zealand,
// the Chukotka border): a ring's longitudes kept continuous (179.5, 180.5 rather than 179.5,
// -179.5), so its box, its edges and its inside are those of the shape on the globe, and a
// point's longitude moved by whole turns next to such a ring before it is compared with it.

#include <cmath>
#include <vector>

#include "geo/web_mercator.hpp"

namespace trailray::geo {

// Each point after the first moved by whole turns so that it lies within 180 degrees of the one
// before it: a ring crossing the antimeridian then runs past +-180 instead of jumping.
inline void unwrap_longitudes(std::vector<LatLon>& ring) {
  for (std::size_t i = 1; i < ring.size(); ++i) {
    const double step = ring[i].lon - ring[i - 1].lon;
    ring[i].lon = ring[i - 1].lon + (step - 360.0 * std::round(step / 360.0));
  }
}

// `lon` moved by a whole turn towards [lo, hi] (a box of unwrapped longitudes) when that brings
// it inside or closer; otherwise as given.
inline double longitude_near(double lon, double lo, double hi) {
  const auto outside = [lo, hi](double x) { return x < lo ? lo - x : x > hi ? x - hi : 0.0; };
  for (const double turned : {lon - 360.0, lon + 360.0})
    if (outside(turned) < outside(lon)) return turned;
  return lon;
}

// Into [-180, 180): what readers of plain longitudes (terrain tiles, samplers) expect.
inline double wrapped_longitude(double lon) { return lon - 360.0 * std::floor((lon + 180.0) / 360.0); }

}  // namespace trailray::geo
