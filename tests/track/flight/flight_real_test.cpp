// Flight analysis on the real IGC flights of ../shared/data/igc, checked for plausibility:
// - every flight: take-off before landing, phases tiling it in order, no overlap;
// - every thermal's mean climb in [0, 8] m/s (circling descents, spirals, are circling time, not
//   thermals: FlightOptions::min_thermal_gain_m) and its best 20 s climb under 12 m/s;
// - every thermal's wind under 20 m/s (the strongest in the data is about 13.5 m/s);
// - glides: a positive glide ratio or none (NaN), mean speed under 80 m/s (290 km/h);
// - flights over 40 minutes circle between 5 % and 80 % of the time;
// - flight_with_middle_landing.igc has two flights with ground time between them, and
//   hiking-up.igc's take-off comes hours after the log starts (the walk up is not flown);
// - the wind is not noise: in a flight with at least 8 thermals of 2 turns or more whose mean
//   wind is over 4 m/s, at least 80 % of them give a direction within 45 degrees of the mean
//   (measured: 35 of 35 in the record de France, 27 of 29 in New Zealand, 60 of 62 in the 465 km
//   free flight).
// The benchmark figure (time to analyse the longest flight) is in bench/flight_analysis_bench.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "test_support.hpp"
#include "track/flight/flight_analysis.hpp"
#include "track/io/load.hpp"

namespace fl = trailray::track::flight;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> igc_files(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    std::string ext = e.path().extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (e.is_regular_file() && ext == ".igc") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

fl::FlightAnalysis analyse_file(const fs::path& path) {
  const trailray::track::ReadResult r = trailray::track::load_track_file(path.string());
  EXPECT_TRUE(r.ok()) << path;
  if (!r.ok() || r.file.tracks.empty()) return {};
  return fl::analyse_flights(r.file.tracks.front());
}

}  // namespace

TEST(FlightReal, EveryFlightIsPlausible) {
  TRAILRAY_REQUIRE_DATA(dir, "igc");
  std::size_t files = 0, flights = 0, thermals = 0;
  for (const fs::path& path : igc_files(dir)) {
    SCOPED_TRACE(path.filename().string());
    const fl::FlightAnalysis a = analyse_file(path);
    ++files;
    for (const fl::Flight& f : a.flights) {
      ++flights;
      EXPECT_LT(f.takeoff.time, f.landing.time);
      ASSERT_FALSE(f.phases.empty());
      EXPECT_EQ(f.phases.front().start.point, f.takeoff.point);
      EXPECT_EQ(f.phases.back().end.point, f.landing.point);
      for (std::size_t k = 0; k < f.phases.size(); ++k) {
        EXPECT_LT(f.phases[k].start.time, f.phases[k].end.time);
        if (k > 0) {
          EXPECT_EQ(f.phases[k].start.point, f.phases[k - 1].end.point);
        }
      }
      EXPECT_NEAR(f.circling_s + f.gliding_s + f.unknown_s, f.duration_s, 1e-6);
      for (const fl::Thermal& t : f.thermals) {
        ++thermals;
        EXPECT_GT(t.mean_climb_ms, 0.0);  // a thermal climbs
        EXPECT_GE(t.gain_m, 20.0);
        EXPECT_LE(t.mean_climb_ms, 8.0);
        EXPECT_LT(t.best_climb_ms, 12.0);
        EXPECT_GE(t.best_climb_ms, t.mean_climb_ms - 1e-9);
        EXPECT_LT(t.wind_speed_ms, 20.0);
        EXPECT_GE(t.wind_from_deg, 0.0);
        EXPECT_LT(t.wind_from_deg, 360.0);
        EXPECT_TRUE(fl::is_circling(f.phases[t.phase].phase));
      }
      for (const fl::Glide& g : f.glides) {
        EXPECT_TRUE(std::isnan(g.glide_ratio) || g.glide_ratio > 0);
        EXPECT_LT(g.mean_speed_ms, 80.0);
        EXPECT_EQ(f.phases[g.phase].phase, fl::Phase::Gliding);
      }
      if (f.duration_s > 40 * 60) {
        EXPECT_GE(f.circling_share, 0.05);
        EXPECT_LE(f.circling_share, 0.80);
      }
    }
  }
  EXPECT_GE(files, 10u);
  EXPECT_GE(flights, files - 1);  // all fly but aerofiles_bad-line.igc (9 fixes)
  EXPECT_GE(thermals, 100u);
}

TEST(FlightReal, ThermalWindsAgreeWithinAFlight) {
  TRAILRAY_REQUIRE_DATA(dir, "igc");
  int checked = 0;
  for (const fs::path& path : igc_files(dir)) {
    SCOPED_TRACE(path.filename().string());
    for (const fl::Flight& f : analyse_file(path).flights) {
      double e = 0, n = 0, w = 0;
      std::vector<const fl::Thermal*> th;
      for (const fl::Thermal& t : f.thermals) {
        if (!t.wind_from_centres) continue;
        const double to = t.drift_to_deg * std::numbers::pi / 180;
        e += t.wind_speed_ms * std::sin(to) * t.duration_s;
        n += t.wind_speed_ms * std::cos(to) * t.duration_s;
        w += t.duration_s;
        th.push_back(&t);
      }
      if (th.size() < 8 || std::hypot(e, n) / w <= 4.0) continue;
      ++checked;
      const double from = std::fmod(std::atan2(-e, -n) * 180 / std::numbers::pi + 360.0, 360.0);
      std::size_t agree = 0;
      for (const fl::Thermal* t : th) {
        const double d = std::fmod(std::fabs(t->wind_from_deg - from), 360.0);
        if (std::min(d, 360.0 - d) < 45.0) ++agree;
      }
      EXPECT_GE(static_cast<double>(agree), 0.8 * static_cast<double>(th.size())) << agree << " of " << th.size();
    }
  }
  EXPECT_GE(checked, 4);
}

TEST(FlightReal, MiddleLandingGivesTwoFlights) {
  TRAILRAY_REQUIRE_DATA(path, "igc/igclib_flight_with_middle_landing.igc");
  const fl::FlightAnalysis a = analyse_file(path);
  ASSERT_EQ(a.flights.size(), 2u);
  EXPECT_GT(a.flights[1].takeoff.time - a.flights[0].landing.time, 120.0);  // on the ground between
  for (const fl::Flight& f : a.flights) {
    EXPECT_GT(f.duration_s, 30 * 60.0);
    EXPECT_FALSE(f.thermals.empty());
  }
}

TEST(FlightReal, HikeBeforeTakeoffIsNotFlightTime) {
  TRAILRAY_REQUIRE_DATA(path, "igc/xcscore_hiking-up.igc");
  const trailray::track::ReadResult r = trailray::track::load_track_file(path.string());
  ASSERT_TRUE(r.ok());
  const fl::FlightAnalysis a = fl::analyse_flights(r.file.tracks.front());
  ASSERT_EQ(a.flights.size(), 1u);
  const double log_start = r.file.tracks.front().segments.front().points.front().time;
  EXPECT_GT(a.flights[0].takeoff.time - log_start, 2 * 3600.0);
  EXPECT_GT(a.flights[0].takeoff.alt, 2000.0);  // launched from high up, after the walk
}
