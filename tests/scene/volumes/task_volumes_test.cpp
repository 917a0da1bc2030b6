// The task drawn in 3D: cylinders as volumes with rings at their radius, roles as categories and
// colours, the optimised route touching each cylinder, pins at the centres.

#include <gtest/gtest.h>

#include <cmath>

#include "geo/geodesic.hpp"
#include "scene/volumes/task_volumes.hpp"
#include "track/task/earth.hpp"

namespace trailray::scene {
namespace {

namespace tt = track::task;

tt::Turnpoint tp(const std::string& name, double lat, double lon, double radius, tt::Role role) {
  tt::Turnpoint t;
  t.name = name;
  t.lat = lat;
  t.lon = lon;
  t.radius_m = radius;
  t.role = role;
  return t;
}

tt::Task sample_task() {
  tt::Task task;
  task.turnpoints = {tp("TO", 46.60, 7.90, 400, tt::Role::Takeoff),   tp("SSS", 46.60, 7.90, 3000, tt::Role::Sss),
                     tp("A", 46.70, 8.05, 1000, tt::Role::Turnpoint), tp("B", 46.55, 8.20, 20000, tt::Role::Turnpoint),
                     tp("ESS", 46.50, 7.95, 2000, tt::Role::Ess),     tp("G", 46.49, 7.94, 200, tt::Role::Goal)};
  return task;
}

TEST(TaskVolumes, RingsAreAtTheRadiusWithRolesAndColours) {
  const tt::Task task = sample_task();
  const tt::TaskDistances d = tt::measure_task(task);
  const VolumeSet set = task_volumes(task, d, "t.xctsk", 2500.0);
  ASSERT_EQ(set.volumes.size(), task.turnpoints.size());
  const char* roles[] = {"takeoff", "SSS", "turnpoint", "turnpoint", "ESS", "goal"};
  for (std::size_t i = 0; i < set.volumes.size(); ++i) {
    const Volume& v = set.volumes[i];
    const tt::Turnpoint& t = task.turnpoints[i];
    EXPECT_EQ(v.kind, VolumeKind::TaskCylinder);
    EXPECT_EQ(v.category, roles[i]);
    EXPECT_EQ(v.source, "t.xctsk");
    const glm::vec3 c = task_role_color(t.role);
    EXPECT_EQ(v.color_srgb, c);
    EXPECT_EQ(v.floor.reference, VolumeHeightReference::Ground);
    EXPECT_EQ(v.floor.metres, 0.0);
    EXPECT_EQ(v.ceiling.reference, VolumeHeightReference::Msl);
    EXPECT_EQ(v.ceiling.metres, 2500.0);
    ASSERT_GE(v.boundary.size(), 96u);
    for (const geo::LatLon& p : v.boundary)
      EXPECT_NEAR(geo::geodesic_distance_m(t.lat, t.lon, p.lat, p.lon), t.radius_m, t.radius_m * 0.001);
    // Dense enough that a chord strays less than 2 m from the circle (or 96 points for small ones).
    const double chord =
        geo::geodesic_distance_m(v.boundary[0].lat, v.boundary[0].lon, v.boundary[1].lat, v.boundary[1].lon);
    const double sagitta = t.radius_m - std::sqrt(t.radius_m * t.radius_m - chord * chord / 4.0);
    EXPECT_LT(sagitta, 2.0 + 1e-6);
  }
  // Distinct colours per role.
  EXPECT_NE(task_role_color(tt::Role::Sss), task_role_color(tt::Role::Turnpoint));
  EXPECT_NE(task_role_color(tt::Role::Ess), task_role_color(tt::Role::Goal));
  // No flight: 1500 m above the ground.
  const VolumeSet ground = task_volumes(task, d, "t.xctsk", std::nan(""));
  EXPECT_EQ(ground.volumes[0].ceiling.reference, VolumeHeightReference::Ground);
  EXPECT_EQ(ground.volumes[0].ceiling.metres, 1500.0);
}

TEST(TaskVolumes, GoalLineIsAWallAcrossTheLastLeg) {
  tt::Task task;
  task.goal_type = tt::GoalType::Line;
  task.turnpoints = {tp("TO", 46.0, 7.0, 0, tt::Role::Takeoff), tp("G", 46.1, 7.0, 200, tt::Role::Goal)};
  const tt::TaskDistances d = tt::measure_task(task);
  const VolumeSet set = task_volumes(task, d, "t", 2000.0);
  ASSERT_EQ(set.volumes.size(), 1u);  // the take-off has no cylinder
  const auto& ring = set.volumes[0].boundary;
  ASSERT_EQ(ring.size(), 4u);
  // The leg runs north: the wall runs east-west, 400 m long, centred on the goal.
  const double length = geo::geodesic_distance_m(ring[0].lat, ring[0].lon, ring[1].lat, ring[1].lon);
  EXPECT_NEAR(length, 400.0, 0.5);
  EXPECT_NEAR(ring[0].lat, ring[1].lat, 1e-7);
  EXPECT_NEAR(0.5 * (ring[0].lon + ring[1].lon), 7.0, 1e-7);
}

TEST(TaskVolumes, RouteTouchesEachCylinderAndPinsSitAtTheCentres) {
  const tt::Task task = sample_task();
  const tt::TaskDistances d = tt::measure_task(task);
  const track::TrackFile file = task_route_file(task, d);
  ASSERT_EQ(file.routes.size(), 1u);
  const auto& points = file.routes[0].points;
  ASSERT_EQ(points.size(), task.turnpoints.size());  // no touch point repeats in this task
  const tt::Earth earth(task.earth);
  // The route starts at the take-off's centre and touches every other circle on its edge.
  EXPECT_NEAR(earth.distance_m({points[0].lat, points[0].lon}, {task.turnpoints[0].lat, task.turnpoints[0].lon}), 0.0,
              1e-6);
  for (std::size_t i = 1; i < points.size(); ++i) {
    const tt::Turnpoint& t = task.turnpoints[i];
    EXPECT_NEAR(earth.distance_m({points[i].lat, points[i].lon}, {t.lat, t.lon}), t.radius_m, 0.01) << i;
    EXPECT_FALSE(points[i].has_ele());  // on the ground
  }
  // One pin per turnpoint, except where one repeats the centre before it (TO and SSS here).
  ASSERT_EQ(file.waypoints.size(), task.turnpoints.size() - 1);
  EXPECT_EQ(file.waypoints[0].name, "TO");
  EXPECT_EQ(file.waypoints[1].name, "A");
  EXPECT_DOUBLE_EQ(file.waypoints[1].point.lat, 46.70);
  EXPECT_NE(file.waypoints[1].description.find("turnpoint"), std::string::npos);
  EXPECT_NE(file.routes[0].name.find("optimised"), std::string::npos);
}

}  // namespace
}  // namespace trailray::scene
