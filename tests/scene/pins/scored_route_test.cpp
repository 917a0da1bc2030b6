// The XC score drawn in 3D: the turnpoint pins and the leg routes built from a ScoreResult of a
// constructed flight (a triangle that does not quite close, a straight free flight).
#include <gtest/gtest.h>

#include <cmath>

#include "scene/pins/scored_route.hpp"
#include "track/scoring/score.hpp"

namespace sc = trailray::track::scoring;
namespace scene = trailray::scene;

namespace {

// A 1 Hz flight along straight lines through `corners` (lat, lon), about 50 m between fixes.
std::vector<sc::Fix> fly(const std::vector<std::pair<double, double>>& corners) {
  std::vector<sc::Fix> fixes;
  double t = 1.7e9;
  for (std::size_t k = 0; k + 1 < corners.size(); ++k) {
    const auto [alat, alon] = corners[k];
    const auto [blat, blon] = corners[k + 1];
    const int steps = std::max(1, static_cast<int>(sc::fcc_distance_km(alat, alon, blat, blon) / 0.05));
    for (int s = (k == 0 ? 0 : 1); s <= steps; ++s) {
      const double f = static_cast<double>(s) / steps;
      fixes.push_back(sc::Fix{alat + (blat - alat) * f, alon + (blon - alon) * f, t, 1000, 1000});
      t += 1;
    }
  }
  return fixes;
}

sc::ScoreResult score(const std::vector<sc::Fix>& fixes) {
  sc::ScoreOptions o;
  o.trim = false;
  return sc::score_flight(fixes, *sc::rule_set("xcontest"), o);
}

}  // namespace

TEST(ScoredRoute, ClosedTriangleGivesClosedLegsAGapAndOnePinPerTurnpoint) {
  // Start 1 km from the first corner, end 1.5 km from it: the closing gap is about that apart.
  const auto fixes = fly({{46.009, 7.0}, {46.0, 7.0}, {46.2, 7.1}, {46.0, 7.25}, {46.0, 7.014}});
  const sc::ScoreResult r = score(fixes);
  ASSERT_GE(r.best, 0);
  const sc::TypeResult& best = r.by_type[static_cast<std::size_t>(r.best)];
  ASSERT_GE(best.closing, 0.0) << best.type.name;
  ASSERT_EQ(best.positions.size(), 3u) << best.type.name;

  const trailray::track::TrackFile file = scene::scored_route_file(r, fixes);
  ASSERT_EQ(file.routes.size(), 2u);
  const auto& legs = file.routes[0].points;
  ASSERT_EQ(legs.size(), best.positions.size() + 1);  // closed: back to TP1
  for (std::size_t i = 0; i < best.positions.size(); ++i) {
    EXPECT_DOUBLE_EQ(legs[i].lat, best.positions[i].first);
    EXPECT_DOUBLE_EQ(legs[i].lon, best.positions[i].second);
    EXPECT_FALSE(legs[i].has_ele()) << "the legs lie on the ground";
  }
  EXPECT_DOUBLE_EQ(legs.back().lat, legs.front().lat);
  EXPECT_DOUBLE_EQ(legs.back().lon, legs.front().lon);
  EXPECT_NE(file.routes[0].name.find(best.type.name), std::string::npos) << file.routes[0].name;

  const auto& gap = file.routes[1].points;
  ASSERT_EQ(gap.size(), 2u);
  const sc::Fix& in = fixes[static_cast<std::size_t>(best.closing_in)];
  const sc::Fix& out = fixes[static_cast<std::size_t>(best.closing_out)];
  EXPECT_DOUBLE_EQ(gap[0].lat, in.lat);
  EXPECT_DOUBLE_EQ(gap[1].lon, out.lon);
  EXPECT_NEAR(sc::fcc_distance_km(gap[0].lat, gap[0].lon, gap[1].lat, gap[1].lon), best.closing, 0.01);

  ASSERT_EQ(file.waypoints.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(file.waypoints[i].name.rfind("TP" + std::to_string(i + 1) + " ", 0), 0u) << file.waypoints[i].name;
    EXPECT_DOUBLE_EQ(file.waypoints[i].point.lat, best.positions[i].first);
    EXPECT_DOUBLE_EQ(file.waypoints[i].point.time, fixes[static_cast<std::size_t>(best.points[i])].time);
  }

  // Built as the scene builds files: routes in their own colours, pins placed on the ground.
  scene::CollectedDiagnostics diagnostics;
  scene::TrackStyle style;
  style.color_by = trailray::track::ColorMetric::speed;  // ignored: these are routes
  const scene::ScoredRouteDrawing drawn =
      scene::build_scored_route(r, fixes, "flight.igc", style, {nullptr, 500.0, {}}, {nullptr, 500.0}, diagnostics);
  ASSERT_EQ(drawn.tracks.size(), 2u);
  EXPECT_TRUE(drawn.tracks[0].is_route);
  EXPECT_EQ(drawn.tracks[0].color_srgb, scene::kScoredLegsColor);
  EXPECT_EQ(drawn.tracks[1].color_srgb, scene::kClosingGapColor);
  EXPECT_EQ(drawn.tracks[0].point_count(), 4u);
  const auto& drawn_legs = drawn.tracks[0].cleaned.segments.at(0).points;
  ASSERT_EQ(drawn_legs.size(), 4u);
  for (std::size_t i = 0; i < 3; ++i) {  // the corners where the pins are, not smoothed
    EXPECT_DOUBLE_EQ(drawn_legs[i].lat, best.positions[i].first);
    EXPECT_DOUBLE_EQ(drawn_legs[i].lon, best.positions[i].second);
  }
  ASSERT_EQ(drawn.waypoints.size(), 3u);
  EXPECT_EQ(drawn.waypoints[0].ground_ecef, drawn.waypoints[0].marker_ecef)
      << "no elevation: the pin's marker on the ground";
}

TEST(ScoredRoute, FreeDistanceIsOpenFromStartToFinishWithoutAGap) {
  const auto fixes = fly({{46.0, 7.0}, {46.3, 7.0}});
  const sc::ScoreResult r = score(fixes);
  ASSERT_GE(r.best, 0);
  const sc::TypeResult& best = r.by_type[static_cast<std::size_t>(r.best)];
  ASSERT_LT(best.closing, 0.0) << best.type.name;
  const trailray::track::TrackFile file = scene::scored_route_file(r, fixes);
  ASSERT_EQ(file.routes.size(), 1u);
  EXPECT_EQ(file.routes[0].points.size(), best.positions.size());
  ASSERT_EQ(file.waypoints.size(), best.positions.size());
  EXPECT_EQ(file.waypoints.front().name.rfind("start ", 0), 0u) << file.waypoints.front().name;
  EXPECT_EQ(file.waypoints.back().name, "finish");
}

TEST(ScoredRoute, NothingScoredGivesNothingToDraw) {
  sc::ScoreResult none;
  none.rules = "xcontest";
  const trailray::track::TrackFile file = scene::scored_route_file(none, {});
  EXPECT_TRUE(file.routes.empty());
  EXPECT_TRUE(file.waypoints.empty());
}
