#include "terrain/height_sampler.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "synthetic_height_source.hpp"

namespace trailray::terrain {
namespace {

using test::SyntheticHeightSource;

// The plane's value where bilinear interpolation of the level's samples must land.
double expected(const SyntheticHeightSource& s, double lat, double lon, int zoom, std::uint32_t width,
                SampleLayout layout) {
  const auto c = geo::fractional_tile_coord(lat, lon, zoom);
  const bool area = layout == SampleLayout::pixel_is_area;
  const double step = area ? width : width - 1;
  const double half = area ? 0.5 : 0.0;
  return s.plane(c->x * step - half, c->y * step - half, zoom);
}

std::vector<geo::LatLon> alpine_points(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> lat(46.5, 46.8), lon(7.7, 8.1);
  std::vector<geo::LatLon> points;
  for (int i = 0; i < n; ++i) points.push_back({lat(rng), lon(rng)});
  return points;
}

TEST(HeightSampler, ReproducesTheBilinearSurfaceOfTheFinestLevel) {
  for (auto layout : {SampleLayout::pixel_is_area, SampleLayout::pixel_is_point}) {
    const std::uint32_t width = layout == SampleLayout::pixel_is_area ? 256 : 65;
    SyntheticHeightSource source(width, layout, 12);
    HeightSampler sampler(source);
    const auto points = alpine_points(500, 1);
    const auto heights = sampler.sample(points);
    ASSERT_EQ(heights.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      ASSERT_NEAR(heights[i], expected(source, points[i].lat, points[i].lon, 12, width, layout), 2e-3) << i;
    EXPECT_EQ(sampler.report().with_height, points.size());
    EXPECT_GT(sampler.report().tiles_loaded, 0u);
  }
}

TEST(HeightSampler, CrossesTileSeamsWithTheNeighboursSamples) {
  // Points within half a sample of a tile edge interpolate between two tiles' samples.
  SyntheticHeightSource source(256, SampleLayout::pixel_is_area, 12);
  HeightSampler sampler(source);
  const geo::TileId tile{12, 2137, 1445};
  std::vector<geo::LatLon> points;
  for (double px : {0.1, 255.9, 128.0})
    for (double py : {0.2, 255.8, 64.0}) points.push_back(*geo::latlon_from_tile_pixel(tile, px, py, 256));
  const auto heights = sampler.sample(points);
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_NEAR(heights[i], expected(source, points[i].lat, points[i].lon, 12, 256, SampleLayout::pixel_is_area),
                2e-3)
        << i;
}

TEST(HeightSampler, HolesAreLeftOutAndRenormalised) {
  SyntheticHeightSource source(256, SampleLayout::pixel_is_area, 12);
  const geo::TileId tile{12, 2137, 1445};
  source.hole = [&](HeightTile& t) {
    if (t.id == tile) t.heights[std::size_t{100} * 256 + 100] = kNoHeight;
  };
  HeightSampler sampler(source);
  // Between samples 100 and 101 in both directions: one of four neighbours is a hole.
  const auto p = geo::latlon_from_tile_pixel(tile, 101.0, 101.0, 256);
  const double h = sampler.sample(p->lat, p->lon);
  const double step = 256;
  const double others = (source.plane(tile.x * step + 101, tile.y * step + 100, 12) +
                         source.plane(tile.x * step + 100, tile.y * step + 101, 12) +
                         source.plane(tile.x * step + 101, tile.y * step + 101, 12)) / 3.0;
  EXPECT_NEAR(h, others, 1e-3);
}

TEST(HeightSampler, FallsBackToCoarserLevelsWhereTheFinestHasNoData) {
  SyntheticHeightSource source(256, SampleLayout::pixel_is_area, 12);
  source.empty_at_zoom = {12, 11};
  HeightSampler sampler(source);
  const auto points = alpine_points(20, 2);
  const auto heights = sampler.sample(points);
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_NEAR(heights[i], expected(source, points[i].lat, points[i].lon, 10, 256, SampleLayout::pixel_is_area),
                2e-3);
  EXPECT_GT(sampler.report().tiles_no_data, 0u);
}

TEST(HeightSampler, FailedTilesAreReportedAndDoNotStopTheOthers) {
  SyntheticHeightSource source(256, SampleLayout::pixel_is_area, 12);
  const auto bad = geo::tile_containing(46.6, 7.8, 12);
  // Tiles of this column number fail; at coarser levels the point lies in another column.
  source.failing = {bad->x};
  HeightSampler sampler(source);
  std::vector<geo::LatLon> points{{46.6, 7.8}, {46.6, 8.3}};
  const auto heights = sampler.sample(points);
  // The good point is exact at zoom 12; the bad one fell back to a coarser level.
  EXPECT_NEAR(heights[1], expected(source, 46.6, 8.3, 12, 256, SampleLayout::pixel_is_area), 2e-3);
  EXPECT_FALSE(std::isnan(heights[0]));
  EXPECT_GE(sampler.report().tiles_failed, 1u);
  ASSERT_FALSE(sampler.report().errors.empty());
  EXPECT_NE(sampler.report().errors.front().find("broken"), std::string::npos);
}

TEST(HeightSampler, ManyBatchesGiveTheSameAnswerAsOne) {
  SyntheticHeightSource source(256, SampleLayout::pixel_is_area, 14);
  HeightSamplerOptions small;
  small.tiles_per_batch = 3;
  HeightSampler batched(source, small), whole(source);
  const auto points = alpine_points(300, 3);
  std::size_t calls = 0;
  const auto a = batched.sample(points, [&](const LoadProgress&, std::size_t, std::size_t) { ++calls; });
  const auto b = whole.sample(points);
  EXPECT_GT(calls, 0u);
  for (std::size_t i = 0; i < points.size(); ++i) EXPECT_DOUBLE_EQ(a[i], b[i]);
}

TEST(HeightSampler, InvalidPointsHaveNoHeight) {
  SyntheticHeightSource source(256, SampleLayout::pixel_is_area, 10);
  HeightSampler sampler(source);
  std::vector<geo::LatLon> points{{std::nan(""), 7.0}, {46.0, 7.0}};
  const auto h = sampler.sample(points);
  EXPECT_TRUE(std::isnan(h[0]));
  EXPECT_FALSE(std::isnan(h[1]));
}

}  // namespace
}  // namespace trailray::terrain
