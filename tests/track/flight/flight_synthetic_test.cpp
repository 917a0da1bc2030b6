// Flight analysis on simulated flights whose thermals, glides and wind are known.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "synthetic_flight.hpp"
#include "track/flight/flight_analysis.hpp"

namespace fl = trailray::track::flight;
using trailray::track::test::SyntheticFlight;

namespace {

double angle_diff(double a, double b) {
  double d = std::fmod(std::fabs(a - b), 360.0);
  return d > 180.0 ? 360.0 - d : d;
}

// Phases tile the flight: in order, each starting where the one before ended, from take-off to landing.
void expect_tiling(const fl::Flight& f) {
  ASSERT_FALSE(f.phases.empty());
  EXPECT_EQ(f.phases.front().start.time, f.takeoff.time);
  EXPECT_EQ(f.phases.back().end.time, f.landing.time);
  double sum = 0;
  for (std::size_t k = 0; k < f.phases.size(); ++k) {
    EXPECT_GT(f.phases[k].duration_s(), 0.0);
    if (k > 0) {
      EXPECT_EQ(f.phases[k].start.point, f.phases[k - 1].end.point);
      EXPECT_NE(f.phases[k].phase, f.phases[k - 1].phase);
    }
    sum += f.phases[k].duration_s();
  }
  EXPECT_DOUBLE_EQ(sum, f.duration_s);
  EXPECT_NEAR(f.circling_s + f.gliding_s + f.unknown_s, f.duration_s, 1e-6);
}

}  // namespace

// Two thermals (right then left) in a 4 m/s wind from 250 degrees, glides between.
TEST(FlightSynthetic, ThermalsClimbAndWindComeOutRight) {
  SyntheticFlight sim(4.0, 250.0);
  sim.ground(120);
  const double takeoff = sim.time();
  sim.glide(120, 0.0);
  const double t1 = sim.time();
  sim.circle(180, true, 2.0);  // 40 m radius at 10 m/s: 25 s a turn, 7.2 turns
  sim.glide(300, 90.0, 10.0, 1.5);
  const double t2 = sim.time();
  sim.circle(150, false, 1.5, 50.0, 11.0);
  sim.glide(200, 330.0);  // a turn of 30 degrees on from where the circles ended (north)
  const double landing = sim.time();
  sim.ground(120);

  const fl::FlightAnalysis a = fl::analyse_flights(sim.track());
  ASSERT_EQ(a.flights.size(), 1u);
  const fl::Flight& f = a.flights[0];
  EXPECT_NEAR(f.takeoff.time, takeoff, 6.0);
  EXPECT_NEAR(f.landing.time, landing, 6.0);
  expect_tiling(f);
  ASSERT_EQ(f.thermals.size(), 2u);
  const fl::Thermal& r = f.thermals[0];
  const fl::Thermal& l = f.thermals[1];
  EXPECT_EQ(r.direction, fl::Phase::CirclingRight);
  EXPECT_EQ(l.direction, fl::Phase::CirclingLeft);
  // Edges blur by a few seconds of the glides around (the turn-rate window).
  EXPECT_NEAR(r.start.time, t1, 5.0);
  EXPECT_NEAR(r.duration_s, 180.0, 10.0);
  EXPECT_NEAR(l.start.time, t2, 5.0);
  EXPECT_NEAR(l.duration_s, 150.0, 10.0);
  EXPECT_NEAR(r.mean_climb_ms, 2.0, 0.15);
  EXPECT_NEAR(l.mean_climb_ms, 1.5, 0.15);
  EXPECT_NEAR(r.best_climb_ms, 2.0, 0.05);  // steady climb: the best 20 s equal it
  EXPECT_NEAR(r.turns, 7.2, 0.5);
  for (const fl::Thermal* t : {&r, &l}) {
    EXPECT_TRUE(t->wind_from_centres);
    EXPECT_NEAR(t->wind_speed_ms, 4.0, 0.2);
    EXPECT_LT(angle_diff(t->wind_from_deg, 250.0), 3.0);
    EXPECT_LT(angle_diff(t->drift_to_deg, 70.0), 3.0);
    EXPECT_NEAR(t->drift_m, 4.0 * t->duration_s, 0.05 * 4.0 * t->duration_s);
  }
  ASSERT_EQ(f.wind.size(), 2u);  // thermal 1 from 880 to 1240 m, thermal 2 from 790 to 1015 m
  for (const fl::WindBand& b : f.wind) {
    EXPECT_NEAR(b.speed_ms, 4.0, 0.2);
    EXPECT_LT(angle_diff(b.from_deg, 250.0), 3.0);
    EXPECT_EQ(b.ceiling_m - b.floor_m, 500.0);
  }
  EXPECT_NEAR(f.mean_thermal_climb_ms, (2.0 * 180 + 1.5 * 150) / 330.0, 0.15);
  EXPECT_NEAR(f.circling_share, 330.0 / (landing - takeoff), 0.03);
  EXPECT_NEAR(f.wind[0].floor_m, 500.0, 1e-9);
  EXPECT_NEAR(f.max_alt_m, 1240.0, 3.0);
  EXPECT_NEAR(f.min_alt_m, 790.0, 3.0);  // the ground is at 1000 m: the flight starts there
  // The glide between the thermals: 10 m/s east in the air plus the wind, sinking 1.5 m/s.
  ASSERT_EQ(f.glides.size(), 3u);
  const double ve = 10.0 + 4.0 * std::sin(70.0 * std::numbers::pi / 180),
               vn = 4.0 * std::cos(70.0 * std::numbers::pi / 180);
  const fl::Glide& g = f.glides[1];
  EXPECT_NEAR(g.mean_speed_ms, std::hypot(ve, vn), 0.4);
  EXPECT_NEAR(g.glide_ratio, std::hypot(ve, vn) / 1.5, 0.06 * std::hypot(ve, vn) / 1.5);
  EXPECT_NEAR(g.height_lost_m, 450.0, 25.0);
  EXPECT_EQ(f.longest_glide, 1);
  EXPECT_EQ(f.best_glide, 1);  // the only glide of at least 2 km
}

