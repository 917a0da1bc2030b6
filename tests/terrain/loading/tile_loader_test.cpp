#include "terrain/loading/tile_loader.hpp"

#include <gtest/gtest.h>

#include "terrain/synthetic_height_source.hpp"

namespace trailray::terrain {
namespace {

using namespace std::chrono_literals;
using test::SyntheticHeightSource;

TileLoader<HeightTile>::LoadFunction load_from(HeightSource& s) {
  return [&s](const TileId& id, std::stop_token stop) { return s.load(id, stop); };
}

std::vector<TileRequest> row_of_tiles(int zoom, std::uint32_t y, std::uint32_t x0, std::uint32_t n) {
  std::vector<TileRequest> r;
  for (std::uint32_t i = 0; i < n; ++i) r.push_back({TileId{zoom, x0 + i, y}, static_cast<double>(i)});
  return r;
}

TEST(TileLoader, LoadsEveryWantedTileAndReportsProgress) {
  SyntheticHeightSource source(16, SampleLayout::pixel_is_area);
  source.failing = {5};
  source.empty_at_zoom = {};
  TileLoader<HeightTile> loader(load_from(source), {3, 64u << 20});
  loader.request(row_of_tiles(8, 10, 0, 8));
  ASSERT_TRUE(loader.wait_until_done(30s));
  const auto p = loader.progress();
  EXPECT_EQ(p.wanted, 8u);
  EXPECT_EQ(p.loaded, 7u);
  EXPECT_EQ(p.failed, 1u);
  EXPECT_EQ(loader.state(TileId{8, 5, 10}), TileState::failed);
  ASSERT_EQ(loader.failures().size(), 1u);
  EXPECT_NE(loader.failures()[0].find("8/5/10"), std::string::npos);
  auto tile = loader.get(TileId{8, 2, 10});
  ASSERT_TRUE(tile);
  EXPECT_EQ(tile->id, (TileId{8, 2, 10}));
  // Asking again loads nothing new: loaded tiles are in memory, the failure is remembered.
  const int loads = source.loads;
  loader.request(row_of_tiles(8, 10, 0, 8));
  ASSERT_TRUE(loader.wait_until_done(30s));
  EXPECT_EQ(source.loads, loads);
}

TEST(TileLoader, HigherPriorityTilesLoadFirst) {
  SyntheticHeightSource source(16, SampleLayout::pixel_is_area);
  std::vector<TileId> order;
  std::mutex m;
  TileLoader<HeightTile> loader(
      [&](const TileId& id, std::stop_token stop) {
        {
          std::lock_guard lock(m);
          order.push_back(id);
        }
        return source.load(id, stop);
      },
      {1, 64u << 20});
  source.delay = 20ms;  // the first request occupies the single worker while the rest queue up
  loader.request({{TileId{8, 0, 0}, 100.0}});
  std::this_thread::sleep_for(5ms);
  loader.request({{TileId{8, 0, 0}, 100.0}, {TileId{8, 1, 0}, 1.0}, {TileId{8, 2, 0}, 50.0}, {TileId{8, 3, 0}, 10.0}});
  ASSERT_TRUE(loader.wait_until_done(30s));
  ASSERT_EQ(order.size(), 4u);
  EXPECT_EQ(order[1], (TileId{8, 2, 0}));
  EXPECT_EQ(order[2], (TileId{8, 3, 0}));
  EXPECT_EQ(order[3], (TileId{8, 1, 0}));
}

TEST(TileLoader, TilesThatLeftTheViewAreCancelled) {
  SyntheticHeightSource source(16, SampleLayout::pixel_is_area);
  source.delay = 2s;
  TileLoader<HeightTile> loader(load_from(source), {2, 64u << 20});
  loader.request(row_of_tiles(8, 0, 0, 6));
  while (source.loads < 2) std::this_thread::sleep_for(1ms);
  const auto start = std::chrono::steady_clock::now();
  source.delay = 0ms;
  loader.request(row_of_tiles(8, 1, 0, 2));  // a different row: everything in flight is dropped
  ASSERT_TRUE(loader.wait_until_done(30s));
  EXPECT_LT(std::chrono::steady_clock::now() - start, 1500ms) << "in-flight loads were not cancelled";
  for (int i = 0; i < 1000 && source.cancelled < 2; ++i) std::this_thread::sleep_for(1ms);
  EXPECT_EQ(source.cancelled, 2);
  EXPECT_EQ(loader.progress().loaded, 2u);
  EXPECT_EQ(loader.state(TileId{8, 3, 0}), TileState::unknown);  // was queued, never loaded
}

TEST(TileLoader, MemoryBudgetEvictsLeastRecentlyUsed) {
  SyntheticHeightSource source(64, SampleLayout::pixel_is_area);  // 16 KiB of heights a tile
  const std::size_t tile_bytes = source.load(TileId{8, 0, 0}, {}).tile.byte_size();
  // One worker: the tiles load in priority order, 8/2/0 first, then 8/1/0, then 8/0/0.
  TileLoader<HeightTile> loader(load_from(source), {1, 3 * tile_bytes + 10});
  loader.request(row_of_tiles(8, 0, 0, 3));
  ASSERT_TRUE(loader.wait_until_done(30s));
  ASSERT_TRUE(loader.get(TileId{8, 2, 0}));  // touch the oldest: now the most recently used
  loader.request(row_of_tiles(8, 0, 3, 1));
  ASSERT_TRUE(loader.wait_until_done(30s));
  EXPECT_LE(loader.memory_used_bytes(), 3 * tile_bytes + 10);
  EXPECT_TRUE(loader.get(TileId{8, 2, 0}));
  EXPECT_FALSE(loader.get(TileId{8, 1, 0}));  // the least recently used one went
  EXPECT_TRUE(loader.get(TileId{8, 0, 0}));
  EXPECT_TRUE(loader.get(TileId{8, 3, 0}));
}

TEST(TileLoader, TilesTheViewWantsAreNotEvictedEvenOverBudget) {
  SyntheticHeightSource source(64, SampleLayout::pixel_is_area);
  const std::size_t tile_bytes = source.load(TileId{8, 0, 0}, {}).tile.byte_size();
  TileLoader<HeightTile> loader(load_from(source), {2, 2 * tile_bytes});
  loader.request(row_of_tiles(8, 0, 0, 5));
  ASSERT_TRUE(loader.wait_until_done(30s));
  EXPECT_EQ(loader.progress().loaded, 5u);
  EXPECT_EQ(source.loads, 6);  // once each (plus the one above), none loaded twice
  // Once the view moves on, the budget applies again.
  loader.request(row_of_tiles(8, 1, 0, 1));
  ASSERT_TRUE(loader.wait_until_done(30s));
  EXPECT_LE(loader.memory_used_bytes(), 2 * tile_bytes);
}

TEST(TileLoader, DestructionWithWorkInFlightReturnsPromptly) {
  SyntheticHeightSource source(16, SampleLayout::pixel_is_area);
  source.delay = 10s;
  const auto start = std::chrono::steady_clock::now();
  {
    TileLoader<HeightTile> loader(load_from(source), {4, 64u << 20});
    loader.request(row_of_tiles(8, 0, 0, 16));
    while (source.loads < 4) std::this_thread::sleep_for(1ms);
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
  EXPECT_EQ(source.loads, 4);
}

}  // namespace
}  // namespace trailray::terrain
