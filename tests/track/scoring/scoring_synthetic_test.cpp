// XC scoring on constructed flights whose optimum is known: a triangle, an out-and-return,
// closing-limit and FAI 28 % edges, and random small flights checked against brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "track/scoring/score.hpp"

namespace sc = trailray::track::scoring;

namespace {

struct LatLon {
  double lat, lon;
};

// A 1 Hz flight along straight lines through `corners`, about `step_km` between fixes.
std::vector<sc::Fix> fly(const std::vector<LatLon>& corners, double step_km = 0.05) {
  std::vector<sc::Fix> fixes;
  double t = 1.7e9;
  for (std::size_t k = 0; k + 1 < corners.size(); ++k) {
    const LatLon a = corners[k], b = corners[k + 1];
    const double d = sc::fcc_distance_km(a.lat, a.lon, b.lat, b.lon);
    const int steps = std::max(1, static_cast<int>(d / step_km));
    for (int s = (k == 0 ? 0 : 1); s <= steps; ++s) {
      const double f = static_cast<double>(s) / steps;
      fixes.push_back(sc::Fix{a.lat + (b.lat - a.lat) * f, a.lon + (b.lon - a.lon) * f, t, 1000, 1000});
      t += 1;
    }
  }
  return fixes;
}

sc::ScoreResult score(const std::vector<sc::Fix>& fixes, const std::string& rules, bool all_types = true,
                      sc::DistanceModel model = sc::DistanceModel::Fcc) {
  sc::ScoreOptions o;
  o.trim = false;
  o.all_types = all_types;
  o.model = model;
  return sc::score_flight(fixes, *sc::rule_set(rules), o);
}

const sc::TypeResult& type_named(const sc::ScoreResult& r, const std::string& name) {
  for (const auto& t : r.by_type)
    if (t.type.name == name) return t;
  throw std::runtime_error("no type " + name);
}

double leg(const LatLon& a, const LatLon& b) { return sc::round2(sc::fcc_distance_km(a.lat, a.lon, b.lat, b.lon)); }

// Brute force of one type over every choice of fixes (small flights only), written from the rules
// independently of the optimiser.
double brute_force(const std::vector<sc::Fix>& f, const sc::FlightType& t, sc::DistanceModel model) {
  const sc::Metric m(f, model);
  const int n = static_cast<int>(f.size());
  auto d = [&](int i, int j) { return sc::round2(m.distance(i, j)); };
  auto closing = [&](int a, int c) {
    double best = 1e300;
    for (int p = 0; p <= a; ++p)
      for (int q = c; q < n; ++q) best = std::min(best, m.distance(p, q));
    return sc::round2(best);
  };
  double best = -1;
  if (t.shape == sc::Shape::FreeDistance) {
    for (int s = 0; s < n; ++s)
      for (int a = s; a < n; ++a)
        for (int b = a; b < n; ++b)
          for (int c = b; c < n; ++c)
            for (int e = c; e < n; ++e) {
              const double dist = sc::final_round(t, d(s, a) + d(a, b) + d(b, c) + d(c, e));
              if (dist >= t.min_distance) best = std::max(best, sc::final_round(t, dist * t.multiplier));
            }
    return best;
  }
  for (int a = 0; a < n; ++a)
    for (int b = a; b < n; ++b)
      for (int c = b; c < n; ++c) {
        std::vector<double> legs = t.shape == sc::Shape::OutAndReturn2 ? std::vector<double>{d(a, c), d(a, c)}
                                                                       : std::vector<double>{d(a, b), d(b, c), d(c, a)};
        if (t.shape == sc::Shape::OutAndReturn2 && b != a) continue;
        const double dist = sc::final_round(t, legs[0] + legs[1] + (legs.size() > 2 ? legs[2] : 0.0));
        if (dist <= 0 || dist < t.min_distance) continue;
        bool ok = true;
        for (double l : legs) {
          if (t.min_side > 0 && l < t.min_side * dist) ok = false;
          if (t.max_side > 0 && l > t.max_side * dist) ok = false;
        }
        if (!ok) continue;
        const double cd = closing(a, c);
        if (cd > sc::closing_limit(t, dist)) continue;
        best = std::max(best, sc::final_round(t, (dist - sc::closing_penalty(t, cd)) * t.multiplier));
      }
  return best;
}

}  // namespace