// Straight glides in still air: the glide ratio is airspeed / sink; the best glide is the best
// ratio among glides of 2 km or more, not the longest one.
TEST(FlightSynthetic, GlideRatioOfStraightGlides) {
  SyntheticFlight sim;
  sim.ground(60);
  sim.glide(400, 30.0, 10.0, 1.25);  // 4 km at L/D 8
  sim.circle(120, true, 2.5);
  sim.glide(300, 120.0, 12.0, 1.0);  // 3.6 km at L/D 12
  sim.circle(120, false, 2.5);
  sim.glide(100, 200.0, 10.0, 0.5);  // 1 km at L/D 20: too short to be the best glide
  sim.ground(60);
  const fl::FlightAnalysis a = fl::analyse_flights(sim.track());
  ASSERT_EQ(a.flights.size(), 1u);
  const fl::Flight& f = a.flights[0];
  expect_tiling(f);
  ASSERT_EQ(f.glides.size(), 3u);
  ASSERT_EQ(f.thermals.size(), 2u);
  EXPECT_NEAR(f.glides[0].glide_ratio, 8.0, 0.4);
  EXPECT_NEAR(f.glides[0].distance_m, 4000.0, 100.0);
  EXPECT_NEAR(f.glides[0].mean_speed_ms, 10.0, 0.3);
  EXPECT_NEAR(f.glides[1].glide_ratio, 12.0, 0.8);
  EXPECT_NEAR(f.glides[1].mean_speed_ms, 12.0, 0.4);
  EXPECT_NEAR(f.glides[2].glide_ratio, 20.0, 2.0);
  EXPECT_EQ(f.best_glide, 1);
  EXPECT_EQ(f.longest_glide, 0);
  for (const fl::Thermal& t : f.thermals) EXPECT_LT(t.wind_speed_ms, 0.2);  // still air: no drift
}

// A glide that climbs has no glide ratio (NaN), not a negative or infinite one.
TEST(FlightSynthetic, ClimbingGlideHasNoRatio) {
  SyntheticFlight sim;
  sim.ground(60);
  sim.glide(200, 0.0, 10.0, 1.0);
  sim.glide(200, 0.0, 10.0, -0.8);  // ridge lift: straight and climbing
  sim.glide(100, 0.0, 10.0, 1.0);
  sim.ground(60);
  const fl::FlightAnalysis a = fl::analyse_flights(sim.track());
  ASSERT_EQ(a.flights.size(), 1u);
  ASSERT_EQ(a.flights[0].glides.size(), 1u);
  const fl::Glide& g = a.flights[0].glides[0];
  EXPECT_NEAR(g.height_lost_m, 200 - 160 + 100, 3.0);
  EXPECT_GT(g.glide_ratio, 0.0);
  // Now only the climbing part as its own flight's glide.
  SyntheticFlight up;
  up.ground(60);
  up.glide(90, 0.0, 10.0, 1.5);
  up.glide(300, 0.0, 10.0, -1.0);
  up.ground(60);
  const fl::FlightAnalysis b = fl::analyse_flights(up.track());
  ASSERT_EQ(b.flights.size(), 1u);
  ASSERT_EQ(b.flights[0].glides.size(), 1u);
  EXPECT_LT(b.flights[0].glides[0].height_lost_m, 0.0);
  EXPECT_TRUE(std::isnan(b.flights[0].glides[0].glide_ratio));
  EXPECT_EQ(b.flights[0].best_glide, -1);
}

