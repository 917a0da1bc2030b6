// Heatmap tiles (track/heatmap_pixels.hpp) against the counts cell by cell: at zooms whose pixels
// are larger than a cell, each pixel holds the largest count of the cells whose centre it covers;
// at finer zooms, the count of the cell under its centre.
#include "track/heatmap_pixels.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "geo/web_mercator.hpp"

using namespace trailray;
using track::HeatmapCounts;

namespace {

HeatmapCounts random_counts(double cell, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> step(-0.003, 0.003);
  HeatmapCounts counts(cell);
  for (int n = 0; n < 12; ++n) {
    track::Track t;
    t.segments.emplace_back();
    track::TrackPoint p;
    p.lat = 46.6 + step(rng);
    p.lon = 7.9 + step(rng);
    for (int i = 0; i < 150; ++i) {
      t.segments[0].points.push_back(p);
      p.lat += step(rng);
      p.lon += step(rng);
    }
    counts.add_track(t);
  }
  return counts;
}

constexpr double kWorld = 2.0 * geo::kMercatorHalfExtentM;

}  // namespace

TEST(HeatmapPixels, CoarsePixelsHoldTheLargestCountOfTheirCells) {
  const HeatmapCounts counts = random_counts(50.0, 3);
  for (int zoom : {6, 9, 11}) {
    const double pixel = kWorld / (256.0 * std::ldexp(1.0, zoom));
    ASSERT_GE(pixel, 50.0);
    // The reference: every counted cell into the pixel of its centre.
    std::map<std::pair<std::int64_t, std::int64_t>, std::uint32_t> expected;
    for (const auto& [key, tile] : counts.tiles())
      for (int r = 0; r < 256; ++r)
        for (int c = 0; c < 256; ++c) {
          const std::uint32_t v = tile[static_cast<std::size_t>(r * 256 + c)];
          if (v == 0) continue;
          const auto px = static_cast<std::int64_t>((static_cast<double>(key.first * 256 + c) + 0.5) * 50.0 / pixel);
          const auto py = static_cast<std::int64_t>((static_cast<double>(key.second * 256 + r) + 0.5) * 50.0 / pixel);
          auto& e = expected[{px, py}];
          e = std::max(e, v);
        }
    std::size_t non_zero = 0;
    for (const auto& [xy, pixels] : track::heatmap_tile_pixels(counts, zoom))
      for (int r = 0; r < 256; ++r)
        for (int c = 0; c < 256; ++c) {
          const std::uint32_t v = pixels[static_cast<std::size_t>(r * 256 + c)];
          const auto it = expected.find({xy.first * 256 + c, xy.second * 256 + r});
          EXPECT_EQ(v, it == expected.end() ? 0u : it->second) << "zoom " << zoom;
          non_zero += v != 0;
        }
    EXPECT_EQ(non_zero, expected.size()) << "zoom " << zoom;
  }
  EXPECT_EQ(track::heatmap_max(counts), [&] {
    std::uint32_t most = 0;
    for (const auto& [key, tile] : counts.tiles())
      for (std::uint32_t v : tile) most = std::max(most, v);
    return most;
  }());
}

TEST(HeatmapPixels, FinePixelsTakeTheCellUnderTheirCentre) {
  const HeatmapCounts counts = random_counts(100.0, 4);
  const int zoom = 13;  // 19 m pixels, 100 m cells
  EXPECT_EQ(track::heatmap_native_zoom(100.0), 11);
  const double pixel = kWorld / (256.0 * std::ldexp(1.0, zoom));
  const auto tiles = track::heatmap_tile_pixels(counts, zoom);
  ASSERT_FALSE(tiles.empty());
  std::size_t checked = 0;
  for (const auto& [xy, pixels] : tiles)
    for (int r = 0; r < 256; r += 7)
      for (int c = 0; c < 256; c += 5) {
        const track::HeatmapCell cell{static_cast<std::int64_t>(std::floor((static_cast<double>(xy.first * 256 + c) + 0.5) * pixel / 100.0)),
                                      static_cast<std::int64_t>(std::floor((static_cast<double>(xy.second * 256 + r) + 0.5) * pixel / 100.0))};
        EXPECT_EQ(pixels[static_cast<std::size_t>(r * 256 + c)], counts.at(cell));
        ++checked;
      }
  EXPECT_GT(checked, 1000u);
  // Every counted cell shows in some tile of that zoom.
  std::size_t counted_cells = 0;
  for (const auto& [key, tile] : counts.tiles())
    for (std::uint32_t v : tile) counted_cells += v != 0;
  EXPECT_GT(counted_cells, 0u);
  EXPECT_THROW(track::heatmap_tile_pixels(counts, 25), std::invalid_argument);
}
