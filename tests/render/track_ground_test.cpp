// Terrain inside the tube does not hide it (track_trace.glsl, terrain_inside_tube): a level
// track lying on flat ground, its centre exactly at the ground's height, seen obliquely, is the
// opaque tube over its whole silhouette, though the rays near its near-side edge meet the ground
// before they meet the tube (they used to draw a translucent ghost there), in metres and in
// pixels, with shadows too. Terrain that is not inside the tube still hides it: a track a few
// radii below flat ground is a ghost over its whole silhouette, and a track on the ground that
// passes under a raised slab (a forest canopy over a hike, in a surface model) is a ghost under
// it and opaque beside it. Every pixel's expected cover comes from the pixel's central ray
// against the tube's exact cylinder on the CPU; pixels within about a pixel of the silhouette
// are left out (anti-aliased fringe).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

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
using test::polyline;
using test::track_alpha;

constexpr scene::GeoPosition kPlace{46.5, 10.0, 0.0};
constexpr float kGhostAlpha = 0.45f;

class TrackGroundTest : public GlTest {};

// A camera south of the frame's origin, looking north and `pitch_deg` down at the point
// `up_m` above it from `distance_m`.
scene::Camera looking_north_at(const LocalFrame& frame, double up_m, double distance_m, double pitch_deg, const scene::Lens& lens) {
  const double pitch = pitch_deg * M_PI / 180.0;
  const glm::dvec3 eye = frame.point(0.0, -distance_m * std::cos(pitch), up_m + distance_m * std::sin(pitch));
  return scene::Camera(eye, 0.0, -pitch_deg, lens, scene::DepthRange{10.0, 1.0e5});
}

// An east-west line of points `up_m` above the frame's origin, every 20 m from -600 to 600 m
// east (wider than any of these pictures).
scene::TrackGeometry east_west_line(const LocalFrame& frame, double up_m) {
  std::vector<glm::dvec3> line;
  for (double east = -600.0; east <= 600.0; east += 20.0) line.push_back({east, 0.0, up_m});
  return test::geometry_of({polyline(frame, line)});
}

// What a pixel's central ray does with the tube around the east-west axis through the point
// `up_m` above the frame's origin (an infinite cylinder: the track runs past the picture's
// sides).
struct PixelOnTube {
  double miss_m = 0.0;      // how far the ray passes from the axis
  double pixel_m = 0.0;     // a pixel's size where it passes closest
  double east_m = 0.0;      // the axis point it passes closest to
  double entry_up_m = 0.0;  // height above the frame's origin where it enters the cylinder
};

PixelOnTube pixel_on_tube(const scene::Camera& camera, const LocalFrame& frame, double up_m, double radius_m, double x,
                          double y) {
  const scene::Ray ray = camera.ray_through_pixel(x, y);
  const glm::dvec3 eye = ray.origin, d = ray.direction, u = frame.axes.east;
  const glm::dvec3 w = eye - frame.point(0.0, 0.0, up_m);
  const glm::dvec3 d_across = d - u * glm::dot(d, u), w_across = w - u * glm::dot(w, u);
  const double across2 = glm::dot(d_across, d_across);
  const double t = -glm::dot(w_across, d_across) / across2;
  PixelOnTube p;
  p.miss_m = glm::length(w_across + d_across * t);
  const double lens_angle =
      2.0 * std::tan(0.5 * camera.lens().vertical_fov_deg * M_PI / 180.0) / camera.lens().height_px;
  p.pixel_m = lens_angle * t * glm::dot(d, camera.axes().forward);
  p.east_m = glm::dot(w + d * t, u);
  if (p.miss_m < radius_m) {
    const double entry = t - std::sqrt((radius_m * radius_m - p.miss_m * p.miss_m) / across2);
    p.entry_up_m = glm::dot(eye + d * entry - frame.origin, frame.axes.up);
  }
  return p;
}

// The tube's radius for a width: metres as given, pixels at the depth of the axis point nearest
// the camera (where every capsule of an east-west line seen from due south takes it).
double tube_radius_m(const scene::Camera& camera, const LocalFrame& frame, double up_m,
                     const scene::TrackWidth& width) {
  if (width.unit == scene::TrackWidth::Unit::metres) return 0.5 * width.value;
  const glm::dvec3 eye = camera.position();
  const glm::dvec3 to_axis = frame.point(0.0, 0.0, up_m) - eye;
  const glm::dvec3 nearest = to_axis - frame.axes.east * glm::dot(to_axis, frame.axes.east);
  const double lens_angle =
      2.0 * std::tan(0.5 * camera.lens().vertical_fov_deg * M_PI / 180.0) / camera.lens().height_px;
  return 0.5 * width.value * lens_angle * glm::dot(nearest, camera.axes().forward);
}

