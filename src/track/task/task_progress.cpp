#include "track/task/task_progress.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "geo/local_frame.hpp"
#include "track/task/earth.hpp"

namespace trailray::track::task {

namespace {

struct Place {
  double lat = 0.0, lon = 0.0, time = 0.0;
  std::size_t fix = 0;  // the fix at or after this place
};

Place place_of(const std::vector<TrackPoint>& fixes, std::size_t i) {
  return {fixes[i].lat, fixes[i].lon, fixes[i].time, i};
}

Place between(const Place& a, const TrackPoint& b, std::size_t b_index, double f) {
  return {a.lat + f * (b.lat - a.lat), a.lon + f * (b.lon - a.lon), a.time + f * (b.time - a.time), b_index};
}

// Crossings of one circle along the flight.
struct CircleCrossing {
  const Earth& earth;
  geo::LatLon centre;
  double radius_m;
  double tolerance;

  double distance(double lat, double lon) const { return earth.distance_m(centre, {lat, lon}); }
  bool inside(const Place& p) const { return distance(p.lat, p.lon) <= radius_m; }

  // The first crossing after `from` (fixes from from.fix on): out of the circle when `exit`, into
  // it otherwise; nullopt when the flight never crosses so.
  std::optional<Place> next(const std::vector<TrackPoint>& fixes, const Place& from, bool exit) const {
    const double threshold = radius_m * (exit ? 1.0 - tolerance : 1.0 + tolerance);
    const auto crossed = [&](double d) { return exit ? d >= threshold : d <= threshold; };
    Place a = from;
    if (crossed(distance(a.lat, a.lon))) {
      // Already on the far side of the threshold (inside the tolerance band): reached here.
      return a;
    }
    for (std::size_t k = from.fix; k < fixes.size(); ++k) {
      const TrackPoint& b = fixes[k];
      if (crossed(distance(b.lat, b.lon))) {
        double lo = 0.0, hi = 1.0;  // the crossing lies between a (not crossed) and b (crossed)
        for (int it = 0; it < 40; ++it) {
          const double mid = 0.5 * (lo + hi);
          const Place m = between(a, b, k, mid);
          (crossed(distance(m.lat, m.lon)) ? hi : lo) = mid;
        }
        return between(a, b, k, hi);
      }
      a = place_of(fixes, k);
      a.fix = k + 1;
    }
    return std::nullopt;
  }
};

// A goal line: the first crossing from the side the last leg comes from.
std::optional<Place> goal_line_crossing(const std::vector<TrackPoint>& fixes, const Place& from,
                                        const geo::LatLon& centre, const geo::LatLon& incoming_from,
                                        double half_length_m) {
  const geo::LocalFrame frame(centre.lat, centre.lon, 0.0);
  const geo::Enu back = frame.to_local(incoming_from.lat, incoming_from.lon, 0.0);
  const double len = std::hypot(back.east, back.north);
  if (!(len > 0.0)) return std::nullopt;
  const double ve = -back.east / len, vn = -back.north / len;  // along the leg, towards the far side
  Place a = from;
  geo::Enu pa = frame.to_local(a.lat, a.lon, 0.0);
  for (std::size_t k = from.fix; k < fixes.size(); ++k) {
    const TrackPoint& b = fixes[k];
    const geo::Enu pb = frame.to_local(b.lat, b.lon, 0.0);
    const double sa = pa.east * ve + pa.north * vn, sb = pb.east * ve + pb.north * vn;
    if (sa < 0.0 && sb >= 0.0) {
      const double f = -sa / (sb - sa);
      const double qe = pa.east + f * (pb.east - pa.east), qn = pa.north + f * (pb.north - pa.north);
      if (std::abs(-qe * vn + qn * ve) <= half_length_m) return between(a, b, k, f);
    }
    a = place_of(fixes, k);
    a.fix = k + 1;
    pa = pb;
  }
  return std::nullopt;
}

// Where the route comes from into the goal: the last route point before it that is not its centre.
geo::LatLon incoming_point(const TaskRoute& route, const Earth& earth, std::size_t goal) {
  for (std::size_t i = goal; i-- > 0;)
    if (earth.distance_m(route.points[i], route.points[goal]) > 1.0) return route.points[i];
  return route.points[goal];
}

}  // namespace

std::vector<TrackPoint> timed_fixes(const TrackFile& file) {
  std::vector<TrackPoint> out;
  for (const Track& t : file.tracks)
    for (const Segment& s : t.segments)
      for (const TrackPoint& p : s.points)
        if (p.has_time() && std::isfinite(p.lat) && std::isfinite(p.lon)) out.push_back(p);
  return out;
}

TaskProgress task_progress(const Task& task, const TaskRoute& route, const std::vector<TrackPoint>& fixes,
                           const ProgressOptions& options) {
  TaskProgress out;
  const std::size_t n = task.turnpoints.size();
  out.turnpoints.resize(n);
  out.fixes = fixes.size();
  if (fixes.empty() || n == 0 || route.points.size() != n) return out;
  const Earth earth(task.earth);
  out.day_start = std::floor(fixes.front().time / 86400.0) * 86400.0;
  const int sss = task.sss_index(), ess = task.ess_index(), goal = task.goal_index();
  const double tolerance = std::clamp(options.tolerance, 0.0, 0.5);

  std::vector<double> gates;
  if (task.sss)
    for (double g : task.sss->gates_s) gates.push_back(out.day_start + g);
  std::sort(gates.begin(), gates.end());
  const auto valid_start = [&gates](double t) { return gates.empty() || t >= gates.front(); };

  // The next turnpoint `i` reached after `from`.
  const auto reach = [&](std::size_t i, const Place& from) -> std::optional<Place> {
    const Turnpoint& tp = task.turnpoints[i];
    if (static_cast<int>(i) == goal && task.goal_type == GoalType::Line)
      return goal_line_crossing(fixes, from, {tp.lat, tp.lon}, incoming_point(route, earth, i), tp.radius_m);
    const CircleCrossing circle{earth, {tp.lat, tp.lon}, tp.radius_m, tolerance};
    if (static_cast<int>(i) != sss) return circle.next(fixes, from, circle.inside(from));
    // The start: a crossing in the task's direction, at or after the first gate.
    const bool exit = !task.sss || task.sss->direction == Direction::Exit;
    Place at = from;
    for (;;) {
      if (circle.inside(at) != exit) {  // first get to the side the crossing starts from
        const auto back = circle.next(fixes, at, !exit);
        if (!back) return std::nullopt;
        at = *back;
        if (at.fix >= fixes.size()) return std::nullopt;
        at = place_of(fixes, at.fix), at.fix += 1;
        continue;
      }
      const auto c = circle.next(fixes, at, exit);
      if (!c) return std::nullopt;
      if (valid_start(c->time)) return c;
      if (c->fix >= fixes.size()) return std::nullopt;
      at = place_of(fixes, c->fix), at.fix += 1;
    }
  };

  Place at = place_of(fixes, 0);
  at.fix = 1;
  std::size_t i = 0;
  if (task.turnpoints.front().role == Role::Takeoff) {
    out.turnpoints[0] = {true, at.time, 0, at.lat, at.lon, false};
    i = 1;
  }
  for (; i < n; ++i) {
    std::optional<Place> p = reach(i, at);
    if (!p) break;
    if (static_cast<int>(i) == sss && i + 1 < n) {
      // A restart: a later valid crossing of the start before the next turnpoint replaces this one.
      for (int restarts = 0; restarts < 1000; ++restarts) {
        const std::optional<Place> next_tp = reach(i + 1, *p);
        // From the first fix after the crossing, not from the crossing itself: that lies on the
        // circle, inside or outside by the last bit of the distance (glibc and musl's sin/cos
        // decided it differently), and from "inside" the same crossing would be found again.
        if (p->fix >= fixes.size()) break;
        Place after = place_of(fixes, p->fix);
        after.fix = p->fix + 1;
        const std::optional<Place> again = reach(i, after);
        if (!again || (next_tp && again->time >= next_tp->time) || again->time <= p->time) break;
        p = again;
      }
    }
    const bool was_inside = earth.distance_m({task.turnpoints[i].lat, task.turnpoints[i].lon}, {at.lat, at.lon}) <=
                            task.turnpoints[i].radius_m;
    out.turnpoints[i] = {true, p->time, std::min(p->fix, fixes.size() - 1), p->lat, p->lon, was_inside};
    at = *p;
  }
  for (const TurnpointReach& r : out.turnpoints) {
    if (!r.reached) break;
    ++out.reached;
  }

  if (sss >= 0 && out.turnpoints[static_cast<std::size_t>(sss)].reached) {
    const double crossing = out.turnpoints[static_cast<std::size_t>(sss)].time;
    out.start_time = crossing;
    if (task.sss && task.sss->type == SssType::Race && !gates.empty()) {
      for (double g : gates)
        if (g <= crossing) out.start_time = g;
    }
  }
  if (ess >= 0 && out.turnpoints[static_cast<std::size_t>(ess)].reached) {
    out.ess_time = out.turnpoints[static_cast<std::size_t>(ess)].time;
    if (!std::isnan(out.start_time)) out.speed_section_s = out.ess_time - out.start_time;
  }
  if (goal >= 0 && out.turnpoints[static_cast<std::size_t>(goal)].reached) {
    out.goal = true;
    out.goal_time = out.turnpoints[static_cast<std::size_t>(goal)].time;
    out.goal_after_deadline = !std::isnan(task.deadline_s) && out.goal_time > out.day_start + task.deadline_s;
  }
  return out;
}

}  // namespace trailray::track::task
