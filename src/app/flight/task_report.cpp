#include "app/flight/task_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace trailray::app {

namespace tt = track::task;

namespace {

std::string clock(double seconds) {
  if (std::isnan(seconds)) return "-";
  const long long s = static_cast<long long>(std::llround(std::fmod(std::fmod(seconds, 86400.0) + 86400.0, 86400.0)));
  return fmt::format("{:02}:{:02}:{:02}", s / 3600 % 24, s / 60 % 60, s % 60);
}

std::string duration(double seconds) {
  if (std::isnan(seconds)) return "-";
  const long long s = std::llround(std::abs(seconds));
  return fmt::format("{}{}:{:02}:{:02}", seconds < 0 ? "-" : "", s / 3600, s / 60 % 60, s % 60);
}

nlohmann::json number_or_null(double v) { return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v); }
double km(double m) { return std::round(m) / 1000.0; }

// The name column: as wide as the longest name.
std::size_t name_width(const tt::Task& task) {
  std::size_t w = 4;
  for (const tt::Turnpoint& t : task.turnpoints) w = std::max(w, t.name.size());
  return w;
}

std::string start_text(const tt::Task& t) {
  if (!t.sss) return "no speed section";
  std::string gates;
  for (double g : t.sss->gates_s) gates += (gates.empty() ? "" : ", ") + clock(g) + "Z";
  return fmt::format("start {} {}{}", t.sss->type == tt::SssType::Race ? "race" : "elapsed time",
                     t.sss->direction == tt::Direction::Exit ? "exit" : "enter",
                     gates.empty() ? std::string() : ", gates " + gates);
}

}  // namespace

std::vector<std::string> task_time_notes(const tt::Task& task, const tt::TaskProgress& p, double first_fix_time,
                                         double last_fix_time) {
  std::vector<std::string> notes;
  if (std::isnan(p.day_start)) return notes;
  if (task.sss && !task.sss->gates_s.empty()) {
    const double gate = p.day_start + task.sss->gates_s.front();
    if (gate < first_fix_time - 3600.0)
      notes.push_back(
          fmt::format("the first start gate {}Z is more than an hour before the flight began ({}Z): the "
                      "task's times may be local time written as UTC",
                      clock(gate), clock(first_fix_time)));
  }
  if (!std::isnan(task.deadline_s) && p.day_start + task.deadline_s < first_fix_time)
    notes.push_back(fmt::format("the deadline {}Z is before the flight began ({}Z)", clock(task.deadline_s),
                                clock(first_fix_time)));
  (void)last_fix_time;
  return notes;
}

TaskFlightReport task_flight_report(const std::string& path, const track::TrackFile& file, const tt::Task& task,
                                    const tt::TaskDistances& d, double tolerance) {
  TaskFlightReport f;
  f.file = path;
  const std::vector<track::TrackPoint> fixes = tt::timed_fixes(file);
  if (fixes.empty()) {
    f.error = path + ": no point with a time";
    return f;
  }
  f.progress = tt::task_progress(task, d.optimised, fixes, {tolerance});
  f.notes = task_time_notes(task, f.progress, fixes.front().time, fixes.back().time);
  return f;
}

nlohmann::json task_flight_json(const tt::Task& task, const TaskFlightReport& f) {
  nlohmann::json j;
  j["file"] = f.file;
  if (f.error) {
    j["error"] = *f.error;
    return j;
  }
  const tt::TaskProgress& p = f.progress;
  nlohmann::json reached = nlohmann::json::array();
  for (std::size_t i = 0; i < p.turnpoints.size(); ++i) {
    const tt::TurnpointReach& r = p.turnpoints[i];
    if (!r.reached) break;
    reached.push_back({{"index", i},
                       {"name", task.turnpoints[i].name},
                       {"time", r.time},
                       {"clock", clock(r.time) + "Z"},
                       {"fix", r.fix},
                       {"lat", r.lat},
                       {"lon", r.lon},
                       {"by_exit", r.exit}});
  }
  j["reached"] = reached;
  j["reached_count"] = p.reached;
  j["goal"] = p.goal;
  j["goal_after_deadline"] = p.goal_after_deadline;
  j["start_time"] = number_or_null(p.start_time);
  j["ess_time"] = number_or_null(p.ess_time);
  j["speed_section_s"] = number_or_null(p.speed_section_s);
  j["notes"] = f.notes;
  return j;
}

