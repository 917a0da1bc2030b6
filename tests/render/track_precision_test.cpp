// Float precision next to the camera (DESIGN.md precision rule): a 20 cm tube 5 m below a camera
// that steps sideways 5 cm at a time moves across the picture smoothly, by the same amount at
// every step. Float arithmetic on large numbers would round positions to centimetres, and at
// 5 m a centimetre is about a pixel: the tube would stand still, then jump.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "geo/wgs84.hpp"
#include "gl_test_support.hpp"
#include "render/renderer.hpp"
#include "render/passes/track_pass.hpp"
#include "scene_test_support.hpp"
#include "track_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;
using test::keep_image;
using test::kTrackRed;
using test::LocalFrame;
using test::track_alpha;

const scene::Lens kLens{30.0, 320, 240};
constexpr double kTrackM = 800.0, kAboveM = 5.0, kStepM = 0.05;
constexpr int kSteps = 20;

class TrackPrecisionTest : public GlTest {
 protected:
  // The tube (north-south through `frame`'s origin at kTrackM) seen from kAboveM above it as the
  // camera steps east from -0.5 m: per step, the alpha-weighted mean column of the tube in the
  // middle rows, minus the column its axis projects to. A smooth pass keeps that difference
  // constant; rounding makes it wander.
  static std::vector<double> centroid_errors(const LocalFrame& frame, const scene::TrackGeometry& geometry,
                                             const std::string& name) {
    test::SceneDrawer renderer(nullptr, nullptr);
    const scene::TrackSet buffer = test::track_set({test::track_of(geometry)});
    const geo::Geodetic origin = geo::geodetic_from_ecef(frame.origin);
    const scene::GeoPosition place{origin.lat_deg, origin.lon_deg, origin.height_m};
    scene::Scene options = test::plain_scene(place, 0.0);
    options.style.tracks.width = {0.2, scene::TrackWidth::Unit::metres};
    std::vector<double> errors;
    for (int step = 0; step <= kSteps; ++step) {
      const double east = -0.5 + kStepM * step;
      const scene::Camera camera(frame.point(east, 0.0, kTrackM + kAboveM), 0.0, -90.0, kLens,
                          scene::DepthRange{0.5, 1.0e5});
      const auto images = test::render_both(renderer, camera, options, buffer);
      if (step == 0) keep_image(images.with, name);
      double sum = 0.0, weighted = 0.0;
      for (std::uint32_t y = kLens.height_px / 2 - 20; y < kLens.height_px / 2 + 20; ++y)
        for (std::uint32_t x = 0; x < kLens.width_px; ++x) {
          const double a = track_alpha(images.with, images.without, x, y);
          sum += a;
          weighted += a * (x + 0.5);
        }
      EXPECT_GT(sum, 40 * 10.0) << "step " << step << ": the tube is missing";
      const auto axis = camera.project(frame.point(0.0, 0.0, kTrackM));
      if (sum <= 0.0 || !axis) return {};
      errors.push_back(weighted / sum - axis->x_px);
    }
    return errors;
  }

  // Each step moves the tube f * 5 cm / 5 m = 4.5 px; the centroid keeps to its projected place
  // within a tenth of that, with no step standing out.
  static void expect_smooth(const std::vector<double>& errors, const std::string& what) {
    ASSERT_EQ(errors.size(), static_cast<std::size_t>(kSteps + 1)) << what;
    double mean = 0.0;
    for (const double e : errors) mean += e / static_cast<double>(errors.size());
    for (std::size_t i = 0; i < errors.size(); ++i)
      EXPECT_NEAR(errors[i], mean, 0.3) << what << ": step " << i << " (mean offset " << mean << " px)";
    EXPECT_NEAR(mean, 0.0, 1.0) << what << ": the tube is not where its axis projects";
  }
};

// A compact track far from the Earth's centre (as every place is): 200 m long, under the camera.
TEST_F(TrackPrecisionTest, ATubeFiveMetresAwayMovesSmoothlyWithTheCamera) {
  const LocalFrame frame({46.5, 10.0, 0.0});
  const auto geometry = test::geometry_of({test::polyline(frame, {{0, -100, kTrackM}, {0, 100, kTrackM}})});
  expect_smooth(centroid_errors(frame, geometry, "track_precision_near.png"), "compact track");
}

// The same tube, but its segment starts 300 km east (a long straight leg of a simplified flight):
// the block origin its points are stored relative to (the block's first point) is 300 km from
// the camera, where a float resolves 1.6 to 3 cm, and the offset lies across the tube, so the
// rounding of "origin minus eye" moves the tube sideways as the eye moves.
TEST_F(TrackPrecisionTest, ATubeFiveMetresAwayMovesSmoothlyWhenItsOriginIs300KmAway) {
  const LocalFrame frame({46.5, 10.0, 0.0});
  const auto geometry =
      test::geometry_of({test::polyline(frame, {{300000, -100, kTrackM}, {0, -100, kTrackM}, {0, 100, kTrackM}})});
  expect_smooth(centroid_errors(frame, geometry, "track_precision_far_origin.png"), "origin 300 km away");
}

}  // namespace
}  // namespace trailray::render
