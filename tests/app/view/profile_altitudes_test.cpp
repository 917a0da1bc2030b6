// The profile chart's altitude lines: one for a track with one altitude; for an IGC flight its GNSS
// and pressure altitudes whichever the 3D track is drawn at (`--igc-altitude`), the one it is drawn
// at marked so; the chart's extent covers all; the tooltip lists both.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app/view/viewer_ui.hpp"
#include "scene/tracks/track_files.hpp"
#include "test_support.hpp"
#include "ui/profile_chart.hpp"
#include "ui/tooltip.hpp"
#include "viewer_test_tracks.hpp"

namespace trailray::app::view {
namespace {

using namespace test_tracks;

const double kNone = std::nan("");

// 11 points 100 m and 10 s apart at 500 m; pressure and GNSS altitude `pressure`, `gnss` below
// it (NaN: none); without `with_ele` the points have no drawn altitude.
scene::TrackSet flight(double pressure, double gnss, bool with_ele = true) {
  track::Segment s = line(11, 100.0, 10.0, 500.0);
  for (track::TrackPoint& p : s.points) {
    if (!std::isnan(pressure)) p.pressure_altitude = static_cast<float>(p.ele - pressure);
    if (!std::isnan(gnss)) p.gnss_altitude = static_cast<float>(p.ele - gnss);
    if (!with_ele) p.ele = track::kMissing;
  }
  return viewer_tracks({file_of("flight.igc", {track_of("flight", {s})})});
}

std::vector<std::string> labels(const std::vector<AltitudeLine>& lines) {
  std::vector<std::string> out;
  for (const AltitudeLine& l : lines) {
    const char* source = l.source == AltitudeLine::Source::gnss       ? " [gnss]"
                         : l.source == AltitudeLine::Source::pressure ? " [pressure]"
                                                                      : "";
    out.push_back(l.label + source + (l.in_3d ? " [3d]" : ""));
  }
  return out;
}

TEST(ProfileAltitudes, OneAltitudeIsOneLine) {
  EXPECT_EQ(labels(altitude_lines(flight(kNone, kNone)[0])), std::vector<std::string>{"altitude [3d]"});
}

TEST(ProfileAltitudes, GnssDrawnAndPressureAreTwoLines) {
  // `--igc-altitude auto` or `gnss`: `ele` is the GNSS altitude.
  const auto tracks = flight(120.0, 0.0);
  EXPECT_EQ(labels(altitude_lines(tracks[0])),
            (std::vector<std::string>{"GNSS altitude (3D track) [3d]", "pressure altitude [pressure]"}));
  // The chart spans both: 380 m to 500 m.
  const auto e = chart_extent(tracks[0], ChartAxis::distance);
  ASSERT_TRUE(e);
  EXPECT_NEAR(e->y_min, 380.0, 1e-3);
  EXPECT_NEAR(e->y_max, 500.0, 1e-3);
}

TEST(ProfileAltitudes, PressureDrawnAndGnssAreTwoLines) {
  // `--igc-altitude pressure`: `ele` is the pressure altitude, the GNSS one 120 m above it.
  const auto tracks = flight(0.0, -120.0);
  EXPECT_EQ(labels(altitude_lines(tracks[0])),
            (std::vector<std::string>{"pressure altitude (3D track) [3d]", "GNSS altitude [gnss]"}));
  const auto e = chart_extent(tracks[0], ChartAxis::distance);
  ASSERT_TRUE(e);
  EXPECT_NEAR(e->y_min, 500.0, 1e-3);
  EXPECT_NEAR(e->y_max, 620.0, 1e-3);
}

TEST(ProfileAltitudes, PressureDrawnWithoutAGnssChannelIsOneLineMarkedSo) {
  EXPECT_EQ(labels(altitude_lines(flight(0.0, kNone)[0])),
            std::vector<std::string>{"pressure altitude (3D track) [3d]"});
}

TEST(ProfileAltitudes, WithoutADrawnAltitudeTheRecordedOnesAreNotIn3d) {
  // `--igc-altitude gnss` on a file without GNSS altitude: the 3D track lies on the ground.
  const auto tracks = flight(0.0, kNone, false);
  EXPECT_EQ(labels(altitude_lines(tracks[0])), std::vector<std::string>{"pressure altitude (not in 3D) [pressure]"});
  const auto e = chart_extent(tracks[0], ChartAxis::distance);
  ASSERT_TRUE(e);
  EXPECT_NEAR(e->y_min, 499.0, 1e-3);  // a flat 500 m, widened by 1 m
  EXPECT_EQ(labels(altitude_lines(flight(0.0, -50.0, false)[0])),
            (std::vector<std::string>{"GNSS altitude (not in 3D) [gnss]", "pressure altitude (not in 3D) [pressure]"}));
}

TEST(ProfileAltitudes, NoAltitudeNoLine) { EXPECT_TRUE(altitude_lines(flight(kNone, kNone, false)[0]).empty()); }

TEST(ProfileAltitudes, TooltipListsTheIgcAltitudesThereAre) {
  const auto both = tooltip_lines(flight(0.0, -120.0)[0], 4);
  ASSERT_EQ(both.size(), 8u);
  EXPECT_EQ(both[1], "altitude: 500 m");
  EXPECT_EQ(both[2], "GNSS altitude: 620 m");
  EXPECT_EQ(both[3], "pressure altitude: 500 m");
  EXPECT_EQ(both[4], "height above ground: \u2014");
  const auto pressure = tooltip_lines(flight(120.0, kNone)[0], 4);
  ASSERT_EQ(pressure.size(), 7u);
  EXPECT_EQ(pressure[2], "pressure altitude: 380 m");
  const auto gnss = tooltip_lines(flight(kNone, 0.0)[0], 4);
  ASSERT_EQ(gnss.size(), 7u);
  EXPECT_EQ(gnss[2], "GNSS altitude: 500 m");
  EXPECT_EQ(tooltip_lines(flight(kNone, kNone)[0], 4).size(), 6u);
}

TEST(ProfileAltitudesRealFile, InterlakenChartShowsBothAltitudesInEveryMode) {
  TRAILRAY_REQUIRE_DATA(path, "igc/goigc_0100_interlaken.igc");
  scene::CollectedDiagnostics diagnostics;
  track::ReadOptions automatic, pressure;
  pressure.igc_altitude = track::ReadOptions::IgcAltitude::Pressure;
  const auto a = viewer_tracks({scene::read_track_file(path.string(), automatic, diagnostics)});
  const auto p = viewer_tracks({scene::read_track_file(path.string(), pressure, diagnostics)});
  EXPECT_EQ(labels(altitude_lines(a[0])),
            (std::vector<std::string>{"GNSS altitude (3D track) [3d]", "pressure altitude [pressure]"}));
  EXPECT_EQ(labels(altitude_lines(p[0])),
            (std::vector<std::string>{"pressure altitude (3D track) [3d]", "GNSS altitude [gnss]"}));
  // Auto's chart reaches down to the lowest pressure altitude, below the lowest GNSS one;
  // pressure's up to the highest GNSS altitude, above the highest pressure one.
  const auto ea = chart_extent(a[0], ChartAxis::distance);
  ASSERT_TRUE(ea);
  EXPECT_LT(ea->y_min, a[0].lowest_altitude() - 50.0);
  const auto ep = chart_extent(p[0], ChartAxis::distance);
  ASSERT_TRUE(ep);
  const double highest_drawn = *std::max_element(p[0].altitude_m.begin(), p[0].altitude_m.end());
  EXPECT_GT(ep->y_max, highest_drawn + 50.0);
}

}  // namespace
}  // namespace trailray::app::view
