// The first terrain pictures, headless (llvmpipe in CI), small: where a real peak lands, which
// slope the sun lights, the neutral ground without a source.
#include "render/renderer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "geo/tile_id.hpp"
#include "gl_test_support.hpp"
#include "scene/camera/camera.hpp"
#include "scene_test_support.hpp"
#include "terrain/sources/source_factory.hpp"
#include "test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;
using test::keep_image;
using test::luminance;
using test::mean_luminance;
using test::sun_from;

bool is_sky(const std::array<std::uint8_t, 4>& p) {
  const auto near = [](std::uint8_t v, float c) {
    return std::abs(static_cast<int>(v) - static_cast<int>(std::lround(c * 255.0f))) <= 1;
  };
  return near(p[0], kSkyColorSrgb.r) && near(p[1], kSkyColorSrgb.g) && near(p[2], kSkyColorSrgb.b);
}

// Tiles of a north-south ridge at kRidgeLon: 1000 m flat valleys, rising to 1800 m over 2 km on
// either side, computed for any tile (65 x 65 pixel-is-point samples).
constexpr double kRidgeLat = 46.5, kRidgeLon = 10.0;
struct RidgeSource : test::EastProfileSource {
  RidgeSource()
      : EastProfileSource("ridge", kRidgeLat, kRidgeLon, [](double east_m) {
          return 1000.0 + 800.0 * std::max(0.0, 1.0 - std::abs(east_m) / 2000.0);
        }) {}
};

// Imagery up to zoom 8 only (coarser than the terrain drawn): red west of kRidgeLon, blue east.
class HalvesImagery : public terrain::ImagerySource {
 public:
  HalvesImagery() {
    info_.name = "halves";
    info_.max_zoom = 8;
  }
  const terrain::SourceInfo& info() const override { return info_; }
  terrain::TileResult<terrain::ImageTile> load(const terrain::TileId& id, std::stop_token) override {
    terrain::TileResult<terrain::ImageTile> r;
    r.status = terrain::TileStatus::ok;
    r.tile.id = id;
    r.tile.width = r.tile.height = 256;
    for (std::uint32_t row = 0; row < 256; ++row)
      for (std::uint32_t col = 0; col < 256; ++col) {
        const bool west = geo::latlon_from_tile_pixel(id, col + 0.5, row + 0.5, 256)->lon < kRidgeLon;
        r.tile.rgba.insert(r.tile.rgba.end(), {std::uint8_t(west ? 220 : 20), 20, std::uint8_t(west ? 20 : 220), 255});
      }
    return r;
  }

 private:
  terrain::SourceInfo info_;
};

class RendererTest : public GlTest {};

TEST_F(RendererTest, TheSunLightsTheSlopeFacingIt) {
  RidgeSource ridge;
  test::SceneDrawer renderer(&ridge, nullptr);
  const scene::Lens lens{45.0, 240, 135};
  const auto camera = scene::camera_at({{kRidgeLat, kRidgeLon, 9000.0}, 0.0, -90.0}, lens, 1000.0);
  ASSERT_TRUE(camera.ok()) << camera.error;
  // Points halfway up each slope, 1 km west and east of the crest.
  const double deg_per_km = 1.0 / (111.320 * std::cos(kRidgeLat * M_PI / 180.0));
  const auto west = camera.value->project(scene::ecef_from({kRidgeLat, kRidgeLon - deg_per_km, 1400.0}));
  const auto east = camera.value->project(scene::ecef_from({kRidgeLat, kRidgeLon + deg_per_km, 1400.0}));
  ASSERT_TRUE(west && east);

  scene::Scene options = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
  options.sun_direction_ecef = sun_from(kRidgeLat, kRidgeLon, 270.0, 30.0);
  const test::Drawn from_west = renderer.draw(*camera.value, options);
  keep_image(from_west.image, "ridge_sun_west.png");
  EXPECT_GT(from_west.report.tiles_with_data, 0u);
  EXPECT_EQ(from_west.image.width, 240u);
  const double west_lit = mean_luminance(from_west.image, west->x_px, west->y_px, 2);
  const double east_dark = mean_luminance(from_west.image, east->x_px, east->y_px, 2);
  EXPECT_GT(west_lit, east_dark + 40.0) << "sun in the west: west slope " << west_lit << ", east slope " << east_dark;

  options.sun_direction_ecef = sun_from(kRidgeLat, kRidgeLon, 90.0, 30.0);
  const test::Drawn from_east = renderer.draw(*camera.value, options);
  keep_image(from_east.image, "ridge_sun_east.png");
  const double west_dark = mean_luminance(from_east.image, west->x_px, west->y_px, 2);
  const double east_lit = mean_luminance(from_east.image, east->x_px, east->y_px, 2);
  EXPECT_GT(east_lit, west_dark + 40.0) << "sun in the east: west slope " << west_dark << ", east slope " << east_lit;

  // The valley floor at 1000 m is tinted green (hypsometric tint), not grey.
  const auto valley = camera.value->project(scene::ecef_from({kRidgeLat, kRidgeLon - 3.5 * deg_per_km, 1000.0}));
  ASSERT_TRUE(valley);
  const auto p =
      from_west.image.pixel(static_cast<std::uint32_t>(valley->x_px), static_cast<std::uint32_t>(valley->y_px));
  EXPECT_GT(p[1], p[0]);
  EXPECT_GT(p[1], p[2]);
}

