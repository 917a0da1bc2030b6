// The renderer's GPU caches (tile meshes, imagery textures) under their byte budgets: flying
// across far-apart places holds no more than the budget beyond the frame's own tiles, a place
// seen again is uploaded again and drawn as before, and a new neutral ground height replaces
// meshes instead of piling them up.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "gl_test_support.hpp"
#include "scene/camera/camera.hpp"
#include "render/renderer.hpp"
#include "scene_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;

constexpr double kLat = 46.5, kLon = 6.0;
// Places about 115 km apart (1.5 degrees of longitude): no tile of one is drawn at another.
constexpr double kPlaceStepDeg = 1.5;
constexpr int kPlaces = 5;

// Hills that differ from place to place.
class WavySource : public test::EastProfileSource {
 public:
  WavySource()
      : EastProfileSource("wavy", kLat, kLon,
                          [](double east_m) { return 1200.0 + 400.0 * std::sin(east_m / 2300.0) + 0.002 * east_m; }) {}
};

// Imagery whose colour follows latitude and longitude, so a texture drawn at the wrong place or
// left over from another tile shows.
class StripedImagery : public terrain::ImagerySource {
 public:
  StripedImagery() {
    info_.name = "striped";
    info_.max_zoom = 12;
  }
  const terrain::SourceInfo& info() const override { return info_; }
  terrain::TileResult<terrain::ImageTile> load(const terrain::TileId& id, std::stop_token) override {
    constexpr std::uint32_t kSize = 64;
    terrain::TileResult<terrain::ImageTile> r;
    r.status = terrain::TileStatus::ok;
    r.tile.id = id;
    r.tile.width = r.tile.height = kSize;
    for (std::uint32_t row = 0; row < kSize; ++row)
      for (std::uint32_t col = 0; col < kSize; ++col) {
        const auto ll = geo::latlon_from_tile_pixel(id, col + 0.5, row + 0.5, kSize);
        const auto channel = [](double x) { return static_cast<std::uint8_t>(127.5 + 127.0 * std::sin(x)); };
        r.tile.rgba.insert(r.tile.rgba.end(), {channel(ll->lon * 40.0), channel(ll->lat * 40.0), 128, 255});
      }
    return r;
  }

 private:
  terrain::SourceInfo info_;
};

class SceneGpuBudgetTest : public GlTest {
 protected:
  static scene::Camera camera_over(int place) {
    auto made = scene::camera_at({{kLat, kLon + place * kPlaceStepDeg, 5000.0}, 30.0, -50.0}, scene::Lens{45.0, 96, 64}, 1200.0);
    EXPECT_TRUE(made.ok()) << made.error;
    return *made.value;
  }
  static scene::Scene options() {
    scene::Scene o = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
    o.style.shading.ssao = false;
    o.style.shading.shadows = false;
    o.neutral_ground_m = 1000.0;
    return o;
  }
};

// The largest difference of any channel of any pixel.
int max_difference(const scene::RgbaImage& a, const scene::RgbaImage& b) {
  EXPECT_EQ(a.rgba.size(), b.rgba.size());
  int most = 0;
  for (std::size_t i = 0; i < std::min(a.rgba.size(), b.rgba.size()); ++i)
    most = std::max(most, std::abs(int{a.rgba[i]} - int{b.rgba[i]}));
  return most;
}

// After a frame's eviction a cache holds the frame's own entries plus older ones within the budget.
void expect_within_budget(const GpuCacheStats& s, const std::string& what) {
  EXPECT_TRUE(s.bytes <= s.budget_bytes || s.entries == s.frame_entries)
      << what << ": " << s.bytes << " bytes in " << s.entries << " entries held, budget " << s.budget_bytes
      << ", the frame's own " << s.frame_bytes << " bytes in " << s.frame_entries;
  EXPECT_LE(s.bytes, std::max(s.budget_bytes, s.frame_bytes)) << what;
  EXPECT_GE(s.entries, s.frame_entries) << what;
}

