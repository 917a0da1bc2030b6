#include "track/task/task_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "track/task/earth.hpp"

namespace trailray::track::task {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kGolden = 0.6180339887498949;

struct Circle {
  geo::LatLon centre;
  double radius_m = 0.0;
  bool point = false;  // the route goes through the centre
};

// The route's length through `x` (on circle c) between its neighbours (either may be absent),
// and the sign of its derivative along the circle.
struct LegSum {
  const Earth& earth;
  const Circle& circle;
  const geo::LatLon* prev;
  const geo::LatLon* next;

  geo::LatLon at(double azimuth) const { return earth.destination(circle.centre, azimuth, circle.radius_m); }
  double operator()(double azimuth) const {
    const geo::LatLon x = at(azimuth);
    double s = 0.0;
    if (prev != nullptr) s += earth.distance_m(*prev, x);
    if (next != nullptr) s += earth.distance_m(x, *next);
    return s;
  }
  // Proportional to -d(length)/d(azimuth): moving x along the circle's tangent t shortens the
  // leg to a neighbour P at the rate cos(angle between t and the direction from x to P). Exact
  // to the last bits where the length itself, a sum of long legs, is not: this locates the
  // minimum to micrometres.
  double descent(double azimuth) const {
    const geo::LatLon x = at(azimuth);
    const double tangent = earth.azimuth_deg(x, circle.centre) - 90.0;
    double g = 0.0;
    if (prev != nullptr && (prev->lat != x.lat || prev->lon != x.lon))
      g += std::cos((earth.azimuth_deg(x, *prev) - tangent) * kPi / 180.0);
    if (next != nullptr && (next->lat != x.lat || next->lon != x.lon))
      g += std::cos((earth.azimuth_deg(x, *next) - tangent) * kPi / 180.0);
    return g;
  }
};

// Golden-section search for the minimum of f on [lo, hi] (degrees) to `tol_deg`.
template <typename F>
double golden_minimum(const F& f, double lo, double hi, double tol_deg) {
  double a = lo, b = hi;
  double c = b - kGolden * (b - a), d = a + kGolden * (b - a);
  double fc = f(c), fd = f(d);
  while (b - a > tol_deg) {
    if (fc < fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - kGolden * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + kGolden * (b - a);
      fd = f(d);
    }
  }
  return 0.5 * (a + b);
}

// The minimum near `a` refined where the derivative changes sign (the length's rounding noise
// limits a search on values to about 1e-4 rad); `a` itself when no sign change is near.
double refine(const LegSum& f, double a) {
  constexpr double kHalf = 0.05;  // degrees: several times the value search's resolution
  double lo = a - kHalf, hi = a + kHalf;
  if (!(f.descent(lo) > 0.0 && f.descent(hi) < 0.0)) return a;
  for (int it = 0; it < 60 && hi - lo > 1e-13; ++it) {
    const double mid = 0.5 * (lo + hi);
    (f.descent(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The azimuth on the circle minimising the legs: near `current` when `local` (a window of
// +-kWindow degrees, widened to the whole circle when the minimum sits on its edge), else from
// a scan of the whole circle.
double best_azimuth(const LegSum& f, double current, bool local) {
  constexpr double kWindow = 5.0, kValueTol = 1e-3;
  if (local) {
    const double a = golden_minimum(f, current - kWindow, current + kWindow, kValueTol);
    if (std::abs(a - current) < kWindow * 0.98) return refine(f, a);
  }
  constexpr int kSamples = 72;
  double best = 0.0, best_value = std::numeric_limits<double>::infinity();
  for (int k = 0; k < kSamples; ++k) {
    const double az = -180.0 + 360.0 * k / kSamples;
    const double v = f(az);
    if (v < best_value) best_value = v, best = az;
  }
  const double step = 360.0 / kSamples;
  return refine(f, golden_minimum(f, best - step, best + step, kValueTol));
}

// Coordinate descent from `points` (one per node; nodes are the distinct consecutive circles).
double descend(const Earth& earth, const std::vector<Circle>& nodes, std::vector<geo::LatLon>& points,
               const OptimiseOptions& options, TaskRoute& stats) {
  const std::size_t n = nodes.size();
  std::vector<double> azimuth(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    if (!nodes[i].point) azimuth[i] = earth.azimuth_deg(nodes[i].centre, points[i]);
  stats.converged = false;
  for (int sweep = 0; sweep < options.max_sweeps; ++sweep) {
    double moved = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const Circle& c = nodes[i];
      if (c.point) continue;
      const LegSum f{earth, c, i > 0 ? &points[i - 1] : nullptr, i + 1 < n ? &points[i + 1] : nullptr};
      // The first sweep scans whole circles: the start may be far from the optimum.
      const double a = best_azimuth(f, azimuth[i], sweep >= 1);
      const geo::LatLon x = f.at(a);
      moved = std::max(moved, earth.distance_m(points[i], x));
      points[i] = x;
      azimuth[i] = std::remainder(a, 360.0);
    }
    stats.sweeps = sweep + 1;
    stats.last_move_m = moved;
    if (sweep >= 1 && moved < options.tolerance_m) {
      stats.converged = true;
      break;
    }
  }
  double length = 0.0;
  for (std::size_t i = 1; i < n; ++i) length += earth.distance_m(points[i - 1], points[i]);
  return length;
}

geo::LatLon toward(const Earth& earth, const Circle& c, const geo::LatLon& target) {
  if (c.point || (target.lat == c.centre.lat && target.lon == c.centre.lon)) return c.centre;
  return earth.destination(c.centre, earth.azimuth_deg(c.centre, target), c.radius_m);
}

}  // namespace

bool is_route_point(const Task& task, std::size_t index) {
  const Turnpoint& tp = task.turnpoints[index];
  if (task.waypoints_only || tp.radius_m <= 0.0 || tp.role == Role::Takeoff) return true;
  return tp.role == Role::Goal && task.goal_type == GoalType::Line;
}

TaskDistances measure_task(const Task& task, const OptimiseOptions& options) {
  TaskDistances out;
  const Earth earth(task.earth);
  const std::size_t n = task.turnpoints.size();
  if (n == 0) return out;
  std::vector<Circle> circles(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Turnpoint& tp = task.turnpoints[i];
    circles[i] = {{tp.lat, tp.lon}, std::max(0.0, tp.radius_m), is_route_point(task, i)};
  }

  out.centre_cumulative_m.assign(n, 0.0);
  for (std::size_t i = 1; i < n; ++i)
    out.centre_cumulative_m[i] =
        out.centre_cumulative_m[i - 1] + earth.distance_m(circles[i - 1].centre, circles[i].centre);
  out.centre_m = out.centre_cumulative_m.back();

  // Consecutive identical circles are one node: a single touch reaches both, and two points on
  // one circle would freeze each other (moving either costs as much on the leg between them as
  // it saves on the other).
  std::vector<Circle> nodes;
  std::vector<std::size_t> node_of(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Circle& c = circles[i];
    const bool same = !nodes.empty() && i > 0 && !c.point && !nodes.back().point &&
                      nodes.back().centre.lat == c.centre.lat && nodes.back().centre.lon == c.centre.lon &&
                      nodes.back().radius_m == c.radius_m;
    if (!same) nodes.push_back(c);
    node_of[i] = nodes.size() - 1;
  }
  const std::size_t m = nodes.size();
  bool any_circle = false;
  for (const Circle& c : nodes) any_circle = any_circle || !c.point;

  TaskRoute& route = out.optimised;
  std::vector<geo::LatLon> best(m);
  for (std::size_t k = 0; k < m; ++k) best[k] = nodes[k].centre;
  if (m > 1 && any_circle) {
    // Coordinate descent finds a local optimum, and which one depends on the start (tasks that
    // touch one big cylinder several times have several): three starts, the shortest kept. At
    // the centres; each point on its circle nearest the one before; nearest the one after.
    std::vector<std::vector<geo::LatLon>> starts(3, best);
    for (std::size_t k = 1; k < m; ++k) starts[1][k] = toward(earth, nodes[k], starts[1][k - 1]);
    for (std::size_t k = m - 1; k-- > 0;) starts[2][k] = toward(earth, nodes[k], starts[2][k + 1]);
    double best_length = std::numeric_limits<double>::infinity();
    for (std::vector<geo::LatLon>& points : starts) {
      TaskRoute stats;
      const double length = descend(earth, nodes, points, options, stats);
      route.sweeps += stats.sweeps;
      if (length < best_length) {
        best_length = length;
        best = points;
        route.converged = stats.converged;
        route.last_move_m = stats.last_move_m;
      }
    }
  }
  route.points.resize(n);
  for (std::size_t i = 0; i < n; ++i) route.points[i] = best[node_of[i]];
  route.cumulative_m.assign(n, 0.0);
  for (std::size_t i = 1; i < n; ++i)
    route.cumulative_m[i] = route.cumulative_m[i - 1] + earth.distance_m(route.points[i - 1], route.points[i]);
  route.distance_m = route.cumulative_m.back();

  const int sss = task.sss_index(), ess = task.ess_index();
  if (sss >= 0 && ess > sss)
    out.speed_section_m =
        route.cumulative_m[static_cast<std::size_t>(ess)] - route.cumulative_m[static_cast<std::size_t>(sss)];
  return out;
}

}  // namespace trailray::track::task
