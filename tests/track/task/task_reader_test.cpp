#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "test_support.hpp"
#include "track/task/task_reader.hpp"

namespace trailray::track::task {
namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(TaskReader, ReadsVersion1WithRolesGatesAndGoal) {
  const std::string text = R"({"version":1,"taskType":"CLASSIC","earthModel":"FAI_SPHERE",
    "turnpoints":[
      {"radius":400,"type":"TAKEOFF","waypoint":{"name":"TO","lat":46.5,"lon":7.5,"altSmoothed":1500}},
      {"radius":2000,"type":"SSS","waypoint":{"name":"S","lat":46.51,"lon":7.5}},
      {"radius":1000,"waypoint":{"name":"A","lat":46.6,"lon":7.6,"description":"Alp"}},
      {"radius":1000,"type":"ESS","waypoint":{"name":"E","lat":46.7,"lon":7.6}},
      {"radius":200,"waypoint":{"name":"G","lat":46.71,"lon":7.6}}],
    "sss":{"type":"ELAPSED-TIME","direction":"ENTER","timeGates":["10:00:00Z","10:30:00Z"]},
    "goal":{"type":"LINE","deadline":"17:15:00Z"}})";
  const TaskReadResult r = read_task_text(text, "t.xctsk");
  ASSERT_FALSE(r.error) << r.error->to_string();
  const Task& t = *r.task;
  ASSERT_EQ(t.turnpoints.size(), 5u);
  EXPECT_EQ(t.turnpoints[0].role, Role::Takeoff);
  EXPECT_EQ(t.turnpoints[1].role, Role::Sss);
  EXPECT_EQ(t.turnpoints[2].role, Role::Turnpoint);
  EXPECT_EQ(t.turnpoints[3].role, Role::Ess);
  EXPECT_EQ(t.turnpoints[4].role, Role::Goal);
  EXPECT_EQ(t.turnpoints[2].description, "Alp");
  EXPECT_DOUBLE_EQ(t.turnpoints[0].altitude_m, 1500.0);
  EXPECT_TRUE(std::isnan(t.turnpoints[1].altitude_m));
  EXPECT_EQ(t.earth, EarthModel::FaiSphere);
  ASSERT_TRUE(t.sss);
  EXPECT_EQ(t.sss->type, SssType::ElapsedTime);
  EXPECT_EQ(t.sss->direction, Direction::Enter);
  EXPECT_EQ(t.sss->gates_s, (std::vector<double>{36000.0, 37800.0}));
  EXPECT_EQ(t.goal_type, GoalType::Line);
  EXPECT_DOUBLE_EQ(t.deadline_s, 17 * 3600.0 + 15 * 60.0);
  EXPECT_EQ(t.sss_index(), 1);
  EXPECT_EQ(t.ess_index(), 3);
  EXPECT_EQ(t.goal_index(), 4);
}

TEST(TaskReader, ErrorsNameTheJsonPathOrLineAndColumn) {
  TaskReadResult r = read_task_text(R"({"turnpoints":[{"radius":400,"waypoint":{"lat":"x","lon":7}}]})", "a.xctsk");
  ASSERT_TRUE(r.error);
  EXPECT_EQ(r.error->to_string(), "a.xctsk: turnpoints[0].waypoint.lat: expected a number");
  r = read_task_text(R"({"turnpoints":[{"radius":400,"waypoint":{"lat":95,"lon":7}}]})", "a.xctsk");
  ASSERT_TRUE(r.error);
  EXPECT_NE(r.error->message.find("latitude out of range"), std::string::npos);
  r = read_task_text("{\"turnpoints\": [\n  {\"radius\": 400,,}\n]}", "b.xctsk");
  ASSERT_TRUE(r.error);
  EXPECT_EQ(r.error->position.line, 2);
  EXPECT_GT(r.error->position.column, 1);
  EXPECT_NE(r.error->message.find("invalid JSON"), std::string::npos);
  r = read_task_text(R"({"sss":{"timeGates":["25:99"]},"turnpoints":[{"radius":1,"waypoint":{"lat":1,"lon":2}}]})",
                     "c.xctsk");
  ASSERT_TRUE(r.error);
  EXPECT_NE(r.error->message.find("sss.timeGates[0]"), std::string::npos);
  r = read_task_text("hello", "d.txt");
  ASSERT_TRUE(r.error);
  EXPECT_FALSE(r.task);
}

TEST(TaskReader, DecodesPolylineValues) {
  // Google's example: -179.9832104 -> "`~oia@" at 1e5 precision.
  const auto v = decode_polyline_values("`~oia@");
  ASSERT_TRUE(v);
  ASSERT_EQ(v->size(), 1u);
  EXPECT_EQ((*v)[0], -17998321);
  EXPECT_FALSE(decode_polyline_values("_"));  // a continuation without its end
}

