// A track straight through a ridge of a real DEM (the swisstopo DHM25 around Interlaken): the
// renderer draws it opaque where the camera sees it and as a translucent ghost where the terrain
// hides it, with the boundary where a ray marched on the CPU over the raster's own heights puts
// it. The rendered terrain is the raster warped into tiles, the CPU's the raster itself
// (bilinear on its grid): they differ by a metre or so, which moves a grazing boundary by a few
// pixels, so samples near a boundary are left out.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "geo/wgs84.hpp"
#include "gl_test_support.hpp"
#include "render/renderer.hpp"
#include "render/passes/track_pass.hpp"
#include "scene_test_support.hpp"
#include "terrain/height_sampler.hpp"
#include "terrain/sources/source_factory.hpp"
#include "test_support.hpp"
#include "track_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;
using test::keep_image;
using test::kTrackRed;
using test::pixel_of;
using test::track_alpha;

class TrackRealRidgeTest : public GlTest {};

// Whether the terrain hides `point` from `eye`: the line between them in 5 m steps, each
// step's height above the ellipsoid against the raster's height below it.
bool terrain_hides(terrain::HeightSampler& sampler, const glm::dvec3& eye, const glm::dvec3& point) {
  const double length = glm::length(point - eye);
  const int steps = static_cast<int>(length / 5.0);
  for (int i = 1; i < steps; ++i) {
    const glm::dvec3 q = glm::mix(eye, point, static_cast<double>(i) / steps);
    const geo::Geodetic g = geo::geodetic_from_ecef(q);
    const double lat = g.lat_deg, lon = g.lon_deg, h = g.height_m;
    const double ground = sampler.sample(lat, lon);
    if (!std::isnan(ground) && h < ground) return true;
  }
  return false;
}

// Along 46.71 N the DEM rises from a valley at 7.846 E (772 m) to a crest at 7.868 E (1583 m)
// and falls to the plain at 7.92 E (563 m): a track at 1200 m from 7.84 to 7.91 E runs into the
// mountain and out again. Seen from 2.8 km south-south-west, a little above it.
TEST_F(TrackRealRidgeTest, ATrackThroughARealRidgeIsOpaqueInFrontAndAGhostBehindIt) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/interlaken_dhm25_wgs84.tif");
  terrain::SourceSettings settings;
  settings.source = dem.string();
  auto source = terrain::open_height_source(settings, {});
  ASSERT_TRUE(source);
  terrain::HeightSampler sampler(*source);
  test::SceneDrawer renderer(source.get(), nullptr);

  constexpr double kLat = 46.71, kTrackM = 1200.0, kWidthPx = 5.0;
  constexpr float kAlpha = 0.45f;
  const scene::Lens lens{50.0, 480, 270};
  const auto made = scene::camera_at({{46.685, 7.866, 1450.0}, 5.0, -4.0}, lens, 600.0);
  ASSERT_TRUE(made.ok()) << made.error;
  const scene::Camera& camera = *made.value;
  const glm::dvec3 eye = camera.position();

  scene::TrackGeometry geometry;
  scene::TrackPolyline line;
  for (double lon = 7.840; lon <= 7.9101; lon += 0.001)
    line.points_ecef.push_back(scene::ecef_from({kLat, lon, kTrackM}));
  geometry.segments.push_back(line);
  const scene::TrackSet buffer = test::track_set({test::track_of(geometry)});
  scene::Scene options = test::plain_scene({kLat, 7.87, 0.0}, 560.0);
  options.style.tracks.width = {kWidthPx, scene::TrackWidth::Unit::pixels};
  options.style.tracks.occlusion.alpha = kAlpha;
  options.style.tracks.occlusion.fade_near_m = 1.0e5f;  // constant alpha however deep
  options.style.tracks.occlusion.fade_far_m = 2.0e5f;
  options.style.tracks.cast_shadows = false;
  const auto images = test::render_both(renderer, camera, options, buffer);
  keep_image(images.with, "track_through_real_ridge.png");

  // Every 10 m along the track: its pixel, and whether the CPU sees the tube's near side.
  const double pixel_angle = 2.0 * std::tan(0.5 * lens.vertical_fov_deg * M_PI / 180.0) / lens.height_px;
  std::vector<test::VisibilitySample> samples;
  for (double lon = 7.841; lon <= 7.909; lon += 0.000131) {
    const glm::dvec3 centre = scene::ecef_from({kLat, lon, kTrackM});
    const glm::dvec3 towards_eye = glm::normalize(eye - centre);
    const double radius = 0.5 * kWidthPx * pixel_angle * glm::length(eye - centre);
    test::VisibilitySample s{0, 0, terrain_hides(sampler, eye, centre + towards_eye * radius),
                             std::to_string(lon) + " E"};
    if (pixel_of(camera, centre, s.x, s.y)) samples.push_back(s);
  }
  ASSERT_GT(samples.size(), 300u) << "the track is not in the picture";
  const bool some_hidden = std::any_of(samples.begin(), samples.end(), [](const auto& s) { return s.hidden; });
  ASSERT_TRUE(some_hidden) << "the ridge hides nothing of the track: the scene is wrong";
  const test::VisibilityCount count = test::check_visibility(samples, images, kAlpha, 0.08, 6.0);
  EXPECT_EQ(count.wrong, 0);
  EXPECT_GT(count.opaque, 50) << "too little of the track in front of the ridge to judge";
  EXPECT_GT(count.ghost, 50) << "too little of the track inside the ridge to judge";
}

}  // namespace
}  // namespace trailray::render
