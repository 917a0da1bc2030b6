#include "track/scoring/cylinders.hpp"

namespace trailray::track::scoring {
namespace {

using LatLon = std::pair<double, double>;

// `point` moved away from `origin` along their line (in degrees) by `km`.
LatLon move_away(const Metric& m, const LatLon& point, const LatLon& origin, double km) {
  const double d0 = m.distance(point.first, point.second, origin.first, origin.second);
  if (d0 <= 0) return point;
  const double t = (d0 + km) / d0;
  return {(1 - t) * origin.first + t * point.first, (1 - t) * origin.second + t * point.second};
}

LatLon middle(const LatLon& a, const LatLon& b) { return {(a.first + b.first) / 2, (a.second + b.second) / 2}; }

}  // namespace

void apply_fai_cylinders(const Metric& m, TypeResult& r) {
  if (!r.valid || r.score <= 0) return;
  const FlightType& t = r.type;
  const double km = t.cylinders;
  std::vector<LatLon>& p = r.positions;
  double sum = 0;
  if (t.shape == Shape::Triangle) {
    std::vector<LatLon> moved(3);
    for (std::size_t i = 0; i < 3; ++i) moved[i] = move_away(m, p[i], middle(p[(i + 2) % 3], p[(i + 1) % 3]), km);
    p = moved;
    for (std::size_t i = 0; i < 3; ++i) {
      const LatLon& a = p[i];
      const LatLon& b = p[(i + 1) % 3];
      r.legs[i] = round2(m.distance(a.first, a.second, b.first, b.second)) - 2 * km;
      sum += r.legs[i];
    }
  } else if (t.shape == Shape::FreeDistance) {
    std::vector<LatLon> moved(p);
    for (std::size_t i = 1; i <= 3; ++i) moved[i] = move_away(m, p[i], middle(p[i - 1], p[i + 1]), km);
    moved[0] = move_away(m, p[0], moved[1], km);
    moved[4] = move_away(m, p[4], moved[3], km);
    p = moved;
    for (std::size_t i = 0; i < 4; ++i) {
      r.legs[i] = round2(m.distance(p[i].first, p[i].second, p[i + 1].first, p[i + 1].second)) - 2 * km;
      sum += r.legs[i];
    }
  } else {
    return;
  }
  for (int& f : r.points) f = -1;  // the points are no longer fixes
  r.distance = final_round(t, sum);
  r.score = r.distance >= t.min_distance ? final_round(t, (r.distance - r.penalty) * t.multiplier) : 0.0;
}

}  // namespace trailray::track::scoring