TEST(TaskReader, IgcDeclarationRolesDefaultRadiusAndPlaceholders) {
  const std::string igc =
      "AXXX\r\nC150701120000150701000102Task\r\nC0000000N00000000ETAKEOFF\r\n"
      "C4630000N00730000ESTART A\r\nC4631500S00731000WTURN B\r\nC4632000N00732000ETURN C\r\n"
      "C4630000N00730000EFINISH A\r\nC0000000N00000000ELANDING\r\nB1200004630000N00730000EA0100001000\r\n";
  const TaskReadResult r = read_task_text(igc, "x.igc");
  ASSERT_FALSE(r.error) << r.error->to_string();
  const Task& t = *r.task;
  ASSERT_EQ(t.turnpoints.size(), 4u);  // the take-off and landing placeholders are left out
  EXPECT_EQ(t.turnpoints[0].role, Role::Sss);
  EXPECT_EQ(t.turnpoints[0].name, "START A");
  EXPECT_DOUBLE_EQ(t.turnpoints[0].lat, 46.5);
  EXPECT_DOUBLE_EQ(t.turnpoints[1].lat, -46.525);
  EXPECT_DOUBLE_EQ(t.turnpoints[1].lon, -7.516666666666667);
  EXPECT_EQ(t.turnpoints[3].role, Role::Goal);
  for (const Turnpoint& tp : t.turnpoints) EXPECT_DOUBLE_EQ(tp.radius_m, kDefaultRadiusM);
  EXPECT_TRUE(r.warnings.empty());

  const TaskReadResult bad = read_task_text("AXXX\nC150701120000150701000102\nC46300X0N00730000EA\n", "y.igc");
  ASSERT_TRUE(bad.error);
  EXPECT_EQ(bad.error->position.line, 3);
  EXPECT_EQ(bad.error->to_string().rfind("y.igc:3:", 0), 0u);
}

TEST(TaskReader, RealXcsoarDeclaration) {
  TRAILRAY_REQUIRE_DATA(path, "tasks/xcsoar_01lz1hq1.igc");
  const TaskReadResult r = read_task_file(path.string());
  ASSERT_FALSE(r.error) << r.error->to_string();
  const Task& t = *r.task;
  // Take-off, start, 5 turnpoints, finish (the landing is not part of the task).
  ASSERT_EQ(t.turnpoints.size(), 8u);
  EXPECT_EQ(t.turnpoints[0].role, Role::Takeoff);
  EXPECT_EQ(t.turnpoints[1].role, Role::Sss);
  EXPECT_EQ(t.turnpoints[2].name, "LOCKHART SIL");
  EXPECT_EQ(t.turnpoints[7].role, Role::Goal);
  EXPECT_NEAR(t.turnpoints[2].lat, -(35 + 13.650 / 60), 1e-9);
  EXPECT_NEAR(t.turnpoints[2].lon, 146 + 43.183 / 60, 1e-9);
}

// The QR text of each reference task holds the same task as its .xctsk, to the polyline's
// 1e-5 degree (about a metre).
TEST(TaskReader, QrStringsMatchTheirXctskFiles) {
  for (const char* name : {"pyxctsk_task_gibe", "pyxctsk_task_fobe_line", "pyxctsk_task_noha_route"}) {
    SCOPED_TRACE(name);
    TRAILRAY_REQUIRE_DATA(json_path, std::string("tasks/") + name + ".xctsk");
    TRAILRAY_REQUIRE_DATA(qr_path, std::string("tasks/") + name + ".qr.txt");
    const TaskReadResult a = read_task_file(json_path.string());
    const TaskReadResult b = read_task_text(slurp(qr_path), qr_path.string());
    ASSERT_FALSE(a.error) << a.error->to_string();
    ASSERT_FALSE(b.error) << b.error->to_string();
    EXPECT_EQ(b.task->format, TaskFormat::XctskQr);
    ASSERT_EQ(a.task->turnpoints.size(), b.task->turnpoints.size());
    for (std::size_t i = 0; i < a.task->turnpoints.size(); ++i) {
      const Turnpoint &x = a.task->turnpoints[i], &y = b.task->turnpoints[i];
      EXPECT_EQ(x.name, y.name);
      EXPECT_EQ(x.role, y.role) << i;
      EXPECT_NEAR(x.lat, y.lat, 1e-5);
      EXPECT_NEAR(x.lon, y.lon, 1e-5);
      EXPECT_DOUBLE_EQ(x.radius_m, y.radius_m);
      if (!std::isnan(x.altitude_m)) {
        EXPECT_DOUBLE_EQ(x.altitude_m, y.altitude_m);
      }
    }
    EXPECT_EQ(a.task->goal_type, b.task->goal_type);
    EXPECT_EQ(a.task->sss.has_value(), b.task->sss.has_value());
    if (a.task->sss && b.task->sss) {
      EXPECT_EQ(a.task->sss->gates_s, b.task->sss->gates_s);
    }
    if (!std::isnan(a.task->deadline_s)) {
      EXPECT_DOUBLE_EQ(a.task->deadline_s, b.task->deadline_s);
    }
  }
}

TEST(TaskReader, IgclibTaskWithoutEarthModel) {
  TRAILRAY_REQUIRE_DATA(path, "tasks/igclib_xctrack_1.xctsk");
  const TaskReadResult r = read_task_file(path.string());
  ASSERT_FALSE(r.error) << r.error->to_string();
  EXPECT_FALSE(r.task->earth_stated);
  EXPECT_EQ(r.task->earth, EarthModel::Wgs84);
  EXPECT_EQ(r.task->goal_type, GoalType::Line);
  EXPECT_EQ(r.task->turnpoints.size(), 9u);
  EXPECT_EQ(r.task->ess_index(), 7);
  EXPECT_EQ(r.task->goal_index(), 8);
}

}  // namespace
}  // namespace trailray::track::task
