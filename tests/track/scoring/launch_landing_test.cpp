// Launch detection: find_flights tells "no flight" (a walk) from a flight; detect_flights, which
// scoring uses, still falls back to the whole log as the reference scorer does.
#include <gtest/gtest.h>

#include <cmath>

#include "track/scoring/launch_landing.hpp"

namespace sc = trailray::track::scoring;

namespace {

// 1 Hz fixes heading north at `speed` m/s and `climb` m/s (whole metres), from (46 N, 7 E) at 1000 m.
void move(std::vector<sc::Fix>& fixes, int seconds, double speed, double climb) {
  for (int i = 0; i < seconds; ++i) {
    sc::Fix f = fixes.empty() ? sc::Fix{46.0, 7.0, 1.7e9, 1000, 0} : fixes.back();
    if (!fixes.empty()) {
      f.lat += speed / 111200.0;
      f.time += 1.0;
      f.gnss_alt += static_cast<int>(std::lround(climb));
    }
    fixes.push_back(f);
  }
}

}  // namespace

TEST(LaunchLanding, WalkHasNoFlightButScoringTakesTheWholeLog) {
  std::vector<sc::Fix> walk;
  move(walk, 1800, 1.4, 0.0);
  EXPECT_TRUE(sc::find_flights(walk).empty());
  const auto windows = sc::detect_flights(walk);
  ASSERT_EQ(windows.size(), 1u);
  EXPECT_EQ(windows[0].launch, 0);
  EXPECT_EQ(windows[0].landing, 1799);
}

TEST(LaunchLanding, FlightBetweenGroundTimeIsFound) {
  std::vector<sc::Fix> log;
  move(log, 120, 0.0, 0.0);
  move(log, 600, 10.0, -1.0);
  const int flown = static_cast<int>(log.size());
  move(log, 120, 0.0, 0.0);
  const auto flights = sc::find_flights(log);
  ASSERT_EQ(flights.size(), 1u);
  // As the reference: the nearest fix judged on the ground, which takes 20 s of standing still.
  EXPECT_GE(flights[0].launch, 90);
  EXPECT_LE(flights[0].launch, 125);
  EXPECT_GE(flights[0].landing, flown - 5);
  EXPECT_LE(flights[0].landing, flown + 30);
  const sc::MotionAverages ma = sc::motion_averages(log);
  ASSERT_EQ(ma.ground_speed.size(), log.size());
  EXPECT_NEAR(ma.ground_speed[400], 10.0, 0.1);
  EXPECT_NEAR(ma.vertical_speed[400], 1.0, 0.1);
  EXPECT_NEAR(ma.ground_speed[10], 0.0, 1e-9);
}
