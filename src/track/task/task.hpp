#pragma once
// A competition or cross-country task: turnpoints with cylinders in the order they must be
// reached, the start (SSS) and its gates, the end of the speed section (ESS), the goal, the
// deadline and the earth model distances are measured on. Read from XCTrack task files (.xctsk
// JSON version 1, the version 2 form of its QR codes, with or without the "XCTSK:" prefix) and
// from IGC C-record declarations (task_reader.hpp). Times of day are seconds after midnight UTC
// (the formats give no date: a flight's day supplies it).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "track/diagnostics.hpp"
#include "track/model.hpp"

namespace trailray::track::task {

enum class Role { Takeoff, Sss, Turnpoint, Ess, Goal };
enum class SssType { Race, ElapsedTime };
enum class Direction { Enter, Exit };
enum class GoalType { Cylinder, Line };
enum class EarthModel { Wgs84, FaiSphere };
enum class TaskFormat { XctskJson, XctskQr, IgcDeclaration, XcsoarTsk };

// What the readers use where a format gives no radius (IGC C records, XCTrack waypoint lists):
// the 400 m cylinder of the FAI Sporting Code (Section 7D) for paragliding and hang-gliding
// badges and records, the same the `fai-cylinders` scoring rules use; a declaration names
// places, and 400 m is the observation zone those places are flown to.
inline constexpr double kDefaultRadiusM = 400.0;

struct Turnpoint {
  std::string name;
  std::string description;
  double lat = 0.0, lon = 0.0;  // degrees, WGS84
  double altitude_m = kMissing;
  double radius_m = kDefaultRadiusM;
  Role role = Role::Turnpoint;
};

struct StartSection {
  SssType type = SssType::Race;
  Direction direction = Direction::Exit;
  std::vector<double> gates_s;  // seconds of the day, UTC, in the file's order
};

struct Task {
  TaskFormat format = TaskFormat::XctskJson;
  // A plain waypoint list (XCTrack's "W" form): no start, no goal, radii not given.
  bool waypoints_only = false;
  std::vector<Turnpoint> turnpoints;
  std::optional<StartSection> sss;  // absent: no speed section stated
  GoalType goal_type = GoalType::Cylinder;
  double deadline_s = kMissing;  // seconds of the day, UTC
  EarthModel earth = EarthModel::Wgs84;
  bool earth_stated = false;  // false: the file names no earth model, WGS84 is assumed
  // A task distance the file states (none of the formats read today has one; kept for those
  // that do, and for the report's comparison).
  std::optional<double> stated_distance_m;

  // The index of the SSS turnpoint, of the ESS (the goal when none is marked) and of the goal
  // (-1: none).
  int sss_index() const;
  int ess_index() const;
  int goal_index() const;
};

struct TaskReadResult {
  std::optional<Task> task;  // absent exactly when `error` is set
  std::vector<Diagnostic> warnings;
  std::optional<Diagnostic> error;
};

// "takeoff", "SSS", "turnpoint", "ESS", "goal": the names the report and the scene use.
const char* role_name(Role role);
const char* format_name(TaskFormat format);
const char* earth_model_name(EarthModel model);

}  // namespace trailray::track::task
