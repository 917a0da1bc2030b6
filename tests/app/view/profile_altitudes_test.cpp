// The profile chart's altitude lines: one for a track with one altitude; for an IGC flight with a
// barometer its GNSS and pressure altitudes, labelled with the one the 3D track is drawn at
// (`--igc-altitude`); the chart's extent covers both; the tooltip lists the pressure altitude.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "app/view/profile_chart.hpp"
#include "app/view/tooltip.hpp"
#include "scene/track_files.hpp"
#include "test_support.hpp"
#include "viewer_test_tracks.hpp"

namespace trailray::app::view {
namespace {

using namespace test_tracks;

// 11 points 100 m and 10 s apart at 500 m; pressure altitude `offset` below (NaN: none).
scene::TrackSet flight(double offset, bool with_ele = true) {
  track::Segment s = line(11, 100.0, 10.0, 500.0);
  for (track::TrackPoint& p : s.points) {
    if (!std::isnan(offset)) p.pressure_altitude = static_cast<float>(p.ele - offset);
    if (!with_ele) p.ele = track::kMissing;
  }
  return viewer_tracks({file_of("flight.igc", {track_of("flight", {s})})});
}

std::vector<std::string> labels(const std::vector<AltitudeLine>& lines) {
  std::vector<std::string> out;
  for (const AltitudeLine& l : lines) out.push_back(l.label + (l.pressure ? " [p]" : "") + (l.in_3d ? " [3d]" : ""));
  return out;
}

TEST(ProfileAltitudes, OneAltitudeIsOneLine) {
  EXPECT_EQ(labels(altitude_lines(flight(std::nan(""))[0])), std::vector<std::string>{"altitude [3d]"});
}

TEST(ProfileAltitudes, GnssAndPressureAreTwoLinesAndTheGnssOneIsIn3d) {
  const auto tracks = flight(120.0);
  EXPECT_EQ(labels(altitude_lines(tracks[0])),
            (std::vector<std::string>{"GNSS altitude (3D track) [3d]", "pressure altitude [p]"}));
  // The chart spans both: 380 m to 500 m.
  const auto e = chart_extent(tracks[0], ChartAxis::distance);
  ASSERT_TRUE(e);
  EXPECT_NEAR(e->y_min, 380.0, 1e-3);
  EXPECT_NEAR(e->y_max, 500.0, 1e-3);
}

TEST(ProfileAltitudes, PressureDrawnIsOneLineMarkedSo) {
  EXPECT_EQ(labels(altitude_lines(flight(0.0)[0])), std::vector<std::string>{"pressure altitude (3D track) [3d]"});
}

TEST(ProfileAltitudes, PressureWithoutADrawnAltitude) {
  // `--igc-altitude gnss` on a file without GNSS altitude: the 3D track lies on the ground.
  const auto tracks = flight(0.0, false);
  EXPECT_EQ(labels(altitude_lines(tracks[0])), std::vector<std::string>{"pressure altitude (not in 3D) [p]"});
  const auto e = chart_extent(tracks[0], ChartAxis::distance);
  ASSERT_TRUE(e);
  EXPECT_NEAR(e->y_min, 499.0, 1e-3);  // a flat 500 m, widened by 1 m
}

TEST(ProfileAltitudes, NoAltitudeNoLine) { EXPECT_TRUE(altitude_lines(flight(std::nan(""), false)[0]).empty()); }

TEST(ProfileAltitudes, TooltipListsThePressureAltitudeWhenThereIsOne) {
  const auto with = tooltip_lines(flight(120.0)[0], 4);
  ASSERT_EQ(with.size(), 7u);
  EXPECT_EQ(with[1], "altitude: 500 m");
  EXPECT_EQ(with[2], "pressure altitude: 380 m");
  EXPECT_EQ(with[3], "height above ground: \u2014");
  EXPECT_EQ(tooltip_lines(flight(std::nan(""))[0], 4).size(), 6u);
}

TEST(ProfileAltitudesRealFile, InterlakenChartShowsBothAltitudes) {
  TRAILRAY_REQUIRE_DATA(path, "igc/goigc_0100_interlaken.igc");
  scene::CollectedDiagnostics diagnostics;
  track::ReadOptions automatic, pressure;
  pressure.igc_altitude = track::ReadOptions::IgcAltitude::Pressure;
  const auto a = viewer_tracks({scene::read_track_file(path.string(), automatic, diagnostics)});
  const auto p = viewer_tracks({scene::read_track_file(path.string(), pressure, diagnostics)});
  EXPECT_EQ(labels(altitude_lines(a[0])),
            (std::vector<std::string>{"GNSS altitude (3D track) [3d]", "pressure altitude [p]"}));
  EXPECT_EQ(labels(altitude_lines(p[0])), std::vector<std::string>{"pressure altitude (3D track) [3d]"});
  // Auto's chart reaches down to the lowest pressure altitude, below the lowest GNSS one.
  const auto e = chart_extent(a[0], ChartAxis::distance);
  ASSERT_TRUE(e);
  EXPECT_LT(e->y_min, a[0].lowest_altitude() - 50.0);
}

}  // namespace
}  // namespace trailray::app::view
