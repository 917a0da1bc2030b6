// XCSoar task files (.tsk, XML as XCSoar writes them): a <Task> of <Point type="Start|Turn|Area|
// Finish|OptionalStart"> each with a <Waypoint name=... altitude=...><Location latitude=...
// longitude=.../></Waypoint> and an <ObservationZone type=... radius=... length=.../>.
//
// The model's zones are cylinders and a goal line, so XCSoar's zones map as:
//   Cylinder, MatCylinder, Circle (radius)      -> a cylinder of that radius;
//   Line (length) at the finish                 -> the goal line, its half length the radius;
//   Line at the start                           -> a start cylinder of half the line's length (warned:
//                                                  the line's direction is not kept);
//   Sector, Keyhole, FAISector, BGA sectors, SymmetricQuadrant, AnnularSector: a cylinder of their
//                                                  radius (their kDefaultRadiusM without one), warned.
// OptionalStart points (alternative starts) are left out with a warning: a task has one start.
// The start is the SSS (exit), the finish the goal (ESS = goal), as XCSoar scores racing tasks.

#include <cmath>
#include <optional>
#include <string>

#include "track/io/byte_source.hpp"
#include "track/io/parse_util.hpp"
#include "track/io/xml_stream.hpp"
#include "track/task/task_reader.hpp"

namespace trailray::track::task {
namespace {

constexpr double kMaxRadiusM = 1.0e6;  // as the XCTrack reader: far beyond any zone

std::optional<double> number_attribute(const char** attrs, std::string_view name) {
  const char* v = xml_attribute(attrs, name);
  if (v == nullptr) return std::nullopt;
  const std::optional<double> x = parse_double(trim(v));
  if (!x || !std::isfinite(*x)) return std::nullopt;
  return x;
}

// A <Point> being read (outside the handler: clang wants a class with default member
// initialisers complete before an optional of it is emplaced inside another class).
struct PendingPoint {
  SourcePosition where;
  std::string type, zone;
  std::optional<double> radius, length;
  Turnpoint tp;
  bool located = false;
};

class XcsoarTaskHandler final : public XmlHandler {
 public:
  XcsoarTaskHandler(Task& task, WarningCollector& warnings) : task_(task), warnings_(warnings) {}

  void start_element(std::string_view name, const char** attrs) override {
    ++depth_;
    if (depth_ == 1) {
      if (name != "Task") fail("root element is <" + std::string(name.substr(0, 80)) + ">, expected <Task>");
      return;
    }
    if (name == "Point" && depth_ == 2) {
      point_.emplace();
      point_->where = position();
      const char* type = xml_attribute(attrs, "type");
      point_->type = type != nullptr ? type : "";
    } else if (point_ && name == "Waypoint") {
      const char* n = xml_attribute(attrs, "name");
      point_->tp.name = n != nullptr ? n : "";
      const char* comment = xml_attribute(attrs, "comment");
      point_->tp.description = comment != nullptr ? comment : "";
      if (auto alt = number_attribute(attrs, "altitude")) point_->tp.altitude_m = *alt;
    } else if (point_ && name == "Location") {
      const auto lat = number_attribute(attrs, "latitude"), lon = number_attribute(attrs, "longitude");
      if (lat && lon && std::abs(*lat) <= 90.0 && std::abs(*lon) <= 180.0) {
        point_->tp.lat = *lat;
        point_->tp.lon = *lon;
        point_->located = true;
      } else {
        warnings_.add("location", position(), "<Location> without a readable latitude and longitude");
      }
    } else if (point_ && name == "ObservationZone") {
      const char* type = xml_attribute(attrs, "type");
      point_->zone = type != nullptr ? type : "";
      point_->radius = number_attribute(attrs, "radius");
      point_->length = number_attribute(attrs, "length");
    }
  }

  void end_element(std::string_view name, std::string_view) override {
    if (name == "Point" && depth_ == 2 && point_) finish_point();
    --depth_;
  }

  bool had_start = false;

 private:
  void finish_point() {
    PendingPoint p = std::move(*point_);
    point_.reset();
    const std::string label = p.tp.name.empty() ? "a point" : "'" + p.tp.name + "'";
    if (!p.located) {
      warnings_.add("point", p.where, label + " has no <Location>: left out");
      return;
    }
    if (p.type == "OptionalStart") {
      warnings_.add("optional-start", p.where, "an optional start (" + label + ") left out: the task keeps one start");
      return;
    }
    if (p.type == "Start") {
      p.tp.role = Role::Sss;
      had_start = true;
    } else if (p.type == "Finish") {
      p.tp.role = Role::Goal;
    } else {
      if (p.type != "Turn" && p.type != "Area")
        warnings_.add("point-type", p.where, "point type '" + p.type + "' read as a turnpoint");
      p.tp.role = Role::Turnpoint;
    }
    const bool cylinder = p.zone == "Cylinder" || p.zone == "MatCylinder" || p.zone == "Circle";
    if (cylinder && p.radius) {
      p.tp.radius_m = *p.radius;
    } else if (p.zone == "Line" && p.length) {
      p.tp.radius_m = *p.length / 2.0;
      if (p.tp.role == Role::Goal)
        task_.goal_type = GoalType::Line;
      else
        warnings_.add("start-line", p.where, label + ": a start line taken as a cylinder of half its length");
    } else {
      p.tp.radius_m = p.radius.value_or(kDefaultRadiusM);
      warnings_.add("zone-shape", p.where,
                    label + ": observation zone '" + p.zone + "' taken as a cylinder of " +
                        std::to_string(static_cast<long>(std::lround(p.tp.radius_m))) + " m");
    }
    if (!(p.tp.radius_m > 0.0) || p.tp.radius_m > kMaxRadiusM) {
      warnings_.add("zone-radius", p.where, label + ": radius out of range, " + std::to_string(static_cast<int>(kDefaultRadiusM)) + " m taken");
      p.tp.radius_m = kDefaultRadiusM;
    }
    task_.turnpoints.push_back(std::move(p.tp));
  }

  Task& task_;
  WarningCollector& warnings_;
  int depth_ = 0;
  std::optional<PendingPoint> point_;
};

}  // namespace

TaskReadResult read_xcsoar_task(std::string_view text, const std::string& file) {
  TaskReadResult result;
  Task task;
  task.format = TaskFormat::XcsoarTsk;
  WarningCollector warnings(file);
  XcsoarTaskHandler handler(task, warnings);
  std::unique_ptr<ByteSource> source = ByteSource::from_memory(std::string(text), file);
  const XmlParseOutcome outcome = XmlStream::parse(*source, handler);
  result.warnings = warnings.diagnostics();
  if (outcome.kind != XmlParseOutcome::Kind::Complete) {
    result.error = Diagnostic{file, outcome.position,
                              outcome.kind == XmlParseOutcome::Kind::Truncated ? "the task file is cut short"
                                                                               : outcome.message};
    return result;
  }
  if (task.turnpoints.size() < 2) {
    result.error = Diagnostic{file, {}, "an XCSoar task with fewer than two usable points"};
    return result;
  }
  if (handler.had_start) task.sss = StartSection{};  // a race start, left by exiting its zone
  result.task = std::move(task);
  return result;
}

}  // namespace trailray::track::task
