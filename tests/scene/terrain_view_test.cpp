// The terrain view (GL-free): the tiles a camera wants, the neutral ground where there is no
// source, the loading policy, the lowest terrain in view as the neutral height, and heights from
// the tiles in memory only.
#include "scene/terrain_view.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "terrain/east_profile_source.hpp"

namespace trailray::scene {
namespace {

constexpr double kLat = 46.5, kLon = 10.0;

// A plane rising 0.1 m per 0.001 degree of longitude from 1000 m at kLon.
double height_at(double lon) { return 1000.0 + 100.0 * (lon - kLon); }

test::EastProfileSource slope_source() {
  const double metres_per_degree = 111320.0 * std::cos(kLat * M_PI / 180.0);
  return test::EastProfileSource("slope", kLat, kLon,
                                 [=](double east_m) { return height_at(kLon + east_m / metres_per_degree); });
}

Camera overhead() {
  auto made = camera_at({{kLat, kLon, 6000.0}, 0.0, -60.0}, Lens{45.0, 96, 54}, 1000.0);
  EXPECT_TRUE(made.ok()) << made.error;
  return *made.value;
}

TEST(TerrainView, WithoutASourceEveryTileIsTheNeutralGround) {
  TerrainView view(nullptr, nullptr);
  const TerrainTiles tiles = view.tiles_for(overhead(), 500.0);
  ASSERT_FALSE(tiles.tiles.empty());
  for (const TerrainTile& t : tiles.tiles) {
    EXPECT_FALSE(t.has_data);
    EXPECT_EQ(t.image, nullptr);
  }
  EXPECT_EQ(tiles.report.neutral_ground_m, 500.0);
  EXPECT_EQ(tiles.report.selection_rounds, 1);
  EXPECT_EQ(view.tiles_for(overhead(), NAN).report.neutral_ground_m, 0.0);  // nothing loaded: sea level
  EXPECT_TRUE(std::isnan(view.height_in_memory(kLat, kLon)));
}

TEST(TerrainView, WaitingHandsOutLoadedTilesAndTheLowestTerrainInView) {
  test::EastProfileSource source = slope_source();
  TerrainView view(&source, nullptr);
  EXPECT_TRUE(std::isnan(view.height_in_memory(kLat + 0.01, kLon + 0.005)));  // nothing loaded yet
  const TerrainTiles tiles = view.tiles_for(overhead(), NAN);
  ASSERT_FALSE(tiles.tiles.empty());
  EXPECT_FALSE(tiles.report.timed_out);
  EXPECT_TRUE(tiles.report.progress.done());
  double lowest = INFINITY;
  for (const TerrainTile& t : tiles.tiles) {
    EXPECT_TRUE(t.has_data);
    lowest = std::min(lowest, static_cast<double>(t.heights->min_m));
  }
  EXPECT_EQ(tiles.report.neutral_ground_m, lowest);
  EXPECT_NEAR(view.height_in_memory(kLat + 0.01, kLon + 0.005), height_at(kLon + 0.005), 0.01);
}

TEST(TerrainView, NeverWaitingRequestsTilesForLaterCalls) {
  test::EastProfileSource source = slope_source();
  TerrainView view(&source, nullptr);
  TileLoadPolicy policy;
  policy.wait = false;
  view.set_policy(policy);
  TerrainTiles tiles;
  for (int call = 0; call < 2000; ++call) {
    tiles = view.tiles_for(overhead(), 1000.0);
    if (tiles.report.progress.done() && !tiles.tiles.empty() && tiles.tiles.front().has_data) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_TRUE(tiles.report.progress.done());
  EXPECT_EQ(tiles.report.selection_rounds, 1);
  for (const TerrainTile& t : tiles.tiles) EXPECT_TRUE(t.has_data);
}

}  // namespace
}  // namespace trailray::scene
