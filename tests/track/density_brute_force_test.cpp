// Neighbour counts against a brute force that measures every point against every segment of every
// source, on sets made to reach each of the index's shortcuts: many sources crossing one cell (the
// cell's points split again and again, sources decided for whole boxes), points a centimetre
// inside and outside the radius, many points at one place, gaps, invalid points, lone fixes, the
// poles and the antimeridian. The brute force follows density.hpp's rules on its own: whole-cm
// ECEF places, a line ends at an invalid point or a step over max(10 km, 10 r).
#include <gtest/gtest.h>

#include <GeographicLib/Geodesic.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "geo/wgs84.hpp"
#include "track/density.hpp"
#include "track/two_threads.hpp"

namespace trailray::track {
namespace {

TrackPoint place(double lat, double lon) {
  TrackPoint p;
  p.lat = lat;
  p.lon = lon;
  return p;
}

// `east` metres east of the point `north` metres north of (lat, lon).
TrackPoint offset(double lat, double lon, double north, double east) {
  const auto& g = GeographicLib::Geodesic::WGS84();
  double la = 0, lo = 0;
  TrackPoint p;
  g.Direct(lat, lon, 0.0, north, la, lo);
  g.Direct(la, lo, 90.0, east, p.lat, p.lon);
  return p;
}

bool valid(const TrackPoint& p) { return std::isfinite(p.lat) && std::isfinite(p.lon) && std::abs(p.lat) <= 90.0; }

// The place in whole centimetres, as the index keeps it.
glm::dvec3 cm(const TrackPoint& p) {
  const glm::dvec3 e = geo::ecef_from_geodetic(p.lat, p.lon, 0.0) * 100.0;
  return {std::round(e.x), std::round(e.y), std::round(e.z)};
}

double to_segment_cm(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 d = b - a;
  const double l2 = glm::dot(d, d);
  const double t = l2 > 0 ? std::clamp(glm::dot(p - a, d) / l2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * d));
}

// A source's lines as segments (a lone point: a segment of length 0).
std::vector<std::pair<glm::dvec3, glm::dvec3>> segments_of(const NeighbourSource& source, double r_m) {
  const double max_step = std::max(1e6, 10.0 * r_m * 100.0);
  std::vector<std::pair<glm::dvec3, glm::dvec3>> out;
  for (const PointLine& line : source.lines) {
    std::vector<glm::dvec3> run;
    const auto close = [&] {
      if (run.size() == 1) out.emplace_back(run[0], run[0]);
      for (std::size_t i = 0; i + 1 < run.size(); ++i) out.emplace_back(run[i], run[i + 1]);
      run.clear();
    };
    for (const TrackPoint& p : line) {
      if (!valid(p)) {
        close();
        continue;
      }
      const glm::dvec3 c = cm(p);
      if (!run.empty() && glm::length(c - run.back()) > max_step) close();
      run.push_back(c);
    }
    close();
  }
  return out;
}

struct Expected {
  std::vector<float> counts;
  std::size_t on_edge = 0;  // points within a micrometre of the radius: not compared
};

Expected brute_force(const std::vector<NeighbourSource>& sources, const std::vector<TrackPoint>& targets, double r_m) {
  std::vector<std::vector<std::pair<glm::dvec3, glm::dvec3>>> segments;
  for (const NeighbourSource& s : sources) segments.push_back(segments_of(s, r_m));
  const double r = r_m * 100.0;
  Expected out;
  for (const TrackPoint& t : targets) {
    if (!valid(t)) {
      out.counts.push_back(std::numeric_limits<float>::quiet_NaN());
      continue;
    }
    const glm::dvec3 p = cm(t);
    std::size_t count = 0;
    bool edge = false;
    for (const auto& source : segments) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& [a, b] : source) nearest = std::min(nearest, to_segment_cm(p, a, b));
      edge = edge || std::abs(nearest - r) < 1e-4;
      count += nearest <= r ? 1 : 0;
    }
    out.on_edge += edge ? 1 : 0;
    out.counts.push_back(edge ? -1.0f : static_cast<float>(count));
  }
  return out;
}

const ParallelFor two_threads = test::two_threads;

