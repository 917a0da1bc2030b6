#include "track/places/summits.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <tuple>
#include <unordered_map>

namespace trailray::track::places {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMetresPerDegree = 111'320.0;  // along a meridian: the distances here are tens of metres
constexpr double kCellDeg = 0.01;               // the grid: about 1.1 km north-south

std::int64_t cell_of(double deg) { return static_cast<std::int64_t>(std::floor(deg / kCellDeg)); }
std::uint64_t key_of(std::int64_t row, std::int64_t col) {
  return (static_cast<std::uint64_t>(row) << 32) ^ static_cast<std::uint64_t>(col & 0xffffffff);
}

// The candidate places (summits and huts) by grid cell.
struct PlaceGrid {
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells;
  void add(std::size_t index, double lat, double lon) {
    cells[key_of(cell_of(lat), cell_of(lon))].push_back(index);
  }
  // Every place in the cells the box touches.
  template <class F>
  void each_near(double min_lat, double min_lon, double max_lat, double max_lon, F&& f) const {
    for (std::int64_t r = cell_of(min_lat); r <= cell_of(max_lat); ++r)
      for (std::int64_t c = cell_of(min_lon); c <= cell_of(max_lon); ++c) {
        const auto found = cells.find(key_of(r, c));
        if (found != cells.end())
          for (std::size_t i : found->second) f(i);
      }
  }
};

double lerp(double a, double b, double t) {
  if (std::isnan(a)) return t < 0.5 || std::isnan(b) ? a : b;
  if (std::isnan(b)) return t > 0.5 ? b : a;
  return a + (b - a) * t;
}

struct Approach {
  double distance_m, fraction;
};

// The nearest point of the leg a→b to the place, in a plane tangent at the place (tens of
// metres: flat is exact enough).
Approach nearest_on_leg(const Place& p, const TrackPoint& a, const TrackPoint& b) {
  const double east = kMetresPerDegree * std::cos(p.lat_deg * kPi / 180.0);
  const double ax = (a.lon - p.lon_deg) * east, ay = (a.lat - p.lat_deg) * kMetresPerDegree;
  const double bx = (b.lon - p.lon_deg) * east, by = (b.lat - p.lat_deg) * kMetresPerDegree;
  const double dx = bx - ax, dy = by - ay;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? -(ax * dx + ay * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return {std::hypot(ax + t * dx, ay + t * dy), t};
}

double leg_length_m(const TrackPoint& a, const TrackPoint& b) {
  const double east = kMetresPerDegree * std::cos(a.lat * kPi / 180.0);
  return std::hypot((b.lon - a.lon) * east, (b.lat - a.lat) * kMetresPerDegree);
}

}  // namespace

PlacesVisited places_visited(const Track& track, const std::vector<Place>& places, const VisitRules& rules) {
  PlaceGrid grid;
  for (std::size_t i = 0; i < places.size(); ++i)
    if (is_summit(places[i].kind) || is_hut(places[i].kind)) grid.add(i, places[i].lat_deg, places[i].lon_deg);
  std::vector<std::optional<PlaceVisit>> best(places.size());
  if (grid.cells.empty()) return {};

  const double reach_lat = rules.reach_m / kMetresPerDegree;
  for (std::size_t s = 0; s < track.segments.size(); ++s) {
    const std::vector<TrackPoint>& points = track.segments[s].points;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const TrackPoint& a = points[i];
      if (!std::isfinite(a.lat) || !std::isfinite(a.lon)) continue;
      // The leg to the next fix, or the fix alone (the last one, or a leg over a gap).
      const TrackPoint* b = &a;
      if (i + 1 < points.size() && std::isfinite(points[i + 1].lat) && std::isfinite(points[i + 1].lon) &&
          leg_length_m(a, points[i + 1]) <= rules.longest_leg_m)
        b = &points[i + 1];
      const double reach_lon = reach_lat / std::max(0.01, std::cos(a.lat * kPi / 180.0));
      grid.each_near(std::min(a.lat, b->lat) - reach_lat, std::min(a.lon, b->lon) - reach_lon,
                     std::max(a.lat, b->lat) + reach_lat, std::max(a.lon, b->lon) + reach_lon, [&](std::size_t k) {
                       const Place& p = places[k];
                       const Approach near = nearest_on_leg(p, a, *b);
                       if (near.distance_m > rules.reach_m) return;
                       const double ele = lerp(a.ele, b->ele, near.fraction);
                       // A summit: not more than `below_m` under its ele (when both are known).
                       if (is_summit(p.kind) && !std::isnan(p.ele_m) && !std::isnan(ele) && ele < p.ele_m - rules.below_m)
                         return;
                       if (best[k] && best[k]->distance_m <= near.distance_m) return;
                       PlaceVisit v;
                       v.place = p;
                       v.distance_m = near.distance_m;
                       v.time_unix_s = lerp(a.time, b->time, near.fraction);
                       v.track_ele_m = ele;
                       v.segment = s;
                       v.point = i;
                       v.fraction = near.fraction;
                       best[k] = std::move(v);
                     });
    }
  }
  PlacesVisited out;
  for (std::optional<PlaceVisit>& v : best)
    if (v) (is_summit(v->place.kind) ? out.summits : out.huts).push_back(std::move(*v));
  const auto along = [](const PlaceVisit& x, const PlaceVisit& y) {
    return std::tie(x.segment, x.point, x.fraction) < std::tie(y.segment, y.point, y.fraction);
  };
  std::stable_sort(out.summits.begin(), out.summits.end(), along);
  std::stable_sort(out.huts.begin(), out.huts.end(), along);
  return out;
}

}  // namespace trailray::track::places
