// The capsules' level of detail against full detail (RendererOptions::track_level_of_detail): a
// dense track seen from afar draws far fewer capsules and every track pixel of either picture
// lies within a pixel of one of the other, in a colour of the scale close to it; seen from near,
// where no point can be dropped within half a pixel, the pictures are the same.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <vector>

#include "gl_test_support.hpp"
#include "render/renderer.hpp"
#include "scene_test_support.hpp"
#include "track_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;
using test::keep_image;
using test::LocalFrame;

constexpr scene::GeoPosition kPlace{46.5, 10.0, 0.0};
const scene::Lens kLens{40.0, 320, 240};

// A spiral 120 m between turns from 100 m to 1000 m round (seen from 5 km: 8 pixels, so 3-pixel
// tubes keep gaps between them), 300 m above the ground (at 1000 m), rising and falling 20 m, a
// point every 0.9 m, each moved up to half a metre at random (so no two consecutive capsules are
// exactly in line): from 5 km, about seventeen points a pixel.
scene::TrackPolyline dense_spiral(const LocalFrame& frame, std::size_t count) {
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> jitter(-0.5, 0.5);
  std::vector<glm::dvec3> enu;
  double angle = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const double radius = 100.0 + 120.0 * angle / (2.0 * M_PI);
    enu.push_back({radius * std::cos(angle) + jitter(random), radius * std::sin(angle) + jitter(random),
                   1300.0 + 20.0 * std::sin(0.01 * static_cast<double>(i)) + jitter(random)});
    angle += 0.9 / radius;
  }
  std::vector<float> values(count);
  for (std::size_t i = 0; i < count; ++i) values[i] = static_cast<float>(i);  // the colour runs along the track
  return test::polyline(frame, enu, values);
}

// Pixels where the track changes the picture (any channel by more than 40 of 255 from the
// picture without tracks): the tube, not its faint fringe.
std::vector<std::uint8_t> track_mask(const scene::RgbaImage& with, const scene::RgbaImage& without) {
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(with.width) * with.height, 0);
  for (std::uint32_t y = 0; y < with.height; ++y)
    for (std::uint32_t x = 0; x < with.width; ++x) {
      const auto p = with.pixel(x, y), q = without.pixel(x, y);
      for (int c = 0; c < 3; ++c)
        if (std::abs(static_cast<int>(p[c]) - static_cast<int>(q[c])) > 40) mask[y * with.width + x] = 1;
    }
  return mask;
}

int channel_difference(const scene::RgbaImage& a, std::uint32_t ax, std::uint32_t ay, const scene::RgbaImage& b,
                       std::uint32_t bx, std::uint32_t by) {
  const auto p = a.pixel(ax, ay), q = b.pixel(bx, by);
  int most = 0;
  for (int c = 0; c < 3; ++c) most = std::max(most, std::abs(static_cast<int>(p[c]) - static_cast<int>(q[c])));
  return most;
}

struct Comparison {
  int track_pixels = 0;
  int far = 0;      // no track pixel of the other picture within one pixel
  int inside = 0;   // track pixels whose eight neighbours are track pixels too
  int colours = 0;  // of those: none within one pixel whose colour is within the tolerance
};

// For each track pixel of `a`: is a track pixel of `b` within one pixel (the 3x3 around it), and,
// inside the tube, one of those in a colour within `tolerance` of it?
Comparison compare(const scene::RgbaImage& a, const std::vector<std::uint8_t>& mask_a, const scene::RgbaImage& b,
                   const std::vector<std::uint8_t>& mask_b, int tolerance) {
  Comparison out;
  const auto w = static_cast<int>(a.width), h = static_cast<int>(a.height);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (mask_a[static_cast<std::size_t>(y * w + x)] == 0) continue;
      ++out.track_pixels;
      bool near = false, close_colour = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u < 0 || v < 0 || u >= w || v >= h || mask_b[static_cast<std::size_t>(v * w + u)] == 0) continue;
          near = true;
          if (channel_difference(a, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), b,
                                 static_cast<std::uint32_t>(u), static_cast<std::uint32_t>(v)) <= tolerance)
            close_colour = true;
        }
      out.far += near ? 0 : 1;
      // Colours only inside the tube: at its edges the anti-aliased coverage blends it with the
      // ground, and a half-pixel shift changes that blend by up to half the contrast.
      bool inside = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int u = x + dx, v = y + dy;
          inside = inside && u >= 0 && v >= 0 && u < w && v < h && mask_a[static_cast<std::size_t>(v * w + u)] != 0;
        }
      out.inside += inside ? 1 : 0;
      out.colours += inside && !close_colour ? 1 : 0;
    }
  return out;
}