// Ground time before, between and after: two flights, and the ground between is in neither.
TEST(FlightSynthetic, TwoFlightsWithGroundTimeBetween) {
  SyntheticFlight sim(3.0, 180.0);
  sim.ground(300);
  const double takeoff1 = sim.time();
  sim.glide(120, 0.0);
  sim.circle(120, true, 2.0);
  sim.glide(200, 90.0);
  const double landing1 = sim.time();
  sim.ground(900);
  const double takeoff2 = sim.time();
  sim.glide(100, 270.0, 10.0, 1.5);
  sim.circle(200, false, 1.0);
  sim.glide(150, 180.0);
  const double landing2 = sim.time();
  sim.ground(300);
  const fl::FlightAnalysis a = fl::analyse_flights(sim.track());
  ASSERT_EQ(a.flights.size(), 2u);
  EXPECT_NEAR(a.flights[0].takeoff.time, takeoff1, 6.0);
  EXPECT_NEAR(a.flights[0].landing.time, landing1, 6.0);
  EXPECT_NEAR(a.flights[1].takeoff.time, takeoff2, 6.0);
  EXPECT_NEAR(a.flights[1].landing.time, landing2, 6.0);
  EXPECT_NEAR(a.flights[0].duration_s + a.flights[1].duration_s, (landing1 - takeoff1) + (landing2 - takeoff2), 12.0);
  for (const fl::Flight& f : a.flights) {
    expect_tiling(f);
    ASSERT_EQ(f.thermals.size(), 1u);
    EXPECT_NEAR(f.thermals[0].wind_speed_ms, 3.0, 0.2);
    EXPECT_LT(angle_diff(f.thermals[0].wind_from_deg, 180.0), 3.0);
  }
  EXPECT_EQ(a.flights[0].thermals[0].direction, fl::Phase::CirclingRight);
  EXPECT_EQ(a.flights[1].thermals[0].direction, fl::Phase::CirclingLeft);
  // Per point: ground outside the flights, the flights' phases inside.
  const trailray::track::Track track = sim.track();
  const std::vector<fl::Phase> per_point = fl::phase_per_point(track, a);
  ASSERT_EQ(per_point.size(), track.point_count());
  EXPECT_EQ(per_point.front(), fl::Phase::Ground);
  EXPECT_EQ(per_point.back(), fl::Phase::Ground);
  EXPECT_EQ(per_point[static_cast<std::size_t>(landing1 - SyntheticFlight::kT0) + 400], fl::Phase::Ground);
  EXPECT_EQ(per_point[a.flights[0].thermals[0].start.point + 30], fl::Phase::CirclingRight);
  EXPECT_EQ(per_point[a.flights[1].thermals[0].start.point + 30], fl::Phase::CirclingLeft);
}

// S-turns and a single 360 are not thermals; two full turns are.
TEST(FlightSynthetic, STurnsAndASingleTurnAreNotThermals) {
  SyntheticFlight sim;
  sim.ground(60);
  sim.glide(100, 0.0);
  sim.s_turns(120, 0.0, 60.0, 8);  // heading swinging +-60 degrees every 8 s
  sim.glide(100, 0.0);
  sim.circle(25, true, 0.0);  // one turn (25 s at 40 m radius and 10 m/s)
  sim.glide(100, 0.0);
  sim.circle(50, false, 1.0);  // two turns
  sim.glide(100, 0.0);
  sim.ground(60);
  const fl::FlightAnalysis a = fl::analyse_flights(sim.track());
  ASSERT_EQ(a.flights.size(), 1u);
  expect_tiling(a.flights[0]);
  ASSERT_EQ(a.flights[0].thermals.size(), 1u);
  EXPECT_EQ(a.flights[0].thermals[0].direction, fl::Phase::CirclingLeft);
  EXPECT_NEAR(a.flights[0].thermals[0].turns, 2.0, 0.4);
}

