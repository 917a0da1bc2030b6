#pragma once
// Which turnpoints of a task a flight reached, and when: the task's result for one flight
// (`trailray task TASK TRACK`; meant for `trailray flight --task` too).
//
// Turnpoints are taken in order, each after the one before it was reached:
//   - the take-off: the flight's first fix (it is where the flight begins, not a place to reach);
//   - the SSS: a crossing of its circle in the task's direction (exit: from inside to outside),
//     at or after the first start gate; a later crossing before the next turnpoint is reached
//     replaces it (a restart), as in competition scoring; a race's start time is the last gate
//     at or before the crossing, an elapsed-time start's is the crossing itself;
//   - every other cylinder: the first crossing of its circle, in either direction (a flight
//     inside the cylinder when the previous turnpoint was reached must go out to its edge, as
//     the optimised route does for nested cylinders);
//   - a goal line: a crossing of the line (2 x radius long, perpendicular to the last leg of the
//     optimised route, through the goal's centre) from the side the route comes from.
// A crossing's time is interpolated between the two fixes around it (positions linear in
// latitude and longitude over the few seconds between fixes). Distances to a centre are on the
// task's earth model; `tolerance` widens each circle by that fraction for entries and narrows it
// for exits (CIVL GAP allows such a tolerance; 0 = the exact circle).

#include <cstddef>
#include <vector>

#include "track/model.hpp"
#include "track/task/task.hpp"
#include "track/task/task_distance.hpp"

namespace trailray::track::task {

struct TurnpointReach {
  bool reached = false;
  double time = kMissing;  // seconds since the epoch, UTC (interpolated)
  std::size_t fix = 0;     // the fix at or after the crossing
  double lat = 0.0, lon = 0.0;
  bool exit = false;  // reached by going out of the cylinder
};

struct TaskProgress {
  std::vector<TurnpointReach> turnpoints;  // one per turnpoint of the task
  int reached = 0;                         // how many, in order, from the first
  double start_time = kMissing;            // race: the gate; elapsed time: the SSS crossing
  double ess_time = kMissing;
  double speed_section_s = kMissing;  // ESS time minus start time
  double goal_time = kMissing;
  bool goal = false;
  bool goal_after_deadline = false;
  double day_start = kMissing;  // midnight UTC of the flight's first fix: the day of the task's times
  std::size_t fixes = 0;        // fixes with a time that were checked
};

struct ProgressOptions {
  double tolerance = 0.0;  // fraction of the radius (0.001: 0.1 %)
};

// The fixes of a file in order: every point with a time of every track's segments.
std::vector<TrackPoint> timed_fixes(const TrackFile& file);

TaskProgress task_progress(const Task& task, const TaskRoute& route, const std::vector<TrackPoint>& fixes,
                           const ProgressOptions& options = {});

}  // namespace trailray::track::task