// Two renderers, with and without the level of detail, and a dense spiral coloured along its
// points over a plain ground.
class TrackLodRenderTest : public GlTest {
 protected:
  static constexpr std::size_t kPoints = 30000;
  static RendererOptions without_lod() {
    RendererOptions o;
    o.track_level_of_detail = false;
    return o;
  }
  static scene::Scene spiral_scene() {
    scene::Scene s = test::plain_scene(kPlace, 1000.0);
    s.style.tracks.width = {3.0, scene::TrackWidth::Unit::pixels};
    s.color_range = track::ValueRange{0.0, static_cast<double>(kPoints - 1)};
    return s;
  }
  test::SceneDrawer full{nullptr, nullptr, without_lod()};
  test::SceneDrawer lod{nullptr, nullptr};
  const scene::TrackSet tracks = test::track_set({test::track_of(
      test::geometry_of({dense_spiral(LocalFrame(kPlace), kPoints)}), test::kTrackRed, /*by_value=*/true)});
  scene::Scene options = spiral_scene();
};

TEST_F(TrackLodRenderTest, FromAfarADenseTrackDrawsFewerCapsulesWithinAPixelAndItsColoursOfTheFullPicture) {
  const scene::Camera camera = test::looking_down({kPlace.lat_deg, kPlace.lon_deg, 6000.0}, kLens, 100.0);

  const test::WithAndWithout reference = test::render_both(full, camera, options, tracks);
  options.tracks = &tracks;
  const test::Drawn drawn = lod.draw(camera, options);
  const test::Drawn drawn_full = full.draw(camera, options);
  keep_image(reference.with, "track_lod_full.png");
  keep_image(drawn.image, "track_lod_merged.png");

  EXPECT_EQ(drawn_full.report.track_capsules, kPoints - 1);
  EXPECT_LT(drawn.report.track_capsules, (kPoints - 1) / 4) << "about seventeen points a pixel: the capsules merge";
  EXPECT_GT(drawn.report.track_capsules, 100u) << "the spiral's 1700 pixels of length still need their capsules";

  // Both ways round: a merged capsule lies within half a pixel of the points it replaces, so its
  // silhouette moves at most that far; one pixel allows for the rounding to pixels. Colours,
  // inside the tubes: the merged capsule's value is within 1/32 of the scale of the dropped
  // points' (TrackLod), at most 8 of the colour map's 256 entries, and its shading follows the
  // tube's normal, which a half-pixel shift of a 3-pixel tube changes a little; 32 of 255 per
  // channel holds both and still tells a wrong point's colour (the scale runs along 30000 points,
  // a wrong index is a colour from elsewhere on it). The full picture's tubes look a little
  // wider: each of the many capsules a pixel holds adds its own anti-aliased fringe, so pixel
  // counts are not compared.
  const std::vector<std::uint8_t> mask_full = track_mask(reference.with, reference.without);
  const std::vector<std::uint8_t> mask_lod = track_mask(drawn.image, reference.without);
  const Comparison lod_in_full = compare(drawn.image, mask_lod, reference.with, mask_full, 32);
  const Comparison full_in_lod = compare(reference.with, mask_full, drawn.image, mask_lod, 32);
  EXPECT_GT(lod_in_full.track_pixels, 5000) << "too little track to judge";
  EXPECT_GT(lod_in_full.inside, 1000) << "too little inside the tubes to judge the colours";
  EXPECT_EQ(lod_in_full.far, 0);
  EXPECT_EQ(full_in_lod.far, 0);
  EXPECT_EQ(lod_in_full.colours, 0);
  EXPECT_EQ(full_in_lod.colours, 0);
}

TEST_F(TrackLodRenderTest, FromNearWhereNoPointCanBeDroppedThePicturesAreTheSame) {
  // 40 m above the spiral's start, 100 m east of the centre (a pixel: 0.03 m there; the points
  // stray up to half a metre from a line).
  const double east_deg = 100.0 / (111320.0 * std::cos(kPlace.lat_deg * M_PI / 180.0));
  const scene::Camera camera =
      test::looking_down({kPlace.lat_deg, kPlace.lon_deg + east_deg, 1000.0 + 340.0}, kLens, 1.0);
  const test::WithAndWithout drawn = test::render_both(lod, camera, options, tracks);
  options.tracks = &tracks;
  const test::Drawn drawn_full = full.draw(camera, options);
  keep_image(drawn.with, "track_lod_near.png");
  int differ = 0, track = 0;
  for (std::uint32_t y = 0; y < kLens.height_px; ++y)
    for (std::uint32_t x = 0; x < kLens.width_px; ++x) {
      differ += channel_difference(drawn.with, x, y, drawn_full.image, x, y) > 0 ? 1 : 0;
      track += channel_difference(drawn.with, x, y, drawn.without, x, y) > 40 ? 1 : 0;
    }
  EXPECT_GT(track, 200) << "the track is in view";
  EXPECT_EQ(differ, 0);
}

}  // namespace
}  // namespace trailray::render