// Every way of asking (one line at a time, all lines at once on two threads) against the brute
// force; the targets are split into lines of 37 points. Returns the points compared.
std::size_t expect_brute_force(const std::vector<NeighbourSource>& sources, const std::vector<TrackPoint>& targets,
                               double r_m) {
  const Expected expected = brute_force(sources, targets, r_m);
  EXPECT_LE(expected.on_edge, targets.size() / 100);
  std::vector<std::vector<PointLine>> lines;
  for (std::size_t i = 0; i < targets.size(); i += 37)
    lines.push_back({PointLine(targets.data() + i, std::min<std::size_t>(37, targets.size() - i))});
  const auto all = neighbour_counts(sources, lines, r_m, two_threads);
  const NeighbourIndex index(sources, r_m);
  std::size_t compared = 0;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    std::vector<float> one(lines[l][0].size());
    index.count_near(lines[l][0], one);
    for (std::size_t i = 0; i < one.size(); ++i) {
      const float want = expected.counts[l * 37 + i];
      if (want < 0) continue;
      if (std::isnan(want)) {
        EXPECT_TRUE(std::isnan(one[i]) && std::isnan(all[l][0][i])) << "point " << l * 37 + i;
        continue;
      }
      EXPECT_EQ(all[l][0][i], want) << "point " << l * 37 + i << " at " << targets[l * 37 + i].lat << ", "
                                    << targets[l * 37 + i].lon;
      EXPECT_EQ(one[i], want) << "point " << l * 37 + i;
      ++compared;
    }
  }
  return compared;
}

// Random walks from places drawn around (lat, lon) within `spread` metres, a step of `min_step`
// to `max_step`, the heading turning up to `turn` degrees a fix.
std::vector<std::vector<TrackPoint>> walks(std::mt19937& rng, int count, int points, double lat, double lon,
                                           double spread, double min_step, double max_step, double turn) {
  std::uniform_real_distribution<double> start(-spread, spread), heading(0.0, 360.0), step(min_step, max_step),
      bend(-turn, turn);
  std::vector<std::vector<TrackPoint>> out(static_cast<std::size_t>(count));
  for (auto& w : out) {
    double n = start(rng), e = start(rng), h = heading(rng);
    for (int i = 0; i < points; ++i) {
      w.push_back(offset(lat, lon, n, e));
      h += bend(rng);
      const double s = step(rng);
      n += s * std::cos(h * std::numbers::pi / 180.0);
      e += s * std::sin(h * std::numbers::pi / 180.0);
    }
  }
  return out;
}

std::vector<NeighbourSource> sources_of(const std::vector<std::vector<TrackPoint>>& tracks) {
  std::vector<NeighbourSource> out;
  for (const auto& t : tracks) out.push_back({{PointLine(t)}});
  return out;
}

std::vector<TrackPoint> all_points(const std::vector<std::vector<TrackPoint>>& tracks) {
  std::vector<TrackPoint> out;
  for (const auto& t : tracks) out.insert(out.end(), t.begin(), t.end());
  return out;
}

TEST(NeighbourCountsBruteForce, ManySourcesThroughOnePlace) {
  // 300 walks from within 60 m of one place: hundreds of sources in the cells there, most points
  // counting most of them, and the cells' boxes split down to single points.
  std::mt19937 rng(1);
  const auto tracks = walks(rng, 300, 40, 46.68, 7.86, 60.0, 1.0, 40.0, 40.0);
  for (const double r : {30.0, 100.0}) {
    EXPECT_GT(expect_brute_force(sources_of(tracks), all_points(tracks), r), 11000u);
  }
  // The counts are high: the test is of dense places, not of lone points.
  const std::vector<std::vector<PointLine>> first{{PointLine(tracks[0])}};
  const auto counts = neighbour_counts(sources_of(tracks), first, 100.0);
  EXPECT_GT(counts[0][0][0], 150.0f);
}

TEST(NeighbourCountsBruteForce, SparseAndMixedSteps) {
  std::mt19937 rng(2);
  auto tracks = walks(rng, 60, 80, 47.37, 8.54, 3000.0, 5.0, 600.0, 60.0);
  // Invalid points and lone fixes among them.
  tracks[3][10].lat = std::numeric_limits<double>::quiet_NaN();
  tracks[4][20].lat = 95.0;
  tracks[5][30].lon = std::numeric_limits<double>::infinity();
  tracks[6][31].lat = std::numeric_limits<double>::quiet_NaN();  // leaves point 30 of track 6 alone
  tracks[6][29].lat = std::numeric_limits<double>::quiet_NaN();
  for (const double r : {15.0, 150.0, 1500.0})
    EXPECT_GT(expect_brute_force(sources_of(tracks), all_points(tracks), r), 4000u);
}