TEST(ScoringSynthetic, ClosedFaiTriangleScoresItsCorners) {
  // Nearly equilateral, about 10 km sides, closed exactly at the start.
  const LatLon a{46.0, 7.0}, b{46.0, 7.13}, c{46.078, 7.065};
  const auto fixes = fly({a, b, c, a});
  const auto r = score(fixes, "xcontest");
  ASSERT_GE(r.best, 0);
  const auto& best = r.by_type[static_cast<std::size_t>(r.best)];
  EXPECT_EQ(best.type.name, "Closed FAI Triangle");
  const double p = leg(a, b) + leg(b, c) + leg(c, a);
  EXPECT_NEAR(best.distance, p, 1e-9);
  EXPECT_NEAR(best.closing, 0.0, 1e-9);
  EXPECT_NEAR(best.score, sc::round2(p * 1.6), 1e-9);
  // The turnpoints are the corners, in flight order up to where the loop starts.
  const std::vector<LatLon> corners{a, b, c};
  for (const LatLon& corner : corners) {
    double nearest = 1e9;
    for (const auto& tp : best.positions)
      nearest = std::min(nearest, sc::fcc_distance_km(tp.first, tp.second, corner.lat, corner.lon));
    EXPECT_LT(nearest, 0.03);
  }
  EXPECT_TRUE(best.exact);
}

TEST(ScoringSynthetic, XcLeagueOutAndReturn) {
  // 20 km out and back: an out-and-return of 40 km (x2.0 from 35 km), more than its free distance.
  const LatLon a{52.0, -1.0}, b{52.18, -1.0};
  const auto r = score(fly({a, b, a}, 0.1), "xcleague");
  ASSERT_GE(r.best, 0);
  const auto& best = r.by_type[static_cast<std::size_t>(r.best)];
  EXPECT_EQ(best.type.name, "Out-and-Return Distance >=35km");
  EXPECT_EQ(best.type.code, "oar");
  const double dist = sc::round1(2 * leg(a, b));
  EXPECT_NEAR(best.distance, dist, 1e-9);
  EXPECT_NEAR(best.score, sc::round1(dist * 2.0), 1e-9);
  EXPECT_NEAR(type_named(r, "Turnpoint Flight").score, dist, 1e-9);
}

TEST(ScoringSynthetic, FfvlClosingWithinTheFreeThreeKilometres) {
  // The flight ends 2.9 km from its start: inside FFVL's 3 km, so no penalty on the full triangle.
  const LatLon a{45.0, 6.0}, b{45.0, 6.16}, c{45.11, 6.08}, end{45.0 + 2.9 / 111.13, 6.0};
  const auto r = score(fly({a, b, c, end}), "ffvl");
  const auto& flat = type_named(r, "Triangle plat");
  ASSERT_TRUE(flat.valid);
  EXPECT_NEAR(flat.penalty, 0.0, 1e-9);
  EXPECT_GT(flat.closing, 2.8);
  EXPECT_LE(flat.closing, 3.0);
  EXPECT_NEAR(flat.distance, leg(a, b) + leg(b, c) + leg(c, a), 0.03);
}

TEST(ScoringSynthetic, XcontestClosedTriangleLimitIsFivePercent) {
  // About 37 km of triangle, a gap of 1.5 km (4 %) against one of 2.5 km (7 %): the closed types
  // take the full triangle in the first case; in the second no triangle of this flight closes
  // within 5 % (the legs near the start and the end stay about 2.5 km apart), while the free
  // triangle (20 %) still does, with the whole closing as its penalty.
  const LatLon a{45.0, 6.0}, b{45.0, 6.16}, c{45.11, 6.08};
  for (double gap : {1.5, 2.5}) {
    SCOPED_TRACE(gap);
    const LatLon end{45.0 + gap / 111.13, 6.0};
    const auto r = score(fly({a, b, c, end}), "xcontest");
    const auto& closed = type_named(r, "Closed Free Triangle");
    const double full = leg(a, b) + leg(b, c) + leg(c, a);
    if (gap < 2) {
      ASSERT_TRUE(closed.valid);
      EXPECT_LE(closed.closing, sc::round2(0.05 * closed.distance) + 1e-9);
      EXPECT_NEAR(closed.penalty, closed.closing, 1e-9);
      EXPECT_NEAR(closed.distance, full, 0.03);
    } else {
      EXPECT_FALSE(closed.valid);
    }
    const auto& open = type_named(r, "Free Triangle");
    ASSERT_TRUE(open.valid);
    EXPECT_NEAR(open.distance, full, 0.03);
    EXPECT_NEAR(open.closing, gap, 0.02);
    EXPECT_NEAR(open.penalty, open.closing, 1e-9);
    EXPECT_NEAR(open.score, sc::round2((open.distance - open.penalty) * 1.2), 1e-9);
  }
}

