#pragma once
// A task's length, as XCTrack and XContest's task tool quote it:
//   - through centres: the sum of the legs between consecutive turnpoint centres;
//   - optimised: the shortest path that touches each turnpoint's circle in order (FAI CIVL S7F
//     "task distance"). It begins at the take-off's centre (a take-off is a place, not a
//     cylinder to reach: XContest counts the take-off to SSS leg from it), touches the boundary
//     of every other cylinder, an exit SSS included (the take-off is inside it: the route goes
//     out to its edge), and ends at the centre of a goal line (the line is perpendicular to the
//     last leg through that centre) or on the circle of a goal cylinder. Both sets of
//     conventions reproduce XContest's figures for the reference tasks (tests).
// The optimum is found by coordinate descent: each touch point in turn moves to the point of
// its circle that minimises the two legs to its neighbours (a one-dimensional search on the
// azimuth from the centre, with distances on the task's earth model: a scan, a golden-section
// search on the length, then bisection on the sign of its derivative), sweeping until no point
// moves by a millimetre. No step lengthens the route, but the result is a local optimum, so the
// descent runs from three starts and keeps the shortest (as pyxctsk does for the same reason).

#include <vector>

#include "geo/web_mercator.hpp"
#include "track/task/task.hpp"

namespace trailray::track::task {

struct TaskRoute {
  std::vector<geo::LatLon> points;   // one per turnpoint: where the route touches it
  std::vector<double> cumulative_m;  // along the route from the first point to each point
  double distance_m = 0.0;
  int sweeps = 0;            // of the optimisation, all starts together
  double last_move_m = 0.0;  // the largest move of a point in the last sweep
  bool converged = true;     // false: stopped at the sweep limit
};

struct TaskDistances {
  std::vector<double> centre_cumulative_m;  // through centres, to each turnpoint
  double centre_m = 0.0;
  TaskRoute optimised;
  // The speed section (SSS to ESS) along the optimised route; 0 without both.
  double speed_section_m = 0.0;
};

struct OptimiseOptions {
  double tolerance_m = 0.001;  // stop when no touch point moves further in a sweep
  int max_sweeps = 5000;
};

// True when the route passes through the turnpoint's centre rather than touching a circle:
// a take-off, a goal line, a radius of zero, a plain waypoint list.
bool is_route_point(const Task& task, std::size_t index);

TaskDistances measure_task(const Task& task, const OptimiseOptions& options = {});

}  // namespace trailray::track::task
