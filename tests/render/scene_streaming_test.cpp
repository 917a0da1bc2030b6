// The viewer's frames (scene::TileLoadPolicy::wait = false): a frame never waits for a
// tile; it draws what has arrived, coarser tiles standing in while finer ones load, and the
// report's progress tells a loading indicator how far the loaders are.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "gl_test_support.hpp"
#include "scene/camera/camera.hpp"
#include "render/renderer.hpp"
#include "scene_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;

constexpr double kLat = 46.5, kLon = 10.0;

// A hill whose tiles are held back until the test opens the gate (a slow disk or network).
class GatedSource : public test::EastProfileSource {
 public:
  GatedSource()
      : EastProfileSource("gated", kLat, kLon, [](double east_m) { return 1000.0 + 0.1 * std::abs(east_m); }) {}
  terrain::TileResult<terrain::HeightTile> load(const terrain::TileId& id, std::stop_token stop) override {
    while (!open.load() && !stop.stop_requested()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return EastProfileSource::load(id, stop);
  }
  std::atomic<bool> open{false};
};

class SceneStreamingTest : public GlTest {
 protected:
  scene::Camera camera() const {
    auto made = scene::camera_at({{kLat, kLon, 6000.0}, 0.0, -60.0}, scene::Lens{45.0, 96, 54}, 1000.0);
    EXPECT_TRUE(made.ok()) << made.error;
    return *made.value;
  }
  // The viewer's loading policy on the drawer's terrain.
  static void never_wait(test::SceneDrawer& drawer) {
    scene::TileLoadPolicy policy;
    policy.wait = false;
    drawer.terrain().set_policy(policy);
  }
  static scene::Scene viewer_options() {
    scene::Scene o = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
    o.style.shading.ssao = false;
    o.style.shading.shadows = false;
    o.neutral_ground_m = 1000.0;
    return o;
  }
};

TEST_F(SceneStreamingTest, AFrameDoesNotWaitForTilesThatHaveNotArrived) {
  GatedSource source;
  test::SceneDrawer renderer(&source, nullptr);
  never_wait(renderer);
  // With the gate shut a waiting render could only return at its timeout (two minutes).
  const test::Drawn first = renderer.draw(camera(), viewer_options());
  EXPECT_EQ(first.report.tiles_with_data, 0u);
  EXPECT_GT(first.report.terrain.progress.wanted, 0u);
  EXPECT_GT(first.report.terrain.progress.pending(), 0u);
  EXPECT_EQ(first.image.width, 96u);  // drawn (sky and what stands in), read back by default
  source.open = true;
}

TEST_F(SceneStreamingTest, TilesArrivingBetweenFramesAreDrawnByLaterFrames) {
  GatedSource source;
  source.open = true;
  test::SceneDrawer renderer(&source, nullptr);
  never_wait(renderer);
  scene::Scene options = viewer_options();
  test::Drawn scene;
  // Frames until the loaders are done (each frame re-selects with the heights that arrived).
  for (int frame = 0; frame < 2000; ++frame) {
    scene = renderer.draw(camera(), options);
    if (scene.report.terrain.progress.done() && scene.report.tiles_with_data > 0) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_TRUE(scene.report.terrain.progress.done());
  EXPECT_GT(scene.report.tiles_with_data, 0u);
  EXPECT_EQ(scene.report.tiles_with_data, scene.report.tiles_drawn);
  EXPECT_FALSE(scene.report.terrain.timed_out);
}

TEST_F(SceneStreamingTest, HeightsInMemoryComeFromLoadedTilesOnly) {
  GatedSource source;
  test::SceneDrawer renderer(&source, nullptr);
  never_wait(renderer);
  const double east_deg = 1500.0 / (111320.0 * std::cos(kLat * M_PI / 180.0));       // 1.5 km east
  EXPECT_TRUE(std::isnan(renderer.terrain().height_in_memory(kLat + 0.01, kLon + east_deg)));  // nothing loaded
  source.open = true;
  scene::Scene options = viewer_options();
  for (int frame = 0; frame < 2000 && !renderer.draw(camera(), options).report.terrain.progress.done(); ++frame)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  // The hill: 1000 m + 0.1 m per metre east; bilinear on a fine tile is within centimetres.
  EXPECT_NEAR(renderer.terrain().height_in_memory(kLat + 0.01, kLon + east_deg), 1150.0, 0.5);
  EXPECT_NEAR(renderer.terrain().height_in_memory(kLat + 0.01, kLon - east_deg), 1150.0, 0.5);
}

// A target that reads nothing back (a window's, a video encoder's) gets the composed frame.
TEST_F(SceneStreamingTest, ATargetReceivesTheComposedFrame) {
  struct Counting : FrameTarget {
    void receive(const ColorDepthTarget& frame) override {
      ++frames;
      width = frame.width();
      height = frame.height();
    }
    int frames = 0, width = 0, height = 0;
  };
  GatedSource source;
  source.open = true;
  scene::TerrainView terrain(&source, nullptr);
  scene::Scene scene = viewer_options();
  scene.terrain = &terrain;
  Renderer renderer;
  Counting target;
  renderer.draw(scene, camera(), target);
  EXPECT_EQ(target.frames, 1);
  EXPECT_EQ(target.width, 96);
  EXPECT_EQ(target.height, 54);
}

}  // namespace
}  // namespace trailray::render
