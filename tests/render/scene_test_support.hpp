#pragma once
// What the scene tests (renderer, scene_shadows, deferred_pipeline, the track tests) share:
// a renderer with its terrain view that draws a scene into a picture, pixel luminance, a sun
// placed by azimuth and elevation, saving pictures for a human to look at, and synthetic terrain
// that varies only from west to east.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>

#include "geo/tile_id.hpp"
#include "render/frame_target.hpp"
#include "render/gl/framebuffer_readback.hpp"
#include "render/renderer.hpp"
#include "scene/camera/camera.hpp"
#include "scene/scene.hpp"
#include "scene/terrain_view.hpp"
#include "terrain/east_profile_source.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::render::test {

// A frame drawn and read back, with the renderer's report.
struct Drawn {
  scene::RgbaImage image;
  FrameReport report;
};

// A renderer and the terrain view over a test's sources (either may be nullptr): draws scenes
// over that terrain into pictures.
class SceneDrawer {
 public:
  SceneDrawer(terrain::HeightSource* heights, terrain::ImagerySource* imagery, RendererOptions options = {})
      : terrain_(heights, imagery), renderer_(options) {}

  // `scene` over this drawer's terrain (its own terrain is replaced), read back.
  Drawn draw(const scene::Camera& camera, scene::Scene scene, FrameProfiler* profiler = nullptr) {
    scene.terrain = &terrain_;
    ImageTarget target;
    target.profiler = profiler;
    Drawn drawn;
    drawn.report = renderer_.draw(scene, camera, target);
    drawn.image = std::move(target.image);
    return drawn;
  }

  scene::TerrainView& terrain() { return terrain_; }
  Renderer& renderer() { return renderer_; }

 private:
  scene::TerrainView terrain_;
  Renderer renderer_;
};

// A scene lit from `sun_direction_ecef` (towards the sun) with the neutral ground at `ground_m`
// (NaN: the lowest terrain in view) and every effect on.
inline scene::Scene lit_scene(const glm::dvec3& sun_direction_ecef, double ground_m = 0.0) {
  scene::Scene s;
  s.sun_direction_ecef = sun_direction_ecef;
  s.neutral_ground_m = ground_m;
  return s;
}

inline double luminance(const std::array<std::uint8_t, 4>& p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

// Mean luminance of the pixels within `radius` of (x, y).
inline double mean_luminance(const scene::RgbaImage& image, double x, double y, int radius) {
  double sum = 0.0;
  int n = 0;
  for (int j = -radius; j <= radius; ++j)
    for (int i = -radius; i <= radius; ++i) {
      const long px = std::lround(x) + i, py = std::lround(y) + j;
      if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
      sum += luminance(image.pixel(static_cast<std::uint32_t>(px), static_cast<std::uint32_t>(py)));
      ++n;
    }
  return n ? sum / n : 0.0;
}

// Writes the picture to $TRAILRAY_TEST_IMAGE_DIR/name when that is set.
inline void keep_image(const scene::RgbaImage& image, const std::string& name) {
  if (const char* dir = std::getenv("TRAILRAY_TEST_IMAGE_DIR"))
    scene::write_srgb_png(std::filesystem::path(dir) / name, image);
}

// The unit vector towards a sun at `azimuth_deg` (clockwise from north) and `elevation_deg`
// above the horizon of (lat, lon), in ECEF.
inline glm::dvec3 sun_from(double lat, double lon, double azimuth_deg, double elevation_deg) {
  const scene::EnuAxes enu = scene::enu_axes_at(lat, lon);
  const double az = azimuth_deg * M_PI / 180.0, el = elevation_deg * M_PI / 180.0;
  return std::cos(el) * (std::sin(az) * enu.east + std::cos(az) * enu.north) + std::sin(el) * enu.up;
}

using trailray::test::EastProfileSource;

}  // namespace trailray::render::test
