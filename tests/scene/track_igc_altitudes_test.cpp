// A scene track keeps an IGC flight's pressure altitude per flat point beside the altitude it is
// drawn at, and tells whether that drawn altitude is the pressure one (`--igc-altitude`).

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "scene/diagnostics.hpp"
#include "scene/style.hpp"
#include "scene/track_building.hpp"
#include "scene/track_files.hpp"
#include "test_support.hpp"

namespace trailray::scene {
namespace {

// Two segments of 12 points heading north, 20 m and 1 s apart; elevation 1000 + i, pressure
// altitude `offset` below it (NaN offset: none), except point 3 of the first when `hole`.
LoadedTrackFile flight(double offset, bool hole = false) {
  LoadedTrackFile f;
  f.path = "flight.igc";
  f.file.format = track::Format::Igc;
  f.file.tracks.emplace_back();
  for (int s = 0; s < 2; ++s) {
    track::Segment seg;
    for (int i = 0; i < 12; ++i) {
      track::TrackPoint p;
      p.lat = 46.7 + 0.00018 * (i + 20 * s);
      p.lon = 7.85;
      p.time = 1.7e9 + i + 100 * s;
      p.ele = 1000.0 + i;
      if (!std::isnan(offset) && !(hole && s == 0 && i == 3)) p.pressure_altitude = static_cast<float>(p.ele - offset);
      seg.points.push_back(p);
    }
    f.file.tracks.back().segments.push_back(seg);
  }
  return f;
}

std::vector<Track> build(const std::vector<LoadedTrackFile>& files) {
  TrackBuildOptions options;
  options.inspect = true;
  CollectedDiagnostics ignored;
  return build_tracks(files, TrackStyle{}, options, ignored);
}

TEST(TrackPressure, PerFlatPointBesideTheAltitude) {
  const auto tracks = build({flight(80.0, true)});
  ASSERT_EQ(tracks.size(), 1u);
  const Track& t = tracks[0];
  ASSERT_EQ(t.point_count(), 24u);
  ASSERT_EQ(t.pressure_altitude_m.size(), 24u);
  EXPECT_TRUE(std::isnan(t.pressure_altitude_m[3]));
  EXPECT_TRUE(std::isnan(t.pressure_altitude(3)));
  for (std::size_t i = 0; i < 24; ++i) {
    // A straight climb stays straight through smoothing: 80 m below the drawn altitude, except
    // where the kernel reaches the point without one (its window is lopsided there).
    if (i < 12 && i + 5 >= 3 && i <= 3 + 5) continue;
    EXPECT_NEAR(t.pressure_altitude_m[i], t.altitude_m[i] - 80.0, 1e-3) << i;
  }
  EXPECT_NEAR(t.pressure_altitude_m[2], t.altitude_m[2] - 80.0, 1.0);
  EXPECT_TRUE(std::isnan(t.pressure_altitude(24)));  // past the end
  EXPECT_TRUE(t.has_pressure_altitude());
  EXPECT_FALSE(t.altitude_is_pressure());
}

TEST(TrackPressure, SameAltitudesMeanTheDrawnOneIsPressure) {
  const auto tracks = build({flight(0.0)});
  EXPECT_TRUE(tracks[0].has_pressure_altitude());
  EXPECT_TRUE(tracks[0].altitude_is_pressure());
}

TEST(TrackPressure, TracksWithoutItHaveNaNs) {
  const auto tracks = build({flight(std::nan(""))});
  const Track& t = tracks[0];
  ASSERT_EQ(t.pressure_altitude_m.size(), t.point_count());
  for (double p : t.pressure_altitude_m) EXPECT_TRUE(std::isnan(p));
  EXPECT_FALSE(t.has_pressure_altitude());
  EXPECT_FALSE(t.altitude_is_pressure());
}

// The real flight read as `--igc-altitude` says: auto draws the GNSS altitude (about 100 m above
// the pressure altitude in this file), pressure draws the pressure one; both keep the pressure
// altitude.
TEST(TrackPressureRealFile, IgcAltitudeChoosesTheDrawnAltitude) {
  TRAILRAY_REQUIRE_DATA(path, "igc/goigc_0100_interlaken.igc");
  CollectedDiagnostics diagnostics;
  track::ReadOptions automatic, pressure;
  pressure.igc_altitude = track::ReadOptions::IgcAltitude::Pressure;
  const auto a = build({read_track_file(path.string(), automatic, diagnostics)});
  const auto p = build({read_track_file(path.string(), pressure, diagnostics)});
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(a[0].has_pressure_altitude());
  EXPECT_FALSE(a[0].altitude_is_pressure());
  EXPECT_TRUE(p[0].altitude_is_pressure());
  // (The minimum distance counts the climb, so the two may keep different points.)
  for (std::size_t i = 0; i < p[0].point_count(); ++i)
    ASSERT_NEAR(p[0].altitude_m[i], p[0].pressure_altitude_m[i], 0.01) << i;
  double gap = 0.0;
  for (std::size_t i = 0; i < a[0].point_count(); ++i) gap += a[0].altitude_m[i] - a[0].pressure_altitude_m[i];
  gap /= static_cast<double>(a[0].point_count());
  EXPECT_GT(gap, 50.0);
  EXPECT_LT(gap, 150.0);
}

}  // namespace
}  // namespace trailray::scene