TEST(ScoringSynthetic, FaiTwentyEightPercentEdge) {
  // Isosceles triangles whose short side is 29 % or 27 % of the perimeter.
  for (double share : {0.29, 0.27}) {
    SCOPED_TRACE(share);
    const double base = 10.0 * share / (1 - share) * 2 / 2;  // km: short side, the two others 5 km each
    const double half = base / 2 / 111.13;                   // degrees of latitude
    const double h = std::sqrt(25.0 - base * base / 4) / (111.13 * std::cos(46.0 * M_PI / 180));
    const LatLon a{46.0 - half, 7.0}, b{46.0 + half, 7.0}, c{46.0, 7.0 + h};
    const auto r = score(fly({a, b, c, a}, 0.02), "ffvl");
    const auto& fai = type_named(r, "Triangle FAI");
    const double full = leg(a, b) + leg(b, c) + leg(c, a);
    if (share > 0.28) {
      ASSERT_TRUE(fai.valid);
      EXPECT_NEAR(fai.distance, full, 0.03);
    } else if (fai.valid) {
      EXPECT_LT(fai.distance, full - 0.05);
    }
    if (fai.valid) {
      for (double l : fai.legs) EXPECT_GE(l, 0.28 * fai.distance - 1e-9);
    }
  }
}

TEST(ScoringSynthetic, RandomFlightsMatchBruteForce) {
  std::mt19937 rng(15);
  std::normal_distribution<double> step(0.0, 0.004);
  for (int flight = 0; flight < 6; ++flight) {
    std::vector<sc::Fix> fixes;
    double lat = 45.5, lon = 6.5, dlat = 0, dlon = 0;
    const int n = 24;
    for (int i = 0; i < n; ++i) {
      dlat = 0.7 * dlat + step(rng);
      dlon = 0.7 * dlon + step(rng);
      lat += dlat;
      lon += dlon;
      fixes.push_back(sc::Fix{lat, lon, 1.7e9 + i, 1000, 1000});
    }
    for (const char* rules : {"xcontest", "ffvl", "xcleague", "fai"})
      for (auto model : {sc::DistanceModel::Fcc, sc::DistanceModel::Geodesic}) {
        SCOPED_TRACE(std::string(rules) + " flight " + std::to_string(flight));
        const auto r = score(fixes, rules, true, model);
        for (const auto& t : r.by_type) {
          SCOPED_TRACE(t.type.name);
          const double expected = brute_force(fixes, t.type, model);
          if (expected < 0) {
            EXPECT_FALSE(t.valid && t.score > 0);
          } else {
            ASSERT_TRUE(t.valid);
            EXPECT_NEAR(t.score, expected, 1e-9);
          }
        }
      }
  }
}

TEST(ScoringSynthetic, DefaultSearchKeepsTheBestExact) {
  // Without all_types the best type is the same and exact; other types may stop early.
  const LatLon a{46.0, 7.0}, b{46.0, 7.13}, c{46.078, 7.065};
  const auto fixes = fly({a, b, c, a});
  const auto all = score(fixes, "xcontest", true);
  const auto fast = score(fixes, "xcontest", false);
  ASSERT_EQ(all.best, fast.best);
  EXPECT_DOUBLE_EQ(all.by_type[static_cast<std::size_t>(all.best)].score,
                   fast.by_type[static_cast<std::size_t>(fast.best)].score);
  for (std::size_t i = 0; i < fast.by_type.size(); ++i)
    if (fast.by_type[i].exact && fast.by_type[i].valid) {
      EXPECT_DOUBLE_EQ(fast.by_type[i].score, all.by_type[i].score);
    }
}

TEST(ScoringSynthetic, FaiCylindersShortenEveryLeg) {
  const LatLon a{46.0, 7.0}, b{46.0, 7.13}, c{46.078, 7.065};
  const auto fixes = fly({a, b, c, a});
  const auto plain = score(fixes, "fai");
  const auto cyl = score(fixes, "fai-cylinders");
  const auto& p = plain.by_type[static_cast<std::size_t>(plain.best)];
  const auto& q = cyl.by_type[static_cast<std::size_t>(cyl.best)];
  EXPECT_EQ(p.type.name, q.type.name);
  EXPECT_LT(q.distance, p.distance);
  // Moving each corner 400 m outwards and taking 800 m off each leg roughly cancels on a triangle
  // (the corners move apart by about 2 x 0.4 x cos 30 degrees per leg): within 1 km in all.
  EXPECT_NEAR(q.distance, p.distance, 1.0);
}

TEST(ScoringSynthetic, FaiOutAndReturnAroundOneTurnpoint) {
  const LatLon a{46.0, 7.0}, b{46.09, 7.0};  // 10 km out, back to the start
  const auto r = score(fly({a, b, a}, 0.05), "fai-oar");
  ASSERT_GE(r.best, 0);
  const auto& oar = r.by_type[0];
  EXPECT_EQ(oar.type.code, "oar");
  EXPECT_NEAR(oar.distance, sc::round1(2 * leg(a, b)), 0.1 + 1e-9);
  EXPECT_LE(oar.closing, 0.8);
}
