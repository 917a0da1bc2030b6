// Neighbour counts (the density view and the thermal map) on synthetic tracks whose distances are
// known: parallel lines, a crossing, a track passing itself, the radius' edge, sparse fixes, the
// poles and the antimeridian; and against a brute force on random walks.
#include "track/density.hpp"

#include <gtest/gtest.h>

#include <GeographicLib/Geodesic.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include <glm/glm.hpp>

#include "geo/wgs84.hpp"
#include "track/track_builders.hpp"
#include "track/two_threads.hpp"

namespace trailray::track {
namespace {

using test::kLat0;
using test::kLon0;

// A point `east` metres east of the point `north` metres north of (kLat0, kLon0).
TrackPoint at(double north, double east) {
  TrackPoint p;
  const auto& g = GeographicLib::Geodesic::WGS84();
  double lat = 0, lon = 0;
  g.Direct(kLat0, kLon0, 0.0, north, lat, lon);
  g.Direct(lat, lon, 90.0, east, p.lat, p.lon);
  return p;
}

TrackPoint place(double lat, double lon) {
  TrackPoint p;
  p.lat = lat;
  p.lon = lon;
  return p;
}

// A straight line northwards from `from` to `to` metres, `east` metres east, a point every `step`.
std::vector<TrackPoint> northwards(double east, double from = 0, double to = 2000, double step = 10) {
  std::vector<TrackPoint> out;
  for (double s = from; s <= to + 1e-9; s += step) out.push_back(at(s, east));
  return out;
}

NeighbourSource source_of(const std::vector<TrackPoint>& points) { return {{PointLine(points)}}; }

std::vector<float> counts_along(const NeighbourIndex& index, const std::vector<TrackPoint>& points) {
  std::vector<float> out(points.size());
  index.count_near(points, out);
  return out;
}

TEST(NeighbourCounts, ParallelLinesCountThoseWithinTheRadiusAndThemselves) {
  // A at 0 m, B 60 m east, C 130 m east: A-B 60, B-C 70, A-C 130 (over 100).
  const auto a = northwards(0), b = northwards(60), c = northwards(130);
  const std::vector<NeighbourSource> sources{source_of(a), source_of(b), source_of(c)};
  const NeighbourIndex index(sources, 100.0);
  EXPECT_EQ(index.source_count(), 3u);
  for (float v : counts_along(index, a)) EXPECT_EQ(v, 2.0f);
  for (float v : counts_along(index, b)) EXPECT_EQ(v, 3.0f);
  for (float v : counts_along(index, c)) EXPECT_EQ(v, 2.0f);
  // A smaller radius: each alone.
  const NeighbourIndex tight(sources, 50.0);
  for (const auto* line : {&a, &b, &c})
    for (float v : counts_along(tight, *line)) EXPECT_EQ(v, 1.0f);
}

TEST(NeighbourCounts, CrossingTracksCountTwoOnlyNearTheCrossing) {
  // A northwards through (1000, 0); B eastwards through it.
  const auto a = northwards(0);
  std::vector<TrackPoint> b;
  for (double e = -1000; e <= 1000; e += 10) b.push_back(at(1000, e));
  const std::vector<NeighbourSource> sources{source_of(a), source_of(b)};
  const NeighbourIndex index(sources, 100.0);
  const auto counts = counts_along(index, a);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double north = 10.0 * static_cast<double>(i);
    const double off = std::abs(north - 1000.0);
    if (off < 99.0) {
      EXPECT_EQ(counts[i], 2.0f) << north;
    } else if (off > 101.0) {
      EXPECT_EQ(counts[i], 1.0f) << north;
    }
  }
}

TEST(NeighbourCounts, ATrackPassingItselfCountsOnce) {
  // Out and back three times along the same line, 20 m apart, and a second line of the same
  // source beside it: still one source.
  std::vector<TrackPoint> zigzag;
  for (int leg = 0; leg < 6; ++leg) {
    const double east = 20.0 * leg;
    const auto line = northwards(east);
    if (leg % 2 == 0)
      zigzag.insert(zigzag.end(), line.begin(), line.end());
    else
      zigzag.insert(zigzag.end(), line.rbegin(), line.rend());
  }
  const auto beside = northwards(30);
  const std::vector<NeighbourSource> sources{{{PointLine(zigzag), PointLine(beside)}}};
  const NeighbourIndex index(sources, 100.0);
  for (float v : counts_along(index, zigzag)) EXPECT_EQ(v, 1.0f);
}

TEST(NeighbourCounts, TheRadiusIsHorizontalDistanceToTheLine) {
  const auto a = northwards(0, 0, 2000, 10);
  const std::vector<NeighbourSource> sources{source_of(a)};
  const NeighbourIndex index(sources, 100.0);
  EXPECT_EQ(index.count_near(at(1000, 99.5).lat, at(1000, 99.5).lon), 1u);
  EXPECT_EQ(index.count_near(at(1000, 100.5).lat, at(1000, 100.5).lon), 0u);
  EXPECT_EQ(index.count_near(at(1000, -99.5).lat, at(1000, -99.5).lon), 1u);
  // Beyond the end: the distance to the last point.
  EXPECT_EQ(index.count_near(at(2099.5, 0).lat, at(2099.5, 0).lon), 1u);
  EXPECT_EQ(index.count_near(at(2100.5, 0).lat, at(2100.5, 0).lon), 0u);
  // Height plays no part: a point 3 km above the line is on it.
  TrackPoint high = at(1000, 50);
  high.ele = 3000;
  float v = 0;
  index.count_near(PointLine(&high, 1), std::span<float>(&v, 1));
  EXPECT_EQ(v, 1.0f);
}

TEST(NeighbourCounts, SparseFixesCountByTheLineBetweenThem) {
  // Two fixes 2 km apart: the line passes 90 m from the middle point, both fixes 1 km away.
  const std::vector<TrackPoint> sparse{at(0, 90), at(2000, 90)};
  const std::vector<NeighbourSource> sources{source_of(sparse)};
  const NeighbourIndex index(sources, 100.0);
  EXPECT_EQ(index.count_near(at(1000, 0).lat, at(1000, 0).lon), 1u);
  // A step beyond max(10 km, 10 r) is a gap: only its ends count.
  const std::vector<TrackPoint> gap{at(0, 0), at(12000, 0)};
  const std::vector<NeighbourSource> gapped{source_of(gap)};
  const NeighbourIndex with_gap(gapped, 100.0);
  EXPECT_EQ(with_gap.count_near(at(6000, 0).lat, at(6000, 0).lon), 0u);
  EXPECT_EQ(with_gap.count_near(at(12000, 50).lat, at(12000, 50).lon), 1u);
  // ... but within 10 r with a radius of 2 km it is a line.
  const NeighbourIndex wide(gapped, 2000.0);
  EXPECT_EQ(wide.count_near(at(6000, 1500).lat, at(6000, 1500).lon), 1u);
}

TEST(NeighbourCounts, NoSeamAtThePolesOrTheAntimeridian) {
  // 100 m of latitude is 0.000899 degrees; at the equator 100 m of longitude 0.000898.
  const std::vector<TrackPoint> pole{place(89.9996, 10.0)};     // about 45 m from the pole
  const std::vector<TrackPoint> across{place(89.9996, 190.0)};  // the other side: about 90 m away
  const std::vector<NeighbourSource> sources{source_of(pole), source_of(across)};
  const NeighbourIndex index(sources, 100.0);
  EXPECT_EQ(index.count_near(90.0, 0.0), 2u);
  EXPECT_EQ(index.count_near(90.0, 123.0), 2u);  // the pole is one place whatever its longitude
  EXPECT_EQ(index.count_near(89.9996, 10.0), 2u);
  EXPECT_EQ(index.count_near(89.999, 100.0), 0u);  // 110 m from the pole, farther from both

  const std::vector<TrackPoint> east{place(0.0, 179.9996), place(0.05, 179.9996)};
  const std::vector<TrackPoint> west{place(0.0, -179.9996), place(0.05, -179.9996)};
  const std::vector<NeighbourSource> sides{source_of(east), source_of(west)};
  const NeighbourIndex antimeridian(sides, 100.0);  // the lines are 89 m apart across it
  EXPECT_EQ(antimeridian.count_near(0.02, 180.0), 2u);
  EXPECT_EQ(antimeridian.count_near(0.02, -179.9996), 2u);
  EXPECT_EQ(antimeridian.count_near(0.02, 179.999), 1u);  // 67 m from east, 156 m from west
  EXPECT_EQ(antimeridian.count_near(0.02, 179.99), 0u);
}

TEST(NeighbourCounts, InvalidPointsHaveNoCountAndBreakTheirLine) {
  std::vector<TrackPoint> line = northwards(0, 0, 400, 100);  // 0, 100, 200, 300, 400 m
  line[2].lat = std::numeric_limits<double>::quiet_NaN();
  const std::vector<NeighbourSource> sources{source_of(line)};
  const NeighbourIndex index(sources, 30.0);
  // Without the point at 200 m the line stops at 100 m and starts again at 300.
  EXPECT_EQ(index.count_near(at(150, 0).lat, at(150, 0).lon), 0u);
  EXPECT_EQ(index.count_near(at(120, 0).lat, at(120, 0).lon), 1u);
  EXPECT_EQ(index.count_near(at(350, 0).lat, at(350, 0).lon), 1u);
  const auto counts = counts_along(index, line);
  EXPECT_TRUE(std::isnan(counts[2]));
  EXPECT_EQ(counts[0], 1.0f);
  EXPECT_EQ(index.count_near(91.0, 0.0), 0u);
}

TEST(NeighbourCounts, RadiusOutOfRangeOrShapesThatDoNotMatchAreRefused) {
  const std::vector<NeighbourSource> none;
  EXPECT_THROW(NeighbourIndex(none, 0.5), std::invalid_argument);
  EXPECT_THROW(NeighbourIndex(none, 200000.0), std::invalid_argument);
  EXPECT_THROW(NeighbourIndex(none, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
  const NeighbourIndex empty(none, 100.0);
  EXPECT_EQ(empty.count_near(kLat0, kLon0), 0u);
  const auto a = northwards(0, 0, 100, 10);
  std::vector<float> short_out(3);
  EXPECT_THROW(empty.count_near(a, short_out), std::invalid_argument);
}

// The chord between two places on the ellipsoid, and from a place to a segment, in doubles.
glm::dvec3 surface(const TrackPoint& p) { return geo::ecef_from_geodetic(p.lat, p.lon, 0.0); }
double to_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 d = b - a;
  const double l2 = glm::dot(d, d);
  const double t = l2 > 0 ? std::clamp(glm::dot(p - a, d) / l2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * d));
}

TEST(NeighbourCounts, RandomWalksAgreeWithABruteForce) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> start(-1500.0, 1500.0), heading(0.0, 360.0), step(5.0, 400.0);
  std::vector<std::vector<TrackPoint>> walks(40);
  for (auto& w : walks) {
    double n = start(rng), e = start(rng), h = heading(rng);
    for (int i = 0; i < 60; ++i) {
      w.push_back(at(n, e));
      h += heading(rng) / 8.0 - 22.5;
      const double s = step(rng);
      n += s * std::cos(h * std::numbers::pi / 180.0);
      e += s * std::sin(h * std::numbers::pi / 180.0);
    }
  }
  std::vector<NeighbourSource> sources;
  for (const auto& w : walks) sources.push_back(source_of(w));
  const double r = 150.0;
  // On two threads, through the ParallelFor.
  const ParallelFor two_threads = test::two_threads;
  std::vector<std::vector<PointLine>> targets;
  for (const auto& w : walks) targets.push_back({PointLine(w)});
  const auto counts = neighbour_counts(sources, targets, r, two_threads);
  std::vector<std::vector<glm::dvec3>> ecef(walks.size());
  for (std::size_t t = 0; t < walks.size(); ++t)
    for (const TrackPoint& p : walks[t]) ecef[t].push_back(surface(p));
  std::size_t checked = 0, above_one = 0;
  for (std::size_t t = 0; t < walks.size(); ++t) {
    for (std::size_t i = 0; i < walks[t].size(); ++i) {
      const glm::dvec3& p = ecef[t][i];
      std::size_t expected = 0;
      bool on_edge = false;
      for (const auto& w : ecef) {
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j + 1 < w.size(); ++j) nearest = std::min(nearest, to_segment(p, w[j], w[j + 1]));
        on_edge = on_edge || std::abs(nearest - r) < 0.05;
        expected += nearest <= r ? 1 : 0;
      }
      if (on_edge) continue;
      EXPECT_EQ(counts[t][0][i], static_cast<float>(expected)) << "walk " << t << " point " << i;
      ++checked;
      above_one += expected > 1 ? 1 : 0;
    }
  }
  EXPECT_GT(checked, 2000u);
  EXPECT_GT(above_one, 200u);  // the walks do meet: the test is not only of lone points
}

}  // namespace
}  // namespace trailray::track