TEST_F(SceneGpuBudgetTest, FlyingAcrossPlacesStaysWithinTheBudgetAndRedrawsARevisitedPlace) {
  WavySource heights;
  StripedImagery imagery;
  test::SceneDrawer renderer(&heights, &imagery);
  scene::Scene o = options();

  // One place's frame sets the scale: a budget of about two places' worth, so the tour must evict.
  const test::Drawn first = renderer.draw(camera_over(0), o);
  ASSERT_GT(first.report.tiles_with_data, 0u);
  ASSERT_GT(first.report.imagery_tiles_used, 0u);
  ASSERT_GT(first.report.gpu_meshes.frame_bytes, 0u);
  ASSERT_GT(first.report.gpu_imagery.frame_bytes, 0u);
  RendererOptions budgets;
  budgets.mesh_budget_bytes = 2 * first.report.gpu_meshes.frame_bytes;
  budgets.imagery_budget_bytes = 2 * first.report.gpu_imagery.frame_bytes;
  renderer.renderer().set_options(budgets);

  std::vector<scene::RgbaImage> seen;
  std::size_t most_mesh_entries = 0;
  for (int round = 0; round < 2; ++round)
    for (int place = 0; place < kPlaces; ++place) {
      const test::Drawn scene = renderer.draw(camera_over(place), o);
      expect_within_budget(scene.report.gpu_meshes, "meshes");
      expect_within_budget(scene.report.gpu_imagery, "imagery");
      if (round == 0) {
        seen.push_back(scene.image);
      } else {
        // Four places ago: long evicted, so uploaded again, and drawn as the first time.
        EXPECT_GT(scene.report.gpu_meshes.uploads, 0u) << "place " << place;
        EXPECT_GT(scene.report.gpu_imagery.uploads, 0u) << "place " << place;
        EXPECT_LE(max_difference(scene.image, seen[static_cast<std::size_t>(place)]), 1) << "place " << place;
        test::keep_image(scene.image, "gpu_budget_revisit_" + std::to_string(place) + ".png");
      }
      // A few more frames there, turning, as a viewer would draw them.
      for (int frame = 1; frame <= 3; ++frame) {
        auto made = scene::camera_at({{kLat, kLon + place * kPlaceStepDeg, 5000.0}, 30.0 + 20.0 * frame, -50.0},
                              scene::Lens{45.0, 96, 64}, 1200.0);
        ASSERT_TRUE(made.ok()) << made.error;
        const test::Drawn turned = renderer.draw(*made.value, o);
        const std::string where = "round " + std::to_string(round) + " place " + std::to_string(place);
        expect_within_budget(turned.report.gpu_meshes, where + " meshes");
        expect_within_budget(turned.report.gpu_imagery, where + " imagery");
        most_mesh_entries = std::max(most_mesh_entries, turned.report.gpu_meshes.entries);
      }
    }
  // The places look different, so the comparison above would catch a texture or mesh of another.
  EXPECT_GT(max_difference(seen[0], seen[1]), 40);
  // Without eviction every place's tiles would still be held.
  EXPECT_LT(most_mesh_entries, kPlaces * first.report.gpu_meshes.frame_entries);
}

TEST_F(SceneGpuBudgetTest, WithinTheDefaultBudgetARevisitedPlaceUploadsNothing) {
  WavySource heights;
  StripedImagery imagery;
  test::SceneDrawer renderer(&heights, &imagery);
  const test::Drawn first = renderer.draw(camera_over(0), options());
  const test::Drawn elsewhere = renderer.draw(camera_over(2), options());
  const test::Drawn again = renderer.draw(camera_over(0), options());
  EXPECT_EQ(again.report.gpu_meshes.uploads, 0u);
  EXPECT_EQ(again.report.gpu_imagery.uploads, 0u);
  EXPECT_EQ(again.report.gpu_meshes.entries,
            first.report.gpu_meshes.frame_entries + elsewhere.report.gpu_meshes.frame_entries);
  EXPECT_EQ(again.report.gpu_meshes.budget_bytes, kDefaultMeshBudgetBytes);
  EXPECT_EQ(again.report.gpu_imagery.budget_bytes, kDefaultImageryBudgetBytes);
  EXPECT_LE(max_difference(again.image, first.image), 1);
}

TEST_F(SceneGpuBudgetTest, ANewNeutralHeightReplacesTheNeutralGroundsMeshes) {
  test::SceneDrawer renderer(nullptr, nullptr);  // the neutral ground everywhere: all holes
  scene::Scene o = options();
  std::size_t entries = 0;
  for (int frame = 0; frame < 6; ++frame) {
    // Steps small enough to leave the tiles chosen for the view as they are.
    o.neutral_ground_m = 1000.0 + 0.5 * frame;
    const test::Drawn scene = renderer.draw(camera_over(0), o);
    const GpuCacheStats& s = scene.report.gpu_meshes;
    // Far under the default budget, yet no mesh of an old height is left.
    EXPECT_EQ(s.entries, s.frame_entries) << "frame " << frame;
    EXPECT_EQ(s.uploads, s.frame_entries) << "frame " << frame;
    if (frame == 0) entries = s.entries;
    EXPECT_EQ(s.entries, entries) << "frame " << frame;
  }
}

TEST_F(SceneGpuBudgetTest, MeshesWithoutHolesAreKeptWhenTheNeutralHeightChanges) {
  WavySource heights;
  test::SceneDrawer renderer(&heights, nullptr);
  scene::Scene o = options();
  const test::Drawn first = renderer.draw(camera_over(0), o);
  ASSERT_EQ(first.report.tiles_with_data, first.report.tiles_drawn);
  o.neutral_ground_m = 300.0;
  const test::Drawn second = renderer.draw(camera_over(0), o);
  EXPECT_EQ(second.report.gpu_meshes.uploads, 0u);
  EXPECT_EQ(second.report.gpu_meshes.entries, first.report.gpu_meshes.entries);
}

}  // namespace
}  // namespace trailray::render
