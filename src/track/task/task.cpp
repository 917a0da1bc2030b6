#include "track/task/task.hpp"

namespace trailray::track::task {

namespace {

int first_with(const Task& t, Role role) {
  for (std::size_t i = 0; i < t.turnpoints.size(); ++i)
    if (t.turnpoints[i].role == role) return static_cast<int>(i);
  return -1;
}

}  // namespace

int Task::sss_index() const { return first_with(*this, Role::Sss); }
int Task::goal_index() const { return first_with(*this, Role::Goal); }
int Task::ess_index() const {
  const int ess = first_with(*this, Role::Ess);
  return ess >= 0 ? ess : goal_index();
}

const char* role_name(Role role) {
  switch (role) {
    case Role::Takeoff:
      return "takeoff";
    case Role::Sss:
      return "SSS";
    case Role::Turnpoint:
      return "turnpoint";
    case Role::Ess:
      return "ESS";
    case Role::Goal:
      return "goal";
  }
  return "turnpoint";
}

const char* format_name(TaskFormat format) {
  switch (format) {
    case TaskFormat::XctskJson:
      return "XCTrack task (JSON)";
    case TaskFormat::XctskQr:
      return "XCTrack task (QR form, version 2)";
    case TaskFormat::IgcDeclaration:
      return "IGC task declaration (C records)";
    case TaskFormat::XcsoarTsk:
      return "XCSoar task (.tsk)";
  }
  return "task";
}

const char* earth_model_name(EarthModel model) { return model == EarthModel::FaiSphere ? "FAI sphere" : "WGS84"; }

}  // namespace trailray::track::task