enum class Expect { skip, opaque, ghost };

struct CoverCount {
  int opaque = 0, ghost = 0, below_ground = 0, outside = 0, wrong = 0;
};

// Checks every pixel: where its central ray passes more than 0.6 px inside the tube's
// silhouette, the opaque tube (alpha > 0.9) or a ghost (the occluded alpha +- 0.06), as `expect`
// says for the axis point the ray passes nearest; more than a pixel outside it, nothing
// (alpha < 0.05) when `check_outside` (not with shadows: the tube's shadow darkens the ground).
// Counts the opaque pixels whose ray enters the tube below the ground (up < 0).
template <class ExpectAt>
CoverCount check_cover(const test::WithAndWithout& images, const scene::Camera& camera, const LocalFrame& frame, double up_m,
                       double radius_m, ExpectAt expect_at, bool check_outside, const std::string& what) {
  CoverCount count;
  for (std::uint32_t y = 0; y < images.with.height; ++y)
    for (std::uint32_t x = 0; x < images.with.width; ++x) {
      const PixelOnTube p = pixel_on_tube(camera, frame, up_m, radius_m, x + 0.5, y + 0.5);
      const double a = track_alpha(images.with, images.without, x, y);
      const auto fail = [&](const std::string& expected) {
        if (++count.wrong <= 8)
          ADD_FAILURE() << what << ", pixel (" << x << ", " << y << "), " << p.east_m << " m east, "
                        << (p.miss_m - radius_m) / p.pixel_m << " px from the silhouette, entering " << p.entry_up_m
                        << " m above the ground: alpha " << a << ", expected " << expected;
      };
      if (p.miss_m > radius_m + p.pixel_m) {
        ++count.outside;
        if (check_outside && a >= 0.05) fail("nothing");
        continue;
      }
      if (p.miss_m > radius_m - 0.6 * p.pixel_m) continue;
      const Expect expect = expect_at(p.east_m);
      if (expect == Expect::opaque) {
        ++count.opaque;
        count.below_ground += p.entry_up_m < 0.0 ? 1 : 0;
        if (!(a > 0.9)) fail("the opaque tube");
      } else if (expect == Expect::ghost) {
        ++count.ghost;
        if (!(std::abs(a - kGhostAlpha) < 0.06)) fail("a ghost");
      }
    }
  return count;
}

scene::Scene ground_options(const scene::TrackWidth& width) {
  scene::Scene options = test::plain_scene(kPlace, 0.0);
  options.style.tracks.width = width;
  options.style.tracks.occlusion.alpha = kGhostAlpha;
  options.style.tracks.occlusion.fade_near_m = 1.0e5f;  // constant alpha however deep
  options.style.tracks.occlusion.fade_far_m = 2.0e5f;
  return options;
}

// The track on the neutral ground at 0 m, its axis at 0 m: 20 m wide 300 m away, and 14 px
// wide 600 m away, seen 20 degrees down (a third of the tube's silhouette, its near side, is
// seen through the ground: those rays meet the ground before the tube); the pixel-wide one also
// with shadows, which light the tube where the ground cuts it like the rest; the metre-wide one
// also with the distances packed into RGBA8 (the G-buffer without float targets).
TEST_F(TrackGroundTest, ATrackLyingOnTheGroundIsTheOpaqueTubeOverItsWholeSilhouette) {
  const LocalFrame frame(kPlace);
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Lens lens{30.0, 320, 240};
  const scene::TrackSet buffer = test::track_set({test::track_of(east_west_line(frame, 0.0))});
  struct Case {
    scene::TrackWidth width;
    double distance_m;
    bool shadows;
    DistanceEncoding encoding;
    std::string name;
  };
  const DistanceEncoding native = renderer.renderer().distance_encoding();
  for (const Case& c :
       {Case{{20.0, scene::TrackWidth::Unit::metres}, 300.0, false, native, "20m"},
        Case{{20.0, scene::TrackWidth::Unit::metres}, 300.0, false, DistanceEncoding::packed_rgba8, "20m_packed"},
        Case{{14.0, scene::TrackWidth::Unit::pixels}, 600.0, false, native, "14px"},
        Case{{14.0, scene::TrackWidth::Unit::pixels}, 600.0, true, native, "14px_shadows"}}) {
    renderer.renderer().set_distance_encoding(c.encoding);
    const scene::Camera camera = looking_north_at(frame, 0.0, c.distance_m, 20.0, lens);
    scene::Scene options = ground_options(c.width);
    options.style.shading.shadows = c.shadows;
    const auto images = test::render_both(renderer, camera, options, buffer);
    keep_image(images.with, "track_on_ground_" + c.name + ".png");
    const double radius_m = tube_radius_m(camera, frame, 0.0, c.width);
    const CoverCount count = check_cover(
        images, camera, frame, 0.0, radius_m, [](double) { return Expect::opaque; }, !c.shadows, c.name);
    EXPECT_EQ(count.wrong, 0) << c.name;
    EXPECT_GT(count.opaque, 3000) << c.name << ": too little of the tube in the picture to judge";
    // 20 degrees down, the ground's line cuts the silhouette r sin 20 below the axis's image:
    // a third of its width lies below it, seen through the ground.
    EXPECT_GT(count.below_ground, count.opaque / 5) << c.name << ": the scene does not test the ground";
    EXPECT_GT(count.outside, 20000) << c.name;
  }
}

