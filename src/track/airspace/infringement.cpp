#include "track/airspace/infringement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "geo/wgs84.hpp"

namespace trailray::track::airspace {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A limit as a height comparable with one of the point's altitudes.
struct Level {
  double above_m = 0;  // the point's altitude minus the limit (positive: above it)
  bool known = true;   // false: the limit cannot be placed (ground unknown, unlimited)
  const char* altitude = "none";
  bool assumed = false;
};

Level floor_level(const AltitudeLimit& limit, const CheckPoint& p) {
  switch (limit.reference) {
    case AltitudeReference::Unlimited:
      return {kInf, false, "none", false};
    case AltitudeReference::Std:
      if (!std::isnan(p.std_m)) return {p.std_m - limit.metres, true, "pressure", false};
      return {p.msl_m - limit.metres, true, "gnss", false};
    case AltitudeReference::Msl:
      return {p.msl_m - limit.metres, true, "gnss", false};
    case AltitudeReference::Agl:
      if (!std::isnan(p.ground_m)) return {p.msl_m - p.ground_m - limit.metres, true, "gnss-ground", false};
      if (limit.metres == 0.0) return {kInf, false, "none", true};  // GND: below every aircraft
      return {p.msl_m - limit.metres, true, "gnss", true};          // ground taken at sea level
  }
  return {};
}

Level ceiling_level(const AltitudeLimit& limit, const CheckPoint& p) {
  Level l = floor_level(limit, p);
  if (limit.reference == AltitudeReference::Unlimited) return {-kInf, false, "none", false};
  if (limit.reference == AltitudeReference::Agl && std::isnan(p.ground_m)) return {-kInf, false, "none", true};
  return l;
}

struct PointState {
  bool inside = false;
  double above_floor = kMissing, below_ceiling = kMissing;
  Level floor, ceiling;
};

PointState evaluate(const AirspaceIndex& index, std::size_t a, const CheckPoint& p) {
  const Airspace& air = index.file().airspaces[a];
  PointState s;
  s.floor = floor_level(air.floor, p);
  s.ceiling = ceiling_level(air.ceiling, p);
  // NaN altitudes (a fix without any) compare false: such a fix is never inside.
  const bool vertical = s.floor.above_m >= 0.0 && s.ceiling.above_m <= 0.0;
  if (!vertical) return s;
  s.inside = index.contains(a, p.lat, p.lon);
  if (s.floor.known) s.above_floor = s.floor.above_m;
  if (s.ceiling.known) s.below_ceiling = -s.ceiling.above_m;
  return s;
}

CheckPoint lerp(const CheckPoint& a, const CheckPoint& b, double t) {
  auto mix = [t](double x, double y) { return x + (y - x) * t; };
  // Longitude the short way round: two fixes either side of the antimeridian are 0.2 degrees
  // apart, not 359.8.
  const double lon = a.lon + geo::wgs84::wrap_dlon_deg(b.lon - a.lon) * t;
  return {mix(a.lat, b.lat),     lon,  mix(a.time, b.time), mix(a.msl_m, b.msl_m), mix(a.std_m, b.std_m),
          mix(a.ground_m, b.ground_m)};
}

// The time where the line from `out` (outside) to `in` (inside) enters the airspace.
double crossing_time(const AirspaceIndex& index, std::size_t a, const CheckPoint& out, const CheckPoint& in) {
  double lo = 0.0, hi = 1.0;  // evaluate(lo) outside, evaluate(hi) inside
  for (int i = 0; i < 20; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (evaluate(index, a, lerp(out, in, mid)).inside)
      hi = mid;
    else
      lo = mid;
  }
  return out.time + (in.time - out.time) * 0.5 * (lo + hi);
}

void update_depth(Infringement& f, const PointState& s, double horizontal_m) {
  f.max_horizontal_m = std::max(f.max_horizontal_m, horizontal_m);
  auto raise = [](double& m, double v) {
    if (!std::isnan(v)) m = std::isnan(m) ? v : std::max(m, v);
  };
  raise(f.max_above_floor_m, s.above_floor);
  raise(f.max_below_ceiling_m, s.below_ceiling);
  const double vertical = std::isnan(s.above_floor)     ? s.below_ceiling
                          : std::isnan(s.below_ceiling) ? s.above_floor
                                                        : std::min(s.above_floor, s.below_ceiling);
  raise(f.max_vertical_m, vertical);
  if (f.floor_altitude.empty() || f.floor_altitude == "none") f.floor_altitude = s.floor.altitude;
  if (f.ceiling_altitude.empty() || f.ceiling_altitude == "none") f.ceiling_altitude = s.ceiling.altitude;
  f.ground_assumed = f.ground_assumed || s.floor.assumed || s.ceiling.assumed;
}

}  // namespace

std::vector<Infringement> find_infringements(const AirspaceIndex& index,
                                             const std::vector<std::vector<CheckPoint>>& segments) {
  std::vector<Infringement> done;
  for (std::size_t seg = 0; seg < segments.size(); ++seg) {
    const auto& points = segments[seg];
    std::map<std::size_t, Infringement> open;  // airspace -> its stretch in progress
    std::vector<std::size_t> inside_now;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const CheckPoint& p = points[i];
      inside_now.clear();
      for (std::uint32_t a : index.candidates(p.lat, p.lon)) {
        const PointState s = evaluate(index, a, p);
        if (!s.inside) continue;
        inside_now.push_back(a);
        auto it = open.find(a);
        if (it == open.end()) {
          Infringement f;
          f.airspace = a;
          f.segment = seg;
          f.first_point = i;
          f.inside_at_start = i == 0;
          f.entry_time = i == 0 ? p.time : crossing_time(index, a, points[i - 1], p);
          it = open.emplace(a, f).first;
        }
        it->second.last_point = i;
        update_depth(it->second, s, index.distance_to_boundary_m(a, p.lat, p.lon));
      }
      for (auto it = open.begin(); it != open.end();) {
        if (std::find(inside_now.begin(), inside_now.end(), it->first) != inside_now.end()) {
          ++it;
          continue;
        }
        // Left between the last fix inside and this one: the crossing, seen backwards.
        Infringement& f = it->second;
        f.exit_time = crossing_time(index, f.airspace, p, points[i - 1]);
        done.push_back(std::move(f));
        it = open.erase(it);
      }
    }
    for (auto& [a, f] : open) {
      f.inside_at_end = true;
      f.exit_time = points.back().time;
      done.push_back(std::move(f));
    }
  }
  std::stable_sort(done.begin(), done.end(), [](const Infringement& x, const Infringement& y) {
    if (x.segment != y.segment) return x.segment < y.segment;
    return x.first_point < y.first_point;
  });
  return done;
}

}  // namespace trailray::track::airspace
