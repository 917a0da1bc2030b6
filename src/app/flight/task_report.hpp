#pragma once
// The output of `trailray task`: the task (turnpoints, radii, roles, distances through centres
// and optimised, the distance the file states when it states one) and, per flight, the
// turnpoints reached and when. One JSON document or a readable table.

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "track/task/task.hpp"
#include "track/task/task_distance.hpp"
#include "track/task/task_progress.hpp"

namespace trailray::app {

struct TaskFlightReport {
  std::string file;
  std::optional<std::string> error;  // the flight could not be read (or has no timed fix)
  track::task::TaskProgress progress;
  std::vector<std::string> notes;  // what looks wrong with the task's times for this flight
};

// Notes on a flight's result: a start gate or deadline that makes no sense for the flight's
// times (tasks written in local time marked "Z" are common).
std::vector<std::string> task_time_notes(const track::task::Task& task, const track::task::TaskProgress& p,
                                         double first_fix_time, double last_fix_time);

// The task's result for one file read: the progress of its timed fixes (all tracks, in order)
// and the notes on its times; an error when it has no timed fix. `tolerance`: fraction of a radius.
TaskFlightReport task_flight_report(const std::string& path, const track::TrackFile& file,
                                    const track::task::Task& task, const track::task::TaskDistances& d,
                                    double tolerance);

// One flight's result alone (as in task_json's "flights" and `trailray flight --task`).
nlohmann::json task_flight_json(const track::task::Task& task, const TaskFlightReport& flight);
std::string task_flight_text(const track::task::Task& task, const TaskFlightReport& flight);

nlohmann::json task_json(const std::string& file, const track::task::Task& task, const track::task::TaskDistances& d,
                         const std::vector<TaskFlightReport>& flights);
std::string task_table(const std::string& file, const track::task::Task& task, const track::task::TaskDistances& d,
                       const std::vector<TaskFlightReport>& flights);

}  // namespace trailray::app
