#include "track/places/place_area.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace trailray::track::places {

namespace {
constexpr double kMetresPerDegree = 111'320.0;  // along a meridian, near enough for a margin
constexpr double kPi = 3.14159265358979323846;
}  // namespace

geo::LatLonBounds grown_bounds(const geo::LatLonBounds& b, double margin_m) {
  if (b.empty()) return b;
  geo::LatLonBounds out = b;
  const double dlat = margin_m / kMetresPerDegree;
  out.min_lat = std::max(-90.0, b.min_lat - dlat);
  out.max_lat = std::min(90.0, b.max_lat + dlat);
  const double polemost = std::min(89.0, std::max(std::fabs(out.min_lat), std::fabs(out.max_lat)));
  const double dlon = margin_m / (kMetresPerDegree * std::cos(polemost * kPi / 180.0));
  out.min_lon = std::max(-180.0, b.min_lon - dlon);
  out.max_lon = std::min(180.0, b.max_lon + dlon);
  return out;
}

void merge_duplicate_places(std::vector<Place>& places, double radius_m) {
  // Sorted by latitude, each place is compared with those less than the radius north of it:
  // n log n for a country's peaks, not n².
  std::vector<std::size_t> order(places.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return places[a].lat_deg < places[b].lat_deg || (places[a].lat_deg == places[b].lat_deg && a < b);
  });
  const double dlat = radius_m / kMetresPerDegree;
  std::vector<bool> gone(places.size(), false);
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::size_t a = order[i];
    if (gone[a]) continue;
    for (std::size_t j = i + 1; j < order.size() && places[order[j]].lat_deg - places[a].lat_deg <= dlat; ++j) {
      const std::size_t b = order[j];
      if (gone[b] || places[b].kind != places[a].kind || places[b].name != places[a].name) continue;
      const double dy = (places[b].lat_deg - places[a].lat_deg) * kMetresPerDegree;
      const double dx = (places[b].lon_deg - places[a].lon_deg) * kMetresPerDegree *
                        std::cos(places[a].lat_deg * kPi / 180.0);
      if (dx * dx + dy * dy > radius_m * radius_m) continue;
      // The first in the file stays; it takes an elevation it lacks from the other.
      const std::size_t keep = std::min(a, b), drop = std::max(a, b);
      if (std::isnan(places[keep].ele_m)) places[keep].ele_m = places[drop].ele_m;
      gone[drop] = true;
      if (drop == a) break;
    }
  }
  std::size_t w = 0;
  for (std::size_t r = 0; r < places.size(); ++r)
    if (!gone[r]) {
      if (w != r) places[w] = std::move(places[r]);
      ++w;
    }
  places.resize(w);
}

}  // namespace trailray::track::places