nlohmann::json task_json(const std::string& file, const tt::Task& task, const tt::TaskDistances& d,
                         const std::vector<TaskFlightReport>& flights) {
  nlohmann::json doc;
  doc["file"] = file;
  doc["format"] = tt::format_name(task.format);
  doc["earth_model"] = tt::earth_model_name(task.earth);
  doc["earth_model_stated"] = task.earth_stated;
  nlohmann::json tps = nlohmann::json::array();
  for (std::size_t i = 0; i < task.turnpoints.size(); ++i) {
    const tt::Turnpoint& t = task.turnpoints[i];
    tps.push_back({{"name", t.name},
                   {"description", t.description},
                   {"role", tt::role_name(t.role)},
                   {"lat", t.lat},
                   {"lon", t.lon},
                   {"altitude_m", number_or_null(t.altitude_m)},
                   {"radius_m", t.radius_m},
                   {"centre_km", km(d.centre_cumulative_m[i])},
                   {"optimised_km", km(d.optimised.cumulative_m[i])},
                   {"touch", {{"lat", d.optimised.points[i].lat}, {"lon", d.optimised.points[i].lon}}}});
  }
  doc["turnpoints"] = tps;
  if (task.sss) {
    nlohmann::json gates = nlohmann::json::array();
    for (double g : task.sss->gates_s) gates.push_back(clock(g) + "Z");
    doc["sss"] = {{"type", task.sss->type == tt::SssType::Race ? "race" : "elapsed-time"},
                  {"direction", task.sss->direction == tt::Direction::Exit ? "exit" : "enter"},
                  {"gates", gates}};
  }
  doc["goal"] = {{"type", task.goal_type == tt::GoalType::Line ? "line" : "cylinder"},
                 {"deadline", std::isnan(task.deadline_s) ? nlohmann::json(nullptr)
                                                          : nlohmann::json(clock(task.deadline_s) + "Z")}};
  doc["centre_km"] = km(d.centre_m);
  doc["optimised_km"] = km(d.optimised.distance_m);
  doc["speed_section_km"] = km(d.speed_section_m);
  doc["optimisation"] = {{"sweeps", d.optimised.sweeps}, {"converged", d.optimised.converged}};
  if (task.stated_distance_m) {
    doc["stated_km"] = km(*task.stated_distance_m);
    doc["optimised_minus_stated_km"] = km(d.optimised.distance_m - *task.stated_distance_m);
  } else {
    doc["stated_km"] = nullptr;
  }
  nlohmann::json fl = nlohmann::json::array();
  for (const TaskFlightReport& f : flights) fl.push_back(task_flight_json(task, f));
  doc["flights"] = fl;
  return doc;
}

std::string task_flight_text(const tt::Task& task, const TaskFlightReport& f) {
  if (f.error) return fmt::format("{}: {}\n", f.file, *f.error);
  std::string out;
  const std::size_t w = name_width(task);
  const tt::TaskProgress& p = f.progress;
  out += fmt::format("{}: {} of {} turnpoints, {}\n", f.file, p.reached, task.turnpoints.size(),
                     p.goal ? (p.goal_after_deadline ? "goal made after the deadline" : "goal made") : "no goal");
  for (std::size_t i = 0; i < p.turnpoints.size(); ++i) {
    const tt::TurnpointReach& r = p.turnpoints[i];
    out += fmt::format("{:>3}  {:<{}} {:<9} {}\n", i + 1, task.turnpoints[i].name, w,
                       tt::role_name(task.turnpoints[i].role),
                       r.reached ? clock(r.time) + "Z" + (r.exit ? " (out)" : "") : "not reached");
  }
  if (!std::isnan(p.start_time))
    out += fmt::format("start {}Z, ESS {}, speed section {}\n", clock(p.start_time),
                       std::isnan(p.ess_time) ? std::string("not reached") : clock(p.ess_time) + "Z",
                       duration(p.speed_section_s));
  for (const std::string& n : f.notes) out += "note: " + n + "\n";
  return out;
}

std::string task_table(const std::string& file, const tt::Task& task, const tt::TaskDistances& d,
                       const std::vector<TaskFlightReport>& flights) {
  std::string out = fmt::format("{}: {}, {} turnpoints, {}{}\n", file, tt::format_name(task.format),
                                task.turnpoints.size(), tt::earth_model_name(task.earth),
                                task.earth_stated ? "" : " (assumed: the file names no earth model)");
  out += fmt::format("{}; goal {}{}\n", start_text(task), task.goal_type == tt::GoalType::Line ? "line" : "cylinder",
                     std::isnan(task.deadline_s) ? std::string() : ", deadline " + clock(task.deadline_s) + "Z");
  const std::size_t w = name_width(task);
  out += fmt::format("{:>3}  {:<{}} {:<9} {:>9}  {:>10}  {:>12}  {}\n", "#", "name", w, "role", "radius", "centres km",
                     "optimised km", "description");
  for (std::size_t i = 0; i < task.turnpoints.size(); ++i) {
    const tt::Turnpoint& t = task.turnpoints[i];
    out += fmt::format("{:>3}  {:<{}} {:<9} {:>7.0f} m  {:>10.2f}  {:>12.2f}  {}\n", i + 1, t.name, w,
                       tt::role_name(t.role), t.radius_m, d.centre_cumulative_m[i] / 1000.0,
                       d.optimised.cumulative_m[i] / 1000.0, t.description);
  }
  out += fmt::format("distance: {:.2f} km through centres, {:.2f} km optimised", d.centre_m / 1000.0,
                     d.optimised.distance_m / 1000.0);
  if (d.speed_section_m > 0.0) out += fmt::format(" (speed section {:.2f} km)", d.speed_section_m / 1000.0);
  if (task.stated_distance_m)
    out += fmt::format("; the file states {:.2f} km (optimised {:+.2f} km)", *task.stated_distance_m / 1000.0,
                       (d.optimised.distance_m - *task.stated_distance_m) / 1000.0);
  else
    out += "; the file states no distance";
  out += '\n';
  for (const TaskFlightReport& f : flights) out += '\n' + task_flight_text(task, f);
  return out;
}

}  // namespace trailray::app