// The same track 3 radii (30 m) below the neutral ground: the ground is not inside the tube, so
// it hides all of it: a ghost over the whole silhouette.
TEST_F(TrackGroundTest, ATrackThreeRadiiBelowTheGroundIsAGhost) {
  const LocalFrame frame(kPlace);
  test::SceneDrawer renderer(nullptr, nullptr);
  const scene::Lens lens{30.0, 320, 240};
  const scene::TrackWidth width{20.0, scene::TrackWidth::Unit::metres};
  const scene::TrackSet buffer = test::track_set({test::track_of(east_west_line(frame, -30.0))});
  const scene::Camera camera = looking_north_at(frame, -30.0, 300.0, 30.0, lens);
  const auto images = test::render_both(renderer, camera, ground_options(width), buffer);
  keep_image(images.with, "track_below_ground.png");
  const CoverCount count = check_cover(
      images, camera, frame, -30.0, 10.0, [](double) { return Expect::ghost; }, true, "3 radii below");
  EXPECT_EQ(count.wrong, 0);
  EXPECT_GT(count.ghost, 3000) << "too little of the tube in the picture to judge";
}

// A hike on the ground (axis at 0 m, 20 m wide) passing under a slab 30 m high (3 radii above the
// axis), |east| < 80 m, like a forest canopy in a surface model: a ghost under the slab's top,
// the opaque tube well beside it (|east| > 150 m, where the rays pass above the slab's edge);
// between the two the slab's side cuts through the tube, and that is left out.
TEST_F(TrackGroundTest, ATrackUnderARaisedSlabIsAGhostThereAndOpaqueBesideIt) {
  const LocalFrame frame(kPlace);
  test::EastProfileSource slab("slab", kPlace.lat_deg, kPlace.lon_deg,
                               [](double east_m) { return std::abs(east_m) < 80.0 ? 30.0 : 0.0; });
  test::SceneDrawer renderer(&slab, nullptr);
  const scene::Lens lens{30.0, 480, 240};
  const scene::TrackWidth width{20.0, scene::TrackWidth::Unit::metres};
  const scene::TrackSet buffer = test::track_set({test::track_of(east_west_line(frame, 0.0))});
  const scene::Camera camera = looking_north_at(frame, 0.0, 350.0, 25.0, lens);
  const auto images = test::render_both(renderer, camera, ground_options(width), buffer);
  keep_image(images.with, "track_under_slab.png");
  const CoverCount count = check_cover(
      images, camera, frame, 0.0, 10.0,
      [](double east_m) {
        if (std::abs(east_m) < 40.0) return Expect::ghost;
        return std::abs(east_m) > 150.0 ? Expect::opaque : Expect::skip;
      },
      true, "under a slab");
  EXPECT_EQ(count.wrong, 0);
  EXPECT_GT(count.ghost, 1000) << "too little of the tube under the slab to judge";
  EXPECT_GT(count.opaque, 1000) << "too little of the tube beside the slab to judge";
  EXPECT_GT(count.below_ground, count.opaque / 5) << "the scene does not test the ground beside the slab";
}

}  // namespace
}  // namespace trailray::render