TEST_F(RendererTest, ImageryFromAnAncestorTileLandsWhereItBelongs) {
  RidgeSource ridge;
  HalvesImagery imagery;
  test::SceneDrawer renderer(&ridge, &imagery);
  const auto camera = scene::camera_at({{kRidgeLat, kRidgeLon, 9000.0}, 0.0, -90.0}, scene::Lens{45.0, 160, 90}, 1000.0);
  ASSERT_TRUE(camera.ok()) << camera.error;
  scene::Scene options = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
  options.sun_direction_ecef = sun_from(kRidgeLat, kRidgeLon, 180.0, 89.0);
  const test::Drawn scene = renderer.draw(*camera.value, options);
  keep_image(scene.image, "ridge_imagery.png");
  EXPECT_GT(scene.report.imagery_tiles_used, 0u);
  EXPECT_EQ(scene.report.imagery_tiles_used, scene.report.tiles_drawn);
  const double deg_per_km = 1.0 / (111.320 * std::cos(kRidgeLat * M_PI / 180.0));
  for (const double km : {-3.0, -0.5, 0.5, 3.0}) {
    const auto at =
        camera.value->project(scene::ecef_from({kRidgeLat, kRidgeLon + km * deg_per_km, km < -2 || km > 2 ? 1000.0 : 1600.0}));
    ASSERT_TRUE(at);
    const auto p = scene.image.pixel(static_cast<std::uint32_t>(at->x_px), static_cast<std::uint32_t>(at->y_px));
    if (km < 0)
      EXPECT_GT(p[0], p[2] + 60) << km << " km east: red expected";
    else
      EXPECT_GT(p[2], p[0] + 60) << km << " km east: blue expected";
  }
}

TEST_F(RendererTest, WithoutASourceTheNeutralGroundMeetsTheSky) {
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Lens lens{45.0, 160, 90};
  const auto camera = scene::camera_at({{47.0, 8.0, 1500.0}, 30.0, -10.0}, lens, 500.0);
  ASSERT_TRUE(camera.ok()) << camera.error;
  scene::Scene options = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
  options.neutral_ground_m = 500.0;
  options.sun_direction_ecef = sun_from(47.0, 8.0, 180.0, 60.0);
  options.style.shading.atmosphere = false;  // the flat sky, and ground colours without haze
  const test::Drawn scene = renderer.draw(*camera.value, options);
  keep_image(scene.image, "neutral_ground.png");
  EXPECT_GT(scene.report.tiles_drawn, 0u);
  EXPECT_EQ(scene.report.tiles_with_data, 0u);
  // Ground below the horizon row (earth curvature included), sky above it.
  const auto horizon = camera.value->horizon_row_px(80.0);
  ASSERT_TRUE(horizon);
  ASSERT_GT(*horizon, 5.0);
  ASSERT_LT(*horizon, 85.0);
  for (std::uint32_t x : {0u, 80u, 159u}) {
    EXPECT_TRUE(is_sky(scene.image.pixel(x, 0))) << "column " << x;
    const auto ground = scene.image.pixel(x, 89);
    EXPECT_FALSE(is_sky(ground)) << "column " << x;
    // Neutral: grey, not a tint.
    EXPECT_LE(std::abs(ground[0] - ground[1]), 3) << "column " << x;
    EXPECT_LE(std::abs(ground[1] - ground[2]), 6) << "column " << x;
  }
}

