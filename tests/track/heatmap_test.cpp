// Heatmap counts (track/heatmap.hpp) against an independent computation: the cells whose inside a
// segment passes through, found by clipping the segment to every cell near it.
#include "track/heatmap.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "geo/web_mercator.hpp"

using namespace trailray;
using track::HeatmapCell;
using track::HeatmapCounts;

namespace {

track::TrackPoint at(double lat, double lon) {
  track::TrackPoint p;
  p.lat = lat;
  p.lon = lon;
  return p;
}

track::Track track_of(std::vector<std::vector<std::pair<double, double>>> segments) {
  track::Track t;
  for (const auto& s : segments) {
    track::Segment seg;
    for (auto [lat, lon] : s) seg.points.push_back(at(lat, lon));
    t.segments.push_back(seg);
  }
  return t;
}

// Does the segment a-b pass through the open square [x0, x0+1] x [y0, y0+1]? (Liang-Barsky.)
bool crosses(double ax, double ay, double bx, double by, double x0, double y0) {
  double t0 = 0.0, t1 = 1.0;
  const double dx = bx - ax, dy = by - ay;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {ax - x0, x0 + 1 - ax, ay - y0, y0 + 1 - ay};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] <= 0) return false;
      continue;
    }
    const double r = q[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, r);
    else t1 = std::min(t1, r);
  }
  return t0 < t1 || (dx == 0 && dy == 0 && q[0] > 0 && q[1] > 0 && q[2] > 0 && q[3] > 0);
}

std::set<std::pair<std::int64_t, std::int64_t>> brute_force_cells(const track::Track& t, double cell) {
  const double H = geo::kMercatorHalfExtentM;
  std::set<std::pair<std::int64_t, std::int64_t>> out;
  for (const auto& s : t.segments)
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const auto a = geo::mercator_from_latlon(s.points[i].lat, s.points[i].lon);
      const auto b = i + 1 < s.points.size() ? geo::mercator_from_latlon(s.points[i + 1].lat, s.points[i + 1].lon) : a;
      const double ax = (a.x + H) / cell, ay = (H - a.y) / cell, bx = (b.x + H) / cell, by = (H - b.y) / cell;
      const auto x0 = static_cast<std::int64_t>(std::floor(std::min(ax, bx)));
      const auto x1 = static_cast<std::int64_t>(std::floor(std::max(ax, bx)));
      const auto y0 = static_cast<std::int64_t>(std::floor(std::min(ay, by)));
      const auto y1 = static_cast<std::int64_t>(std::floor(std::max(ay, by)));
      for (auto x = x0; x <= x1; ++x)
        for (auto y = y0; y <= y1; ++y)
          if (crosses(ax, ay, bx, by, static_cast<double>(x), static_cast<double>(y))) out.insert({x, y});
    }
  return out;
}

std::set<std::pair<std::int64_t, std::int64_t>> as_set(const std::vector<HeatmapCell>& cells) {
  std::set<std::pair<std::int64_t, std::int64_t>> out;
  for (const auto& c : cells) out.insert({c.col, c.row});
  return out;
}

}  // namespace

TEST(Heatmap, RandomTracksCrossTheCellsAClippedSegmentCrosses) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> step(-0.004, 0.004);  // a few hundred metres
  for (double cell : {10.0, 50.0, 333.0}) {
    for (int n = 0; n < 20; ++n) {
      std::vector<std::pair<double, double>> points{{46.5 + step(rng), 8.0 + step(rng)}};
      for (int i = 0; i < 200; ++i) points.push_back({points.back().first + step(rng), points.back().second + step(rng)});
      const track::Track t = track_of({points});
      HeatmapCounts counts(cell);
      EXPECT_EQ(as_set(counts.track_cells(t)), brute_force_cells(t, cell)) << "cell " << cell;
    }
  }
}

TEST(Heatmap, ATrackCountsOncePerCellAndTracksAddUp) {
  HeatmapCounts counts(50.0);
  // Back and forth three times over the same 2 km: once per cell.
  const track::Track there_and_back = track_of({{{47.0, 11.0}, {47.0, 11.02}, {47.0, 11.0}, {47.0, 11.02}}});
  counts.add_track(there_and_back);
  const track::Track crossing = track_of({{{46.99, 11.01}, {47.01, 11.01}}});
  counts.add_track(crossing);
  EXPECT_EQ(counts.tracks(), 2u);
  const auto line = counts.track_cells(there_and_back);
  std::uint32_t most = 0;
  for (const auto& c : line) most = std::max(most, counts.at(c));
  EXPECT_EQ(most, 2u);  // where the crossing passes
  std::size_t twos = 0;
  for (const auto& c : line) twos += counts.at(c) == 2;
  EXPECT_GE(twos, 1u);
  EXPECT_LE(twos, 3u);
  // 0.02 degrees of longitude at the equator's scale: 2226 Mercator metres, about 45 cells of 50 m.
  EXPECT_NEAR(static_cast<double>(line.size()), 2226.4 / 50.0, 2.0);
}

TEST(Heatmap, MergedCountsEqualCountsMadeTogether) {
  const track::Track a = track_of({{{47.0, 11.0}, {47.01, 11.01}}});
  const track::Track b = track_of({{{47.005, 10.995}, {47.005, 11.02}}, {{47.1, 11.1}}});
  HeatmapCounts together(50.0), first(50.0), second(50.0);
  together.add_track(a);
  together.add_track(b);
  first.add_track(a);
  second.add_track(b);
  first.merge(second);
  EXPECT_EQ(first.tracks(), 2u);
  const auto w = together.extent();
  EXPECT_EQ(first.extent().col0, w.col0);
  EXPECT_EQ(first.raster(w), together.raster(w));
  HeatmapCounts other_cells(60.0);
  EXPECT_THROW(first.merge(other_cells), std::invalid_argument);
}

TEST(Heatmap, ALongStepIsAGapAndSegmentsAreNotJoined) {
  HeatmapCounts counts(100.0);
  const track::Track jump = track_of({{{47.0, 11.0}, {47.0, 11.5}}});  // 38 km east in one step
  EXPECT_EQ(counts.track_cells(jump).size(), 2u);
  const track::Track two = track_of({{{47.0, 11.0}}, {{47.0, 11.01}}});
  EXPECT_EQ(counts.track_cells(two).size(), 2u);
  const track::Track bad = track_of({{{91.0, 11.0}, {std::nan(""), 11.0}}});
  EXPECT_TRUE(counts.track_cells(bad).empty());
}

TEST(Heatmap, TheRasterAndItsGeotransformPlaceTheCells) {
  HeatmapCounts counts(50.0);
  counts.add_track(track_of({{{47.0, 11.0}, {47.0, 11.0}}}));
  const auto w = counts.extent();
  ASSERT_EQ(w.width(), 1);
  ASSERT_EQ(w.height(), 1);
  const auto g = counts.geotransform(w);
  const auto m = geo::mercator_from_latlon(47.0, 11.0);
  EXPECT_LE(g[0], m.x);
  EXPECT_GT(g[0] + g[1], m.x);
  EXPECT_GE(g[3], m.y);
  EXPECT_LT(g[3] + g[5], m.y);
  EXPECT_EQ(counts.raster(w), std::vector<std::uint32_t>{1});
  const auto box = counts.window_of(46.9, 10.9, 47.1, 11.1);
  const auto r = counts.raster(box);
  EXPECT_EQ(std::count(r.begin(), r.end(), 1u), 1);
  EXPECT_THROW(HeatmapCounts(0.5), std::invalid_argument);
}