TEST(NeighbourCountsBruteForce, ACentimetreInsideAndOutsideTheRadius) {
  // 50 sources along meridians 7 m apart, fixes 9 m apart; the targets a centimetre either side
  // of r from each line, beside its fixes and between them, 5 targets at each place: boxes of
  // points that all sit on the radius' edge.
  const double lat = 46.0, lon = 7.0, r = 100.0;
  std::vector<std::vector<TrackPoint>> lines(50);
  for (std::size_t k = 0; k < lines.size(); ++k)
    for (int i = 0; i < 40; ++i) lines[k].push_back(offset(lat, lon, 9.0 * i, 7.0 * static_cast<double>(k)));
  std::vector<TrackPoint> targets;
  for (std::size_t k = 0; k < lines.size(); k += 7)
    for (const double north : {90.0, 94.5, 180.0, 184.5})
      for (const double side : {-1.0, 1.0})
        for (const double d : {-0.01, 0.01})
          for (int copy = 0; copy < 5; ++copy)
            targets.push_back(offset(lat, lon, north, 7.0 * static_cast<double>(k) + side * (r + d)));
  const auto sources = sources_of(lines);
  const Expected expected = brute_force(sources, targets, r);
  // The brute force sees both sides: a target 1 cm inside counts its line, 1 cm outside does not.
  EXPECT_EQ(expected.on_edge, 0u);
  for (std::size_t i = 0; i + 9 < targets.size(); i += 10) EXPECT_EQ(expected.counts[i], expected.counts[i + 5] + 1);
  EXPECT_EQ(expect_brute_force(sources, targets, r), targets.size());
  const NeighbourIndex one({&sources[0], 1}, r);
  const TrackPoint inside = offset(lat, lon, 94.5, r - 0.01), outside = offset(lat, lon, 94.5, r + 0.01);
  EXPECT_EQ(one.count_near(inside.lat, inside.lon), 1u);
  EXPECT_EQ(one.count_near(outside.lat, outside.lon), 0u);
}

TEST(NeighbourCountsBruteForce, ManyPointsAtOnePlaceAndGaps) {
  // Every walk starts at one take-off (thousands of targets at one place), and some jump over
  // a gap (steps over 10 km are not lines).
  std::mt19937 rng(3);
  auto tracks = walks(rng, 120, 30, 46.5, 8.0, 0.0, 10.0, 50.0, 30.0);
  for (std::size_t t = 0; t < tracks.size(); t += 10) {
    // Jump 20 km east for the rest of the walk: a gap, then a line there.
    for (std::size_t i = 15; i < tracks[t].size(); ++i) {
      const TrackPoint p = tracks[t][i];
      tracks[t][i] = offset(p.lat, p.lon, 0.0, 20000.0);
    }
  }
  // Targets across the middle of the gaps too.
  std::vector<TrackPoint> targets = all_points(tracks);
  for (std::size_t t = 0; t < tracks.size(); t += 10)
    targets.push_back(offset(tracks[t][14].lat, tracks[t][14].lon, 0, 10000.0));
  for (int i = 0; i < 500; ++i) targets.push_back(tracks[0][0]);
  EXPECT_GT(expect_brute_force(sources_of(tracks), targets, 60.0), 4000u);
}

TEST(NeighbourCountsBruteForce, AcrossTheAntimeridianAndAroundThePole) {
  std::mt19937 rng(4);
  for (const auto& [lat, lon] : {std::pair{0.0, 179.9995}, std::pair{-12.0, -179.9998}, std::pair{89.9985, 0.0}}) {
    const auto tracks = walks(rng, 80, 30, lat, lon, 150.0, 5.0, 40.0, 50.0);
    std::vector<TrackPoint> targets = all_points(tracks);
    targets.push_back(place(90.0, 0.0));  // the pole, whatever its longitude
    targets.push_back(place(90.0, 123.0));
    targets.push_back(place(lat, 180.0));
    targets.push_back(place(lat, -180.0));
    EXPECT_GT(expect_brute_force(sources_of(tracks), targets, 50.0), 2000u);
  }
}

}  // namespace
}  // namespace trailray::track