// A gap in the log is an Unknown phase (no turn rate across it), inside the one flight.
TEST(FlightSynthetic, GapIsUnknown) {
  SyntheticFlight sim;
  sim.ground(60);
  sim.glide(200, 0.0);
  sim.gap(60, 0.0);
  sim.glide(200, 0.0);
  sim.ground(60);
  const fl::FlightAnalysis a = fl::analyse_flights(sim.track());
  ASSERT_EQ(a.flights.size(), 1u);
  const fl::Flight& f = a.flights[0];
  expect_tiling(f);
  ASSERT_EQ(f.phases.size(), 3u);
  EXPECT_EQ(f.phases[1].phase, fl::Phase::Unknown);
  EXPECT_GE(f.unknown_s, 60.0);
  EXPECT_LT(f.unknown_s, 70.0);
  EXPECT_EQ(f.glides.size(), 2u);
}

// Nothing to analyse: no times, no elevation, a single point, an empty track.
TEST(FlightSynthetic, TracksWithoutTimesOrAltitudeGiveNoFlights) {
  SyntheticFlight sim;
  sim.ground(60);
  sim.glide(300, 0.0);
  sim.ground(60);
  trailray::track::Track no_time = sim.track();
  for (auto& p : no_time.segments[0].points) p.time = trailray::track::kMissing;
  fl::FlightAnalysis a = fl::analyse_flights(no_time);
  EXPECT_TRUE(a.flights.empty());
  EXPECT_EQ(a.points, no_time.point_count());
  EXPECT_EQ(a.points_used, 0u);
  trailray::track::Track no_ele = sim.track();
  for (auto& p : no_ele.segments[0].points) p.ele = trailray::track::kMissing;
  a = fl::analyse_flights(no_ele);
  EXPECT_TRUE(a.flights.empty());
  EXPECT_FALSE(a.has_altitude);
  EXPECT_TRUE(fl::analyse_flights(trailray::track::Track{}).flights.empty());
  EXPECT_EQ(fl::phase_per_point(no_time, a).size(), no_time.point_count());
}

// A walk: no flight at all (not the whole log as one, as scoring would take it).
TEST(FlightSynthetic, WalkIsNoFlight) {
  SyntheticFlight sim;
  sim.ground(60);
  sim.glide(1200, 45.0, 1.4, 0.1);  // 1.4 m/s, climbing 0.1 m/s (uphill)
  sim.ground(60);
  EXPECT_TRUE(fl::analyse_flights(sim.track()).flights.empty());
}

// A logger that records every 20 s is slow, not gappy: no Unknown phase, and a 60 s hole in it
// still is one.
TEST(FlightSynthetic, SparseFixesAreNotGaps) {
  SyntheticFlight sim;
  sim.ground(200);
  sim.glide(600, 0.0);
  sim.circle(300, true, 2.0, 80.0);
  sim.glide(600, 90.0);
  sim.ground(200);
  trailray::track::Track sparse;
  sparse.segments.emplace_back();
  const auto& pts = sim.points();
  for (std::size_t i = 0; i < pts.size(); i += 20)
    if (i < 900 || i > 960) sparse.segments[0].points.push_back(pts[i]);  // one hole of 80 s
  const fl::FlightAnalysis a = fl::analyse_flights(sparse);
  ASSERT_EQ(a.flights.size(), 1u);
  expect_tiling(a.flights[0]);
  EXPECT_GT(a.flights[0].unknown_s, 0.0);
  EXPECT_LE(a.flights[0].unknown_s, 80.0 + 2 * 20.0);
  EXPECT_GT(a.flights[0].gliding_s, 900.0);
}

TEST(FlightSynthetic, CirclingDownIsCirclingNotAThermal) {
  // A thermal climbing 2 m/s, a glide, then two minutes of circles sinking 1.8 m/s (a spiral down
  // to land): one thermal, but all of the circling time.
  SyntheticFlight f;
  f.ground(60);
  f.glide(120, 0.0);
  f.circle(120, true, 2.0);
  f.glide(200, 90.0);
  f.circle(120, false, -1.8);
  f.glide(100, 180.0, 10.0, 2.0);
  f.ground(60);
  const fl::FlightAnalysis a = fl::analyse_flights(f.track());
  ASSERT_EQ(a.flights.size(), 1u);
  const fl::Flight& flight = a.flights[0];
  ASSERT_EQ(flight.thermals.size(), 1u);
  EXPECT_NEAR(flight.thermals[0].mean_climb_ms, 2.0, 0.3);
  EXPECT_NEAR(flight.mean_thermal_climb_ms, 2.0, 0.3);  // not dragged down by the descent
  EXPECT_GT(flight.circling_s, 200.0);                  // both circlings are circling time
}
