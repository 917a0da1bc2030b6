// The viewer's frames (SceneRenderOptions::wait_for_tiles = false): a frame never waits for a
// tile; it draws what has arrived, coarser tiles standing in while finer ones load, and the
// report's progress tells a loading indicator how far the loaders are.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "gl_test_support.hpp"
#include "scene/camera.hpp"
#include "render/scene_renderer.hpp"
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
  static SceneRenderOptions viewer_options() {
    SceneRenderOptions o;
    o.wait_for_tiles = false;
    o.ssao = false;
    o.shadows = false;
    o.neutral_ground_height_m = 1000.0;
    return o;
  }
};

TEST_F(SceneStreamingTest, AFrameDoesNotWaitForTilesThatHaveNotArrived) {
  GatedSource source;
  SceneRenderer renderer({&source, nullptr});
  // With the gate shut a waiting render could only return at its timeout (two minutes).
  const RenderedScene first = renderer.render(camera(), viewer_options());
  EXPECT_EQ(first.report.tiles_with_data, 0u);
  EXPECT_GT(first.report.progress.wanted, 0u);
  EXPECT_GT(first.report.progress.pending(), 0u);
  EXPECT_EQ(first.image.width, 96u);  // drawn (sky and what stands in), read back by default
  source.open = true;
}

TEST_F(SceneStreamingTest, TilesArrivingBetweenFramesAreDrawnByLaterFrames) {
  GatedSource source;
  source.open = true;
  SceneRenderer renderer({&source, nullptr});
  SceneRenderOptions options = viewer_options();
  RenderedScene scene;
  // Frames until the loaders are done (each frame re-selects with the heights that arrived).
  for (int frame = 0; frame < 2000; ++frame) {
    scene = renderer.render(camera(), options);
    if (scene.report.progress.done() && scene.report.tiles_with_data > 0) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_TRUE(scene.report.progress.done());
  EXPECT_GT(scene.report.tiles_with_data, 0u);
  EXPECT_EQ(scene.report.tiles_with_data, scene.report.tiles_drawn);
  EXPECT_FALSE(scene.report.timed_out);
}

TEST_F(SceneStreamingTest, HeightsInMemoryComeFromLoadedTilesOnly) {
  GatedSource source;
  SceneRenderer renderer({&source, nullptr});
  const double east_deg = 1500.0 / (111320.0 * std::cos(kLat * M_PI / 180.0));       // 1.5 km east
  EXPECT_TRUE(std::isnan(renderer.height_in_memory(kLat + 0.01, kLon + east_deg)));  // nothing loaded
  source.open = true;
  SceneRenderOptions options = viewer_options();
  for (int frame = 0; frame < 2000 && !renderer.render(camera(), options).report.progress.done(); ++frame)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  // The hill: 1000 m + 0.1 m per metre east; bilinear on a fine tile is within centimetres.
  EXPECT_NEAR(renderer.height_in_memory(kLat + 0.01, kLon + east_deg), 1150.0, 0.5);
  EXPECT_NEAR(renderer.height_in_memory(kLat + 0.01, kLon - east_deg), 1150.0, 0.5);
}

TEST_F(SceneStreamingTest, WithoutReadBackTheImageStaysEmpty) {
  GatedSource source;
  source.open = true;
  SceneRenderer renderer({&source, nullptr});
  SceneRenderOptions options = viewer_options();
  options.read_back = false;
  const RenderedScene scene = renderer.render(camera(), options);
  EXPECT_EQ(scene.image.width, 0u);
  EXPECT_TRUE(scene.image.rgba.empty());
}

}  // namespace
}  // namespace trailray::render
