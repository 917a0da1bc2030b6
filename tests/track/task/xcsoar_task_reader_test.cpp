// XCSoar task files (.tsk): the real one of the corpus (XCSoar's test data), and written ones
// for the zones the model maps: a finish line is the goal line, other shapes cylinders with a
// warning naming the point, optional starts and points without a place left out saying so.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "test_support.hpp"
#include "track/task/task_reader.hpp"

namespace trailray::track::task {
namespace {

std::string point(const std::string& type, const std::string& name, double lat, double lon, const std::string& zone) {
  return "<Point type=\"" + type + "\"><Waypoint name=\"" + name + "\" altitude=\"500\"><Location latitude=\"" +
         std::to_string(lat) + "\" longitude=\"" + std::to_string(lon) + "\"/></Waypoint>" + zone + "</Point>\n";
}

bool warned(const TaskReadResult& r, const std::string& part) {
  for (const Diagnostic& d : r.warnings)
    if (d.message.find(part) != std::string::npos) return true;
  return false;
}

TEST(XcsoarTask, TheCorpusTaskOfXcsoarsTests) {
  TRAILRAY_REQUIRE_DATA(path, "corpus/tasks/xcsoar_apf-bug554.tsk");
  const TaskReadResult r = read_task_file(path.string());
  ASSERT_TRUE(r.task) << r.error->to_string();
  const Task& t = *r.task;
  EXPECT_EQ(t.format, TaskFormat::XcsoarTsk);
  ASSERT_EQ(t.turnpoints.size(), 5u);
  EXPECT_EQ(t.turnpoints[0].name, "Wanlo Niersq");
  EXPECT_EQ(t.turnpoints[0].role, Role::Sss);
  EXPECT_DOUBLE_EQ(t.turnpoints[0].lat, 51.1011);
  EXPECT_DOUBLE_EQ(t.turnpoints[0].lon, 6.39361);
  EXPECT_DOUBLE_EQ(t.turnpoints[0].altitude_m, 74.0);
  EXPECT_EQ(t.turnpoints[0].description, "121.175 0826");
  for (std::size_t i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(t.turnpoints[i].radius_m, 1000.0) << i;
  EXPECT_EQ(t.turnpoints[3].name, "APF001-2");
  EXPECT_EQ(t.turnpoints[4].role, Role::Goal);
  EXPECT_EQ(t.sss_index(), 0);
  EXPECT_EQ(t.goal_index(), 4);
  ASSERT_TRUE(t.sss.has_value());
  EXPECT_EQ(t.sss->direction, Direction::Exit);
  // The finish is an FAI sector: a cylinder of the default radius, and a warning naming it.
  EXPECT_DOUBLE_EQ(t.turnpoints[4].radius_m, kDefaultRadiusM);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].message.find("'Wanlo Niersq': observation zone 'FAISector'"), std::string::npos);
  EXPECT_EQ(r.warnings[0].position.line, 26);
}

TEST(XcsoarTask, FinishLineIsTheGoalLineOthersWarned) {
  const std::string text =
      "<?xml version=\"1.0\"?>\n<Task type=\"RT\">\n" +
      point("OptionalStart", "Alt", 47.0, 8.0, "<ObservationZone type=\"Cylinder\" radius=\"500\"/>") +
      point("Start", "S", 47.0, 8.1, "<ObservationZone type=\"Line\" length=\"2000\"/>") +
      "<Point type=\"Turn\"><Waypoint name=\"Lost\"/><ObservationZone type=\"Cylinder\" radius=\"500\"/></Point>\n" +
      point("Area", "A", 47.2, 8.2, "<ObservationZone type=\"Sector\" radius=\"20000\" start_radial=\"0\"/>") +
      point("Turn", "T", 47.3, 8.3, "<ObservationZone type=\"Cylinder\" radius=\"3000\"/>") +
      point("Finish", "F", 47.0, 8.1, "<ObservationZone type=\"Line\" length=\"1000\"/>") + "</Task>\n";
  const TaskReadResult r = read_task_text(text, "written.tsk");
  ASSERT_TRUE(r.task) << r.error->to_string();
  const Task& t = *r.task;
  ASSERT_EQ(t.turnpoints.size(), 4u);
  EXPECT_EQ(t.turnpoints[0].name, "S");
  EXPECT_DOUBLE_EQ(t.turnpoints[0].radius_m, 1000.0);  // half the start line
  EXPECT_DOUBLE_EQ(t.turnpoints[1].radius_m, 20000.0);
  EXPECT_DOUBLE_EQ(t.turnpoints[2].radius_m, 3000.0);
  EXPECT_EQ(t.goal_type, GoalType::Line);
  EXPECT_DOUBLE_EQ(t.turnpoints[3].radius_m, 500.0);
  EXPECT_TRUE(warned(r, "an optional start ('Alt') left out"));
  EXPECT_TRUE(warned(r, "'Lost' has no <Location>: left out"));
  EXPECT_TRUE(warned(r, "'S': a start line taken as a cylinder of half its length"));
  EXPECT_TRUE(warned(r, "'A': observation zone 'Sector' taken as a cylinder of 20000 m"));
  EXPECT_EQ(r.warnings.size(), 4u);
}

TEST(XcsoarTask, BadFilesAreErrorsNamingWhere) {
  const TaskReadResult cut = read_task_text("<Task>\n<Point type=\"Start\">\n<Waypoint name=\"x\">", "cut.tsk");
  ASSERT_TRUE(cut.error);
  EXPECT_EQ(cut.error->file, "cut.tsk");
  const TaskReadResult other = read_task_text("<gpx version=\"1.1\"></gpx>", "a.gpx");
  ASSERT_TRUE(other.error);
  EXPECT_NE(other.error->message.find("expected <Task>"), std::string::npos) << other.error->message;
  EXPECT_EQ(other.error->position.line, 1);
  const TaskReadResult one = read_task_text(
      "<Task>" + point("Start", "S", 47.0, 8.0, "<ObservationZone type=\"Cylinder\" radius=\"500\"/>") + "</Task>",
      "one.tsk");
  ASSERT_TRUE(one.error);
  EXPECT_NE(one.error->message.find("fewer than two"), std::string::npos);
  const TaskReadResult unreadable = read_task_text(
      "<Task>" + point("Start", "S", 95.0, 8.0, "") + point("Finish", "F", 47.0, 8.0, "") + "</Task>", "far.tsk");
  ASSERT_TRUE(unreadable.error);  // the start's latitude is out of range: one point left
  EXPECT_TRUE(warned(unreadable, "<Location> without a readable latitude and longitude"));
}

}  // namespace
}  // namespace trailray::track::task
