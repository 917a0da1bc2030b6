// The viewer's flight analysis text and the chart's thermal bands, on a simulated flight with
// known thermals (tests/track/flight/synthetic_flight.hpp), built as the viewer builds tracks.
#include "ui/flight_panel.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "track/flight/synthetic_flight.hpp"
#include "scene/tracks/track_building.hpp"

namespace trailray::ui {
namespace {

using track::test::SyntheticFlight;

struct Built {
  scene::Track track;
  double t1 = 0, t1_end = 0;
};

Built simulated() {
  Built b;
  SyntheticFlight sim(3.0, 270.0);
  sim.ground(120);
  sim.glide(120, 0.0);
  b.t1 = sim.time();
  sim.circle(200, true, 2.0);
  b.t1_end = sim.time();
  sim.glide(400, 90.0, 10.0, 1.2);
  sim.circle(150, false, 1.0, 50.0, 11.0);
  sim.glide(200, 330.0);
  sim.ground(120);
  scene::LoadedTrackFile loaded;
  loaded.path = "sim.igc";
  loaded.file.tracks.push_back(sim.track());
  scene::TrackBuildOptions options;
  options.inspect = true;  // as the viewer: the flight analysis comes with it
  scene::CollectedDiagnostics diagnostics;
  b.track = scene::build_tracks({loaded}, {}, options, diagnostics).at(0);
  return b;
}

TEST(FlightPanel, SummaryNamesTheFlightsFigures) {
  const Built b = simulated();
  ASSERT_TRUE(b.track.flights);
  ASSERT_EQ(b.track.flights->flights.size(), 1u);
  const auto& f = b.track.flights->flights[0];
  const auto lines = flight_summary_lines(f);
  ASSERT_GE(lines.size(), 7u);  // take-off, landing, duration, circling, thermals, glide, a wind band
  EXPECT_EQ(lines[0].rfind("take-off ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find(" UTC, 1000 m"), std::string::npos) << lines[0];  // the simulator starts at 1000 m
  EXPECT_NE(lines[3].find(fmt::format("circling {:.0f} %", 100.0 * f.circling_share)), std::string::npos) << lines[3];
  EXPECT_EQ(lines[4].rfind("thermals 2, mean climb +", 0), 0u) << lines[4];
  EXPECT_NE(lines[4].find(fmt::format("best {:+.1f} m/s", f.best_climb_ms)), std::string::npos) << lines[4];
  EXPECT_NEAR(f.best_climb_ms, 2.0, 0.1);
  // The wind the circles drifted in: 3 m/s from the west.
  bool wind = false;
  for (const auto& line : lines)
    if (line.rfind("wind ", 0) == 0) {
      wind = true;
      EXPECT_NE(line.find(": 3.0 m/s from 270\u00b0"), std::string::npos) << line;
    }
  EXPECT_TRUE(wind);
  const auto row = thermal_row(f.thermals[0]);
  ASSERT_EQ(row.size(), 5u);
  EXPECT_EQ(row[1], fmt::format("{:+.1f} m/s", f.thermals[0].mean_climb_ms));
  EXPECT_EQ(row[2], fmt::format("{:.0f}->{:.0f} m", f.thermals[0].start.alt, f.thermals[0].end.alt));
}

// The band of a thermal spans its points: the first at or after its entry, the last at or before its exit.
TEST(FlightPanel, ThermalBandsSpanTheThermalsPoints) {
  const Built b = simulated();
  const auto& th = b.track.flights->flights.at(0).thermals.at(0);
  const auto span = points_between(b.track, th.start.time, th.end.time);
  ASSERT_TRUE(span);
  const auto& time = b.track.time_unix_s;
  EXPECT_GE(time[span->first], th.start.time);
  EXPECT_LE(time[span->second], th.end.time);
  EXPECT_LT(time[span->first - 1], th.start.time);
  EXPECT_GT(time[span->second + 1], th.end.time);
  // The analysis finds the edges within half its turn window (10 s) of the simulated ones.
  EXPECT_NEAR(time[span->first], b.t1, 12.0);
  EXPECT_NEAR(time[span->second], b.t1_end, 12.0);
  EXPECT_FALSE(points_between(b.track, th.end.time + 1e7, th.end.time + 2e7));
  EXPECT_FALSE(points_between(b.track, th.end.time, th.start.time));
}

}  // namespace
}  // namespace trailray::ui