// Flat ground at the ellipsoid from 1500 m with a level camera: the ground meets the sky on the
// ellipsoid's horizon row (earth curvature: 1.24 degrees below the horizontal), column by column.
TEST_F(RendererTest, FlatGroundMeetsTheSkyOnTheHorizonRowOfTheCurvedEarth) {
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Lens lens{20.0, 320, 180};
  const auto camera = scene::camera_at({{47.0, 8.0, 1500.0}, 30.0, 0.0}, lens, 0.0);
  ASSERT_TRUE(camera.ok()) << camera.error;
  scene::Scene options = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
  options.neutral_ground_m = 0.0;
  options.sun_direction_ecef = sun_from(47.0, 8.0, 180.0, 60.0);
  options.style.shading.atmosphere = false;  // haze would blend the far ground into the sky at the horizon
  const test::Drawn scene = renderer.draw(*camera.value, options);
  keep_image(scene.image, "horizon.png");
  for (const std::uint32_t x : {0u, 100u, 160u, 319u}) {
    const auto horizon = camera.value->horizon_row_px(x + 0.5);
    ASSERT_TRUE(horizon);
    ASSERT_GT(*horizon, 100.0);  // 1.24 degrees below the centre row at 9 px a degree
    std::uint32_t first_ground = 0;
    while (first_ground < 180 && is_sky(scene.image.pixel(x, first_ground))) ++first_ground;
    EXPECT_NEAR(first_ground + 0.5, *horizon, 1.0) << "column " << x;
  }
}

// The highest cell of the Interlaken DEM (2004.23 m at 46.734190 N, 7.919397 E, on the ridge at
// the DEM's northern edge; found with GDAL over the whole raster), seen from 6.7 km south at its
// own height: nothing in front of it is higher, and behind it there is only the neutral ground
// 1440 m lower, so it is the top of the terrain in its pixel column.
TEST_F(RendererTest, TheHighestPeakOfARealDemProjectsToItsPixel) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/interlaken_dhm25_wgs84.tif");
  terrain::SourceSettings settings;
  settings.source = dem.string();
  auto source = terrain::open_height_source(settings, {});
  ASSERT_TRUE(source);
  test::SceneDrawer renderer(source.get(), nullptr);
  const scene::GeoPosition peak{46.734190, 7.919397, 2004.23};
  const scene::Lens lens{20.0, 320, 180};
  const auto camera = scene::camera_at({{peak.lat_deg - 0.06, peak.lon_deg, peak.height_m}, 0.0, -3.0}, lens, 560.0);
  ASSERT_TRUE(camera.ok()) << camera.error;
  const auto expected = camera.value->project(scene::ecef_from(peak));
  ASSERT_TRUE(expected);
  ASSERT_GT(expected->y_px, 10.0);

  scene::Scene options = test::lit_scene(glm::dvec3(0.0, 0.0, 1.0));
  options.neutral_ground_m = 560.0;
  options.sun_direction_ecef = sun_from(peak.lat_deg, peak.lon_deg, 180.0, 50.0);
  options.style.shading.atmosphere = false;  // the silhouette against the flat sky
  const test::Drawn scene = renderer.draw(*camera.value, options);
  keep_image(scene.image, "interlaken_peak.png");
  EXPECT_GT(scene.report.tiles_with_data, 0u);
  EXPECT_FALSE(scene.report.terrain.timed_out);
  const auto column = static_cast<std::uint32_t>(expected->x_px);
  std::uint32_t top = 0;
  while (top < 180 && is_sky(scene.image.pixel(column, top))) ++top;
  // The silhouette's top pixel row holds the peak's projection (a pixel spans [top, top + 1)).
  EXPECT_NEAR(top + 0.5, expected->y_px, 2.0)
      << "peak projects to (" << expected->x_px << ", " << expected->y_px << ")";
}

}  // namespace
}  // namespace trailray::render
