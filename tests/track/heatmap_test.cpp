// Heatmap counts (track/heatmap.hpp) against an independent computation: the cells whose inside a
// segment passes through, found by clipping the segment to every cell near it.
#include "track/heatmap.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>

#include "track/flight/synthetic_flight.hpp"
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

namespace {

// A point at grid coordinates (in cells from the world's north-west corner).
track::TrackPoint at_grid(double gx, double gy, double cell, double time) {
  const double H = geo::kMercatorHalfExtentM;
  const geo::LatLon ll = geo::latlon_from_mercator(gx * cell - H, H - gy * cell);
  track::TrackPoint p = at(ll.lat, ll.lon);
  p.time = time;
  return p;
}

}  // namespace

TEST(HeatmapTime, AStepsSecondsAreSharedAmongItsCellsByLength) {
  const double cell = 100.0;
  HeatmapCounts counts(cell, track::HeatmapMeasure::time);
  // 80 s along a row of cells from the middle of column 300010 to the middle of 300014:
  // half, three whole and half a cell: 10, 20, 20, 20, 10 seconds.
  track::Track t;
  t.segments.push_back({{at_grid(300010.5, 230000.5, cell, 1000.0), at_grid(300014.5, 230000.5, cell, 1080.0)}});
  const auto c = counts.track_counts(t);
  ASSERT_EQ(c.size(), 5u);
  const std::uint32_t expected[] = {10, 20, 20, 20, 10};
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(c[i].cell.col, 300010 + static_cast<std::int64_t>(i));
    EXPECT_EQ(c[i].cell.row, 230000);
    EXPECT_EQ(c[i].count, expected[i]) << i;
  }
  // No time, time going back, and a gap over 10 km count nothing.
  track::Track untimed;
  untimed.segments.push_back({{at_grid(300010.5, 230000.5, cell, std::nan("")), at_grid(300012.5, 230000.5, cell, 0)}});
  EXPECT_TRUE(counts.track_counts(untimed).empty());
  track::Track back;
  back.segments.push_back({{at_grid(300010.5, 230000.5, cell, 50), at_grid(300012.5, 230000.5, cell, 40)}});
  EXPECT_TRUE(counts.track_counts(back).empty());
  track::Track gap;
  gap.segments.push_back({{at_grid(300010.5, 230000.5, cell, 0), at_grid(300400.5, 230000.5, cell, 3600)}});
  EXPECT_TRUE(counts.track_counts(gap).empty());
}

TEST(HeatmapTime, TheCellsHoldTheTracksDurationUpToRounding) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> step(-0.001, 0.001);
  std::vector<std::pair<double, double>> points{{46.5, 8.0}};
  for (int i = 0; i < 500; ++i) points.push_back({points.back().first + step(rng), points.back().second + step(rng)});
  track::Track t = track_of({points});
  for (std::size_t i = 0; i < t.segments[0].points.size(); ++i) t.segments[0].points[i].time = 1e9 + 7.0 * static_cast<double>(i);
  HeatmapCounts counts(50.0, track::HeatmapMeasure::time);
  const auto c = counts.track_counts(t);
  double total = 0;
  for (const auto& x : c) total += x.count;
  EXPECT_NEAR(total, 7.0 * 500, 0.5 * static_cast<double>(counts.track_cells(t).size()));
  // Every cell with time is one the track passes through.
  const auto cells = as_set(counts.track_cells(t));
  for (const auto& x : c) EXPECT_TRUE(cells.contains({x.cell.col, x.cell.row}));
}

TEST(HeatmapThermals, OnlyTheCellsWhereAFlightCircledInLiftCount) {
  const double cell = 50.0;
  track::test::SyntheticFlight f;
  f.ground(60);
  f.glide(200, 0.0, 10.0, 1.0);
  const track::TrackPoint first = f.points().back();
  f.circle(150, true, 2.0);
  f.glide(250, 90.0);
  const track::TrackPoint second = f.points().back();
  f.circle(150, false, 1.5);
  f.glide(300, 180.0, 10.0, 2.0);
  f.ground(60);
  const track::Track t = f.track();
  HeatmapCounts counts(cell, track::HeatmapMeasure::thermals);
  counts.add_track(t);
  counts.add_track(t);  // a second flight the same way
  const auto c = counts.track_counts(t);
  ASSERT_FALSE(c.empty());
  // Each counted cell lies by one of the two circles (radius 40 m: within 140 m of where the circling began).
  const double H = geo::kMercatorHalfExtentM;
  std::size_t near_first = 0, near_second = 0;
  for (const auto& x : c) {
    EXPECT_EQ(x.count, 1u);  // once per flight
    EXPECT_EQ(counts.at(x.cell), 2u);
    const geo::LatLon centre = geo::latlon_from_mercator((static_cast<double>(x.cell.col) + 0.5) * cell - H,
                                                         H - (static_cast<double>(x.cell.row) + 0.5) * cell);
    const auto ground = [&](const track::TrackPoint& p) {
      const double dn = (centre.lat - p.lat) * 111195.0, de = (centre.lon - p.lon) * 111195.0 * std::cos(p.lat * std::numbers::pi / 180);
      return std::hypot(dn, de);
    };
    const bool a = ground(first) < 140.0, b = ground(second) < 140.0;
    EXPECT_TRUE(a || b) << "cell " << x.cell.col << "," << x.cell.row;
    near_first += a;
    near_second += b;
  }
  EXPECT_GE(near_first, 4u);  // a 40 m circle crosses at least four 34 m (ground) cells
  EXPECT_GE(near_second, 4u);
  // The glides between are counted as tracks, not as thermals.
  EXPECT_GT(HeatmapCounts(cell).track_cells(t).size(), 3 * c.size());
  // A track without times has no flights, so no thermals.
  track::Track untimed = t;
  for (auto& p : untimed.segments[0].points) p.time = std::nan("");
  EXPECT_TRUE(counts.track_counts(untimed).empty());
}

TEST(Heatmap, MeasuresDoNotAddUpAndCroppingKeepsTheWindow) {
  HeatmapCounts tracks(50.0), time(50.0, track::HeatmapMeasure::time);
  EXPECT_THROW(tracks.merge(time), std::invalid_argument);
  EXPECT_EQ(track::parse_heatmap_measure("thermals"), track::HeatmapMeasure::thermals);
  EXPECT_FALSE(track::parse_heatmap_measure("Tracks"));
  tracks.add_track(track_of({{{47.0, 11.0}, {47.0, 11.02}}}));
  const auto all = tracks.extent();
  const track::HeatmapWindow left{all.col0, all.row0, all.col0 + 10, all.row1};
  const HeatmapCounts kept = tracks.cropped(left);
  EXPECT_EQ(kept.tracks(), 1u);
  EXPECT_EQ(kept.extent().col0, all.col0);
  EXPECT_EQ(kept.extent().col1, all.col0 + 10);
  EXPECT_EQ(kept.raster(left), tracks.raster(left));
}
