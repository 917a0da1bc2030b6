#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <fstream>

#include "geo/geodesic.hpp"
#include "geo/local_frame.hpp"
#include "test_support.hpp"
#include "track/task/earth.hpp"
#include "track/task/task_distance.hpp"
#include "track/task/task_reader.hpp"

namespace trailray::track::task {
namespace {

Turnpoint tp(const std::string& name, double lat, double lon, double radius, Role role = Role::Turnpoint) {
  Turnpoint t;
  t.name = name;
  t.lat = lat;
  t.lon = lon;
  t.radius_m = radius;
  t.role = role;
  return t;
}

// Cylinders on one meridian: the shortest route runs along it and touches each circle where the
// meridian crosses it, so its length is the take-off to the last circle's near edge.
TEST(TaskDistance, CollinearCylindersOnAMeridian) {
  Task task;
  task.turnpoints = {tp("T", 46.0, 7.0, 0, Role::Takeoff), tp("S", 46.1, 7.0, 3000, Role::Sss),
                     tp("A", 46.3, 7.0, 5000), tp("B", 46.5, 7.0, 2000), tp("G", 46.8, 7.0, 1000, Role::Goal)};
  const TaskDistances d = measure_task(task);
  const double centres = geo::geodesic_distance_m(46.0, 7.0, 46.8, 7.0);
  EXPECT_NEAR(d.centre_m, centres, 1e-6);
  EXPECT_TRUE(d.optimised.converged);
  EXPECT_NEAR(d.optimised.distance_m, centres - 1000.0, 0.002);
  // Every touch point is on its circle, on the meridian.
  const Earth earth;
  for (std::size_t i = 1; i < task.turnpoints.size(); ++i) {
    const Turnpoint& t = task.turnpoints[i];
    EXPECT_NEAR(earth.distance_m({t.lat, t.lon}, d.optimised.points[i]), t.radius_m, 1e-3);
    EXPECT_NEAR(d.optimised.points[i].lon, 7.0, 1e-7);
  }
  // The SSS is touched where the meridian crosses its circle: 0.1 degree of latitude from the
  // take-off, less or more its radius (both crossings lie on the shortest route).
  const double to_sss = geo::geodesic_distance_m(46.0, 7.0, 46.1, 7.0);
  EXPECT_NEAR(std::abs(d.optimised.cumulative_m[1] - to_sss), 3000.0, 0.002);
}

// A right angle solved by hand, in a small local plane: take-off A at the origin, a cylinder of
// radius r at B = (D, 0), the goal point C = (D, D). The mirror through B along (-1, 1) swaps A
// and C, so the touch point is x = B + r (-1, 1) / sqrt 2 and the route 2 |A - x|.
TEST(TaskDistance, RightAngleSolvedByHand) {
  const double D = 10000.0, r = 3000.0;
  const geo::LocalFrame frame(0.5, 10.0, 0.0);
  const auto at = [&frame](double e, double n) {
    double lat = 0, lon = 0, h = 0;
    frame.to_geodetic({e, n, 0.0}, lat, lon, h);
    return geo::LatLon{lat, lon};
  };
  const geo::LatLon a = at(0, 0), b = at(D, 0), c = at(D, D);
  Task task;
  task.turnpoints = {tp("A", a.lat, a.lon, 0, Role::Takeoff), tp("B", b.lat, b.lon, r),
                     tp("C", c.lat, c.lon, 0, Role::Goal)};
  const TaskDistances d = measure_task(task);
  const double s = r / std::sqrt(2.0);
  const double expected = 2.0 * std::hypot(D - s, s);
  // The plane and the ellipsoid differ by centimetres over 10 km.
  EXPECT_NEAR(d.optimised.distance_m, expected, 0.2);
  const geo::Enu x = frame.to_local(d.optimised.points[1].lat, d.optimised.points[1].lon, 0.0);
  EXPECT_NEAR(x.east, D - s, 0.2);
  EXPECT_NEAR(x.north, s, 0.2);
  // A goal cylinder instead of a point: the route ends on its near edge, r shorter... only when
  // the last leg points at the centre, which holds when the goal is the last point.
  task.turnpoints[2].radius_m = 500.0;
  const TaskDistances e = measure_task(task);
  EXPECT_LT(e.optimised.distance_m, d.optimised.distance_m - 499.0);
}

// Nested cylinders around one centre: in at the outer edge, on to the inner edge, out to a
// bigger one and back: the route goes out to each circle (a cylinder is reached at its edge).
TEST(TaskDistance, NestedCylindersAroundOneCentre) {
  Task task;
  task.turnpoints = {tp("T", 0.0, 0.0, 0, Role::Takeoff), tp("A", 0.0, 0.1, 200), tp("B", 0.0, 0.1, 5000),
                     tp("C", 0.0, 0.1, 200, Role::Goal)};
  const TaskDistances d = measure_task(task);
  const double to_a = geo::geodesic_distance_m(0, 0, 0, 0.1) - 200.0;
  EXPECT_NEAR(d.optimised.distance_m, to_a + 2 * 4800.0, 0.01);
}

double reference_km(const nlohmann::json& doc, const char* key) { return doc["metadata"][key].get<double>(); }

// XContest's distances for the three reference tasks, to the 0.1 km they are quoted to: through
// centres (all legs, the take-off's included) and optimised (from the take-off's centre, the
// exit SSS touched on its edge, a goal line at its centre). One exception, measured: fobe's
// optimised route is 47.83 km on WGS84 where XContest says 47.4. Its route zigzags through
// gaps of about 4 km between cylinders of 13 to 14.7 km, so each leg moves by the full
// difference in how the 30 km between their centres is measured: on the FAI sphere (east-west
// 0.3 % shorter there) our optimum is 47.35 km, XContest's figure; its centre distance (218.2)
// is WGS84's. Our figure is the WGS84 optimum (three starts agree), so that task is held to
// 0.5 km and, on the sphere, to XContest's 0.1 km.
TEST(TaskDistance, MatchesXContestOnTheReferenceTasks) {
  struct Case {
    const char* name;
    double optimised_tolerance_km;
  };
  for (const Case& c :
       {Case{"pyxctsk_task_gibe", 0.05}, Case{"pyxctsk_task_fobe_line", 0.5}, Case{"pyxctsk_task_noha_route", 0.05}}) {
    const char* name = c.name;
    SCOPED_TRACE(name);
    TRAILRAY_REQUIRE_DATA(task_path, std::string("tasks/") + name + ".xctsk");
    TRAILRAY_REQUIRE_DATA(ref_path, std::string("tasks/") + name + ".reference.json");
    const TaskReadResult r = read_task_file(task_path.string());
    ASSERT_FALSE(r.error) << r.error->to_string();
    std::ifstream in(ref_path);
    const nlohmann::json ref = nlohmann::json::parse(in);
    const auto t0 = std::chrono::steady_clock::now();
    const TaskDistances d = measure_task(*r.task);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_TRUE(d.optimised.converged);
    std::printf("%s: centres %.4f km (XContest %.1f), optimised %.4f km (XContest %s), %d sweeps, %.1f ms\n", name,
                d.centre_m / 1000, reference_km(ref, "distance_through_centers_km"), d.optimised.distance_m / 1000,
                ref["metadata"].contains("distance_optimized_km")
                    ? std::to_string(reference_km(ref, "distance_optimized_km")).c_str()
                    : "-",
                d.optimised.sweeps, ms);
    EXPECT_NEAR(d.centre_m / 1000.0, reference_km(ref, "distance_through_centers_km"), 0.05 + 1e-9);
    if (ref["metadata"].contains("distance_optimized_km")) {
      EXPECT_NEAR(d.optimised.distance_m / 1000.0, reference_km(ref, "distance_optimized_km"),
                  c.optimised_tolerance_km + 1e-9);
    }
    // Per turnpoint, where XContest gives cumulative figures (the route waypoint list gives legs).
    const auto& rows = ref["turnpoints"];
    ASSERT_EQ(rows.size(), r.task->turnpoints.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
      if (!rows[i].contains("Optimized (km)")) continue;
      EXPECT_NEAR(d.optimised.cumulative_m[i] / 1000.0, rows[i]["Optimized (km)"].get<double>(),
                  c.optimised_tolerance_km + 1e-9)
          << i;
      EXPECT_NEAR(d.centre_cumulative_m[i] / 1000.0, rows[i]["Distance (km)"].get<double>(), 0.05 + 1e-9) << i;
    }
  }
}

TEST(TaskDistance, FobeOnTheFaiSphereIsXContestsFigure) {
  TRAILRAY_REQUIRE_DATA(task_path, "tasks/pyxctsk_task_fobe_line.xctsk");
  TaskReadResult r = read_task_file(task_path.string());
  ASSERT_FALSE(r.error) << r.error->to_string();
  r.task->earth = EarthModel::FaiSphere;
  const TaskDistances d = measure_task(*r.task);
  EXPECT_NEAR(d.optimised.distance_m / 1000.0, 47.4, 0.05);
  // The WGS84 optimum is longer, not a local optimum of a worse start: every start gives it.
  r.task->earth = EarthModel::Wgs84;
  EXPECT_GT(measure_task(*r.task).optimised.distance_m, d.optimised.distance_m + 400.0);
}

}  // namespace
}  // namespace trailray::track::task
