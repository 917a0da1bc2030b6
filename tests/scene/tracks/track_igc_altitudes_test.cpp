// A scene track keeps an IGC flight's GNSS and pressure altitudes per flat point beside the
// altitude it is drawn at, and tells which of them that drawn altitude is (`--igc-altitude`).

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "scene/diagnostics.hpp"
#include "scene/style.hpp"
#include "scene/tracks/track_building.hpp"
#include "scene/tracks/track_files.hpp"
#include "test_support.hpp"

namespace trailray::scene {
namespace {

using Source = Track::AltitudeSource;

// Two segments of 12 points heading north, 20 m and 1 s apart; elevation 1000 + i, pressure
// altitude `pressure` below it and GNSS altitude `gnss` below it (NaN: none), except point 3 of
// the first segment (no pressure altitude) and point 7 of the second (no GNSS altitude) when
// `holes`.
LoadedTrackFile flight(double pressure, double gnss = std::nan(""), bool holes = false) {
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
      if (!std::isnan(pressure) && !(holes && s == 0 && i == 3))
        p.pressure_altitude = static_cast<float>(p.ele - pressure);
      if (!std::isnan(gnss) && !(holes && s == 1 && i == 7)) p.gnss_altitude = static_cast<float>(p.ele - gnss);
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

// A straight climb stays straight through smoothing: `offset` below the drawn altitude, except
// where the kernel (half-width 5) reaches the point `hole` without one (its window is lopsided).
void expect_offset(const Track& t, const std::vector<double>& channel, double offset, std::size_t hole) {
  ASSERT_EQ(channel.size(), t.point_count());
  const std::size_t segment = hole / 12;
  for (std::size_t i = 0; i < channel.size(); ++i) {
    if (i == hole) {
      EXPECT_TRUE(std::isnan(channel[i])) << i;
    } else if (i / 12 == segment && i + 5 >= hole && i <= hole + 5) {
      EXPECT_NEAR(channel[i], t.altitude_m[i] - offset, 1.0) << i;
    } else {
      EXPECT_NEAR(channel[i], t.altitude_m[i] - offset, 1e-3) << i;
    }
  }
}

TEST(TrackIgcAltitudes, PerFlatPointBesideTheAltitude) {
  const auto tracks = build({flight(80.0, -30.0, true)});
  ASSERT_EQ(tracks.size(), 1u);
  const Track& t = tracks[0];
  ASSERT_EQ(t.point_count(), 24u);
  expect_offset(t, t.pressure_altitude_m, 80.0, 3);
  expect_offset(t, t.gnss_altitude_m, -30.0, 19);
  EXPECT_TRUE(std::isnan(t.pressure_altitude(3)));
  EXPECT_TRUE(std::isnan(t.gnss_altitude(19)));
  EXPECT_NEAR(t.gnss_altitude(3), t.altitude_m[3] + 30.0, 1e-3);
  EXPECT_TRUE(std::isnan(t.pressure_altitude(24)));  // past the end
  EXPECT_TRUE(std::isnan(t.gnss_altitude(24)));
  EXPECT_TRUE(t.has_pressure_altitude());
  EXPECT_TRUE(t.has_gnss_altitude());
  EXPECT_EQ(t.altitude_source(), Source::none);  // neither is the drawn one
}

TEST(TrackIgcAltitudes, TheDrawnAltitudeIsTheOneItEquals) {
  EXPECT_EQ(build({flight(80.0, 0.0)})[0].altitude_source(), Source::gnss);
  EXPECT_EQ(build({flight(0.0, -80.0)})[0].altitude_source(), Source::pressure);
  EXPECT_EQ(build({flight(0.0)})[0].altitude_source(), Source::pressure);  // no GNSS channel
  EXPECT_EQ(build({flight(std::nan(""), 0.0)})[0].altitude_source(), Source::gnss);
}

TEST(TrackIgcAltitudes, AutoModesVFixesTakeThePressureAltitudeAndTheDrawnOneStaysGnss) {
  // `--igc-altitude auto` on a file with a few 'V' fixes: `ele` is the pressure altitude there.
  LoadedTrackFile f = flight(80.0, 0.0);
  for (track::Segment& s : f.file.tracks[0].segments)
    for (std::size_t i : {4u, 5u}) s.points[i].ele = static_cast<double>(s.points[i].pressure_altitude);
  EXPECT_EQ(build({f})[0].altitude_source(), Source::gnss);
}

TEST(TrackIgcAltitudes, TracksWithoutThemHaveNaNs) {
  const auto tracks = build({flight(std::nan(""))});
  const Track& t = tracks[0];
  // No array for them (no memory), and NaN through the accessors.
  EXPECT_TRUE(t.pressure_altitude_m.empty());
  EXPECT_TRUE(t.gnss_altitude_m.empty());
  for (std::size_t i = 0; i < t.point_count(); ++i) {
    EXPECT_TRUE(std::isnan(t.pressure_altitude(i)));
    EXPECT_TRUE(std::isnan(t.gnss_altitude(i)));
  }
  EXPECT_FALSE(t.has_pressure_altitude());
  EXPECT_FALSE(t.has_gnss_altitude());
  EXPECT_EQ(t.altitude_source(), Source::none);
}

// The real flight read as `--igc-altitude` says: auto draws the GNSS altitude (about 100 m above
// the pressure altitude in this file), pressure draws the pressure one; both keep both altitudes.
TEST(TrackIgcAltitudesRealFile, IgcAltitudeChoosesTheDrawnAltitudeAndBothAreKept) {
  TRAILRAY_REQUIRE_DATA(path, "igc/goigc_0100_interlaken.igc");
  CollectedDiagnostics diagnostics;
  track::ReadOptions automatic, pressure;
  pressure.igc_altitude = track::ReadOptions::IgcAltitude::Pressure;
  const auto a = build({read_track_file(path.string(), automatic, diagnostics)});
  const auto p = build({read_track_file(path.string(), pressure, diagnostics)});
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(p.size(), 1u);
  for (const Track* t : {&a[0], &p[0]}) {
    EXPECT_TRUE(t->has_pressure_altitude());
    EXPECT_TRUE(t->has_gnss_altitude());
  }
  EXPECT_EQ(a[0].altitude_source(), Source::gnss);
  EXPECT_EQ(p[0].altitude_source(), Source::pressure);
  // (The minimum distance counts the climb, so the two may keep different points.)
  for (std::size_t i = 0; i < a[0].point_count(); ++i) ASSERT_NEAR(a[0].altitude_m[i], a[0].gnss_altitude_m[i], 0.01);
  for (std::size_t i = 0; i < p[0].point_count(); ++i)
    ASSERT_NEAR(p[0].altitude_m[i], p[0].pressure_altitude_m[i], 0.01) << i;
  for (const Track* t : {&a[0], &p[0]}) {
    double gap = 0.0;
    for (std::size_t i = 0; i < t->point_count(); ++i) gap += t->gnss_altitude_m[i] - t->pressure_altitude_m[i];
    gap /= static_cast<double>(t->point_count());
    EXPECT_GT(gap, 50.0);
    EXPECT_LT(gap, 150.0);
  }
}

}  // namespace
}  // namespace trailray::scene
