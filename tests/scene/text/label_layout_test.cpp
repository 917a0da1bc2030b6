// The labels' layout (pure CPU): what is dropped (behind the camera, off the picture, faded out,
// no room), that no two placed boxes ever overlap or touch the legend, the priority order (kind,
// then the waypoint's priority, then the nearer), the fade by distance, the pixel ratio, and the
// candidates a scene gives.

#include <gtest/gtest.h>

#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include "scene/camera/camera.hpp"
#include "scene/text/label_layout.hpp"
#include "scene/text/label_raster.hpp"
#include "scene/scene.hpp"
#include "scene/tracks/track_set.hpp"
#include "scene/pins/waypoints.hpp"

namespace trailray::scene {
namespace {

constexpr GeoPosition kPlace{46.5, 10.0, 0.0};

// Points as metres east, north and up of kPlace.
glm::dvec3 at(double east_m, double north_m, double up_m = 0.0) {
  const EnuAxes axes = enu_axes_at(kPlace.lat_deg, kPlace.lon_deg);
  return ecef_from(kPlace) + east_m * axes.east + north_m * axes.north + up_m * axes.up;
}

// 1000 m above kPlace looking straight down, north up in the picture: about 830 m of ground
// across the 640 pixels.
Camera camera_above(const Lens& lens = {45.0, 640, 480}) {
  return Camera(at(0, 0, 1000), 0.0, -90.0, lens, DepthRange{1.0, 1.0e5});
}

LabelCandidate candidate(std::string text, LabelKind kind, glm::dvec3 anchor, int priority = 0) {
  LabelCandidate c;
  c.text = std::move(text);
  c.kind = kind;
  c.anchor_ecef = anchor;
  c.priority = priority;
  return c;
}

const PlacedLabel* find(const std::vector<PlacedLabel>& placed, const std::string& text) {
  for (const PlacedLabel& p : placed)
    if (p.text == text) return &p;
  return nullptr;
}

TEST(LabelLayout, NothingBehindTheCameraOrOutsideThePictureIsPlaced) {
  LabelLayouter layouter;
  const Camera camera = camera_above();
  const std::vector<LabelCandidate> candidates{
      candidate("ground", LabelKind::waypoint, at(0, 0)),
      candidate("above the camera", LabelKind::waypoint, at(0, 0, 1500)),  // behind it
      candidate("far east", LabelKind::waypoint, at(5000, 0)),             // outside the picture
  };
  const std::vector<PlacedLabel> placed = layouter.layout(candidates, camera, {});
  ASSERT_EQ(placed.size(), 1u);
  EXPECT_EQ(placed[0].text, "ground");
  EXPECT_NEAR(placed[0].anchor_px.x, 320.0, 1.0);
  EXPECT_NEAR(placed[0].anchor_px.y, 240.0, 1.0);
  EXPECT_NEAR(placed[0].anchor_distance_m, 1000.0, 0.5);
  // Its first choice: centred just above the anchor.
  EXPECT_LT(placed[0].box.bottom(), 240);
  EXPECT_GE(placed[0].box.bottom(), 240 - 2 * label_lift_px(placed[0].font_px));
  EXPECT_NEAR(placed[0].box.x + placed[0].box.width / 2.0, 320.0, 1.0);
}

TEST(LabelLayout, NoTwoLabelsOverlapNorCoverAPinInRandomCrowdedScenes) {
  LabelLayouter layouter;
  const Camera camera = camera_above();
  const PixelRect legend{8, 400, 200, 72};
  LabelLayoutOptions options;
  options.keep_out = {legend};
  for (unsigned seed = 1; seed <= 12; ++seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> across(-450.0, 450.0), up(0.0, 300.0);
    std::uniform_int_distribution<int> kind(0, 2), length(1, 24), priority(-2, 2);
    std::vector<LabelCandidate> candidates;
    for (int i = 0; i < 300; ++i)
      candidates.push_back(candidate(
          std::string(static_cast<std::size_t>(length(random)), static_cast<char>('A' + i % 26)),
          static_cast<LabelKind>(kind(random)), at(across(random), across(random), up(random)), priority(random)));
    // Every waypoint has a pin (the pins' clearance) that no label may cover.
    std::vector<PixelRect> pins;
    for (LabelCandidate& c : candidates) {
      if (c.kind != LabelKind::waypoint) continue;
      c.clear_px = c.clear_width_px = 12.0;
      const auto p = camera.project(c.anchor_ecef);
      if (p)
        pins.push_back({static_cast<int>(std::floor(p->x_px)) - 6, static_cast<int>(std::floor(p->y_px)) - 12, 12, 12});
    }
    const std::vector<PlacedLabel> placed = layouter.layout(candidates, camera, options);
    ASSERT_GT(placed.size(), 10u) << "seed " << seed;
    for (const PlacedLabel& label : placed)
      for (const PixelRect& pin : pins) EXPECT_FALSE(label.box.intersects(pin)) << label.text << ", seed " << seed;
    ASSERT_LT(placed.size(), candidates.size()) << "seed " << seed;
    const PixelRect picture{0, 0, 640, 480};
    for (std::size_t i = 0; i < placed.size(); ++i) {
      const PlacedLabel& a = placed[i];
      EXPECT_TRUE(picture.contains(a.box)) << "seed " << seed;
      EXPECT_FALSE(a.box.intersects(legend)) << "seed " << seed;
      const int m = label_margin_px(a.font_px);
      const PixelRect grown{a.box.x - m, a.box.y - m, a.box.width + 2 * m, a.box.height + 2 * m};
      for (std::size_t j = i + 1; j < placed.size(); ++j)
        EXPECT_FALSE(grown.intersects(placed[j].box)) << "seed " << seed << ": " << i << " and " << j;
    }
  }
}

TEST(LabelLayout, ATrackNameBeatsAWaypointWhichBeatsAPlace) {
  LabelLayouter layouter;
  // At one anchor only two boxes fit (above and below); the candidates come in reverse order.
  const std::vector<LabelCandidate> candidates{
      candidate("Place", LabelKind::place, at(0, 0), 5),
      candidate("Waypoint", LabelKind::waypoint, at(0, 0)),
      candidate("Track", LabelKind::track, at(0, 0)),
  };
  const std::vector<PlacedLabel> placed = layouter.layout(candidates, camera_above(), {});
  ASSERT_EQ(placed.size(), 2u);
  EXPECT_EQ(placed[0].text, "Track");
  EXPECT_LT(placed[0].box.bottom(), 240);  // above: the first choice
  EXPECT_EQ(placed[1].text, "Waypoint");
  EXPECT_EQ(find(placed, "Place"), nullptr);
}

TEST(LabelLayout, TheNearerWinsAtEqualPriorityAndPriorityBeatsDistance) {
  LabelLayouter layouter;
  // Three points on one line of sight: the same pixel, 1000, 700 and 400 m from the camera.
  const std::vector<LabelCandidate> same{
      candidate("far", LabelKind::waypoint, at(0, 0, 0)),
      candidate("middle", LabelKind::waypoint, at(0, 0, 300)),
      candidate("near", LabelKind::waypoint, at(0, 0, 600)),
  };
  LabelLayoutOptions no_fade;
  no_fade.fade = LabelFade{1.0e6, 2.0e6};
  std::vector<PlacedLabel> placed = layouter.layout(same, camera_above(), no_fade);
  ASSERT_EQ(placed.size(), 2u);
  EXPECT_EQ(placed[0].text, "near");
  EXPECT_EQ(placed[1].text, "middle");

  std::vector<LabelCandidate> ranked = same;
  ranked[0].priority = 1;  // the far one matters more
  placed = layouter.layout(ranked, camera_above(), no_fade);
  ASSERT_EQ(placed.size(), 2u);
  EXPECT_EQ(placed[0].text, "far");
  EXPECT_EQ(placed[1].text, "near");
}

TEST(LabelLayout, OpacityFallsWithDistance) {
  const LabelFade fade{1000.0, 3000.0};
  float previous = 1.0f;
  for (double d = 0.0; d <= 4000.0; d += 50.0) {
    const float alpha = label_fade_alpha(d, fade);
    EXPECT_LE(alpha, previous) << d;
    previous = alpha;
  }
  EXPECT_EQ(label_fade_alpha(1000.0, fade), 1.0f);
  EXPECT_FLOAT_EQ(label_fade_alpha(2000.0, fade), 0.5f);
  EXPECT_EQ(label_fade_alpha(3000.0, fade), 0.0f);

  // In a layout: points further down a slanted view get fainter, past zero_m they are gone.
  LabelLayouter layouter;
  const Camera oblique(at(0, 0, 1000), 0.0, -20.0, {45.0, 1280, 720}, DepthRange{1.0, 1.0e6});
  std::vector<LabelCandidate> candidates;
  for (int i = 0; i < 8; ++i)
    candidates.push_back(candidate("P" + std::to_string(i), LabelKind::waypoint, at(i * 300.0, 1500.0 + i * 900.0)));
  LabelLayoutOptions options;
  options.fade = LabelFade{3000.0, 6000.0};
  const std::vector<PlacedLabel> placed = layouter.layout(candidates, oblique, options);
  ASSERT_GE(placed.size(), 4u);
  for (std::size_t i = 1; i < placed.size(); ++i) {
    EXPECT_GT(placed[i].anchor_distance_m, placed[i - 1].anchor_distance_m);  // equal rank: nearer first
    EXPECT_LE(placed[i].alpha, placed[i - 1].alpha);
  }
  EXPECT_EQ(placed.front().alpha, 1.0f);
  EXPECT_LT(placed.back().alpha, 1.0f);
  for (const PlacedLabel& p : placed) EXPECT_LT(p.anchor_distance_m, 6000.0);
}

TEST(LabelLayout, ByDefaultTheFadeFollowsTheSubjectDistance) {
  LabelLayouter layouter;
  // One label alone is what the picture is about: never faded, however far.
  const Camera far_camera(at(0, 0, 50000), 0.0, -90.0, {45.0, 640, 480}, DepthRange{10.0, 1.0e6});
  const auto alone = layouter.layout({candidate("alone", LabelKind::waypoint, at(0, 0))}, far_camera, {});
  ASSERT_EQ(alone.size(), 1u);
  EXPECT_EQ(alone[0].alpha, 1.0f);
}

TEST(LabelLayout, TheKeepOutAreasAndThePictureEdgesAreRespected) {
  LabelLayouter layouter;
  LabelLayoutOptions options;
  options.keep_out = {{200, 150, 240, 180}};  // around the picture's centre, where the anchor is
  EXPECT_TRUE(layouter.layout({candidate("hidden", LabelKind::waypoint, at(0, 0))}, camera_above(), options).empty());
  // At the top edge the label goes below its anchor.
  const Camera camera = camera_above();
  const auto top = camera.project(at(0, 400));
  ASSERT_TRUE(top && top->y_px < 20.0);
  const auto placed = layouter.layout({candidate("edge", LabelKind::waypoint, at(0, 400))}, camera, {});
  ASSERT_EQ(placed.size(), 1u);
  EXPECT_GT(placed[0].box.y, top->y_px);
}

TEST(LabelLayout, AWaypointsLabelKeepsItsPinClear) {
  LabelLayouter layouter;
  LabelCandidate bare = candidate("Hut", LabelKind::waypoint, at(0, 0));
  LabelCandidate pinned = bare;
  pinned.clear_px = 30.0;
  pinned.clear_m = 5.0;  // 1.73 m a pixel at 1000 m: the pixels decide
  const auto a = layouter.layout({bare}, camera_above(), {});
  const auto b = layouter.layout({pinned}, camera_above(), {});
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].box.bottom(), a[0].box.bottom() - 30);
  // Near the camera the metres decide: 100 m at 1000 m are about 58 pixels.
  pinned.clear_px = 0.0;
  pinned.clear_m = 100.0;
  const auto c = layouter.layout({pinned}, camera_above(), {});
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].box.bottom(), a[0].box.bottom() - 58, 1.0);
}

TEST(LabelLayout, ThePixelRatioScalesTheBoxes) {
  LabelLayouter layouter;
  const std::vector<LabelCandidate> one{candidate("Rifugio", LabelKind::waypoint, at(0, 0))};
  LabelLayoutOptions options;
  const auto normal = layouter.layout(one, camera_above({45.0, 640, 480}), options);
  options.pixel_ratio = 2.0;
  const auto doubled = layouter.layout(one, camera_above({45.0, 1280, 960}), options);
  ASSERT_EQ(normal.size(), 1u);
  ASSERT_EQ(doubled.size(), 1u);
  EXPECT_EQ(doubled[0].font_px, 2 * normal[0].font_px);
  EXPECT_NEAR(doubled[0].box.width, 2.0 * normal[0].box.width, 0.15 * normal[0].box.width);
  EXPECT_NEAR(doubled[0].box.height, 2.0 * normal[0].box.height, 0.15 * normal[0].box.height);
}

TEST(LabelLayout, TheRasterHasTheTextInsideItsHalo) {
  LabelLayouter layouter;
  const auto placed = layouter.layout({candidate("Hut", LabelKind::waypoint, at(0, 0))}, camera_above(), {});
  ASSERT_EQ(placed.size(), 1u);
  const LabelBitmap bitmap = rasterize_label(layouter.text(), placed[0]);
  ASSERT_EQ(bitmap.width, placed[0].box.width);
  ASSERT_EQ(bitmap.height, placed[0].box.height);
  int text = 0, halo_only = 0;
  for (int y = 0; y < bitmap.height; ++y)
    for (int x = 0; x < bitmap.width; ++x) {
      EXPECT_GE(bitmap.halo(x, y), bitmap.text(x, y));  // the halo covers the text
      if (bitmap.text(x, y) > 128) ++text;
      if (bitmap.halo(x, y) > 128 && bitmap.text(x, y) == 0) ++halo_only;
    }
  EXPECT_GT(text, 20);
  EXPECT_GT(halo_only, 20);
  // Nothing on the box's edge rows is text: the halo has room.
  for (int x = 0; x < bitmap.width; ++x) EXPECT_EQ(bitmap.text(x, 0), 0);
}

TEST(LabelCandidates, NamedVisibleWaypointsPlacesAndTrackStarts) {
  TrackSet tracks;
  Track shown;
  shown.name = "Morning ride";
  shown.geometry.segments = {TrackPolyline{}, TrackPolyline{{at(10, 20), at(30, 40)}, {}, {}}};
  tracks.add(shown);
  Track hidden = shown;
  hidden.name = "hidden";
  hidden.visible = false;
  tracks.add(hidden);
  WaypointSet points;
  Waypoint hut;
  hut.name = "Hut";
  hut.marker_ecef = at(1, 2, 3);
  hut.priority = 4;
  points.points = {hut};
  Waypoint peak = hut;
  peak.name = "Peak";
  peak.kind = WaypointKind::Place;
  points.points.push_back(peak);
  Waypoint unnamed = hut;
  unnamed.name.clear();
  points.points.push_back(unnamed);
  Waypoint invisible = hut;
  invisible.visible = false;
  points.points.push_back(invisible);

  Scene scene;
  scene.tracks = &tracks;
  scene.waypoints = &points;
  const std::vector<LabelCandidate> c = label_candidates(scene);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].text, "Morning ride");
  EXPECT_EQ(c[0].kind, LabelKind::track);
  EXPECT_EQ(c[0].anchor_ecef, at(10, 20));  // the first point of the first non-empty segment
  EXPECT_EQ(c[1].text, "Hut");
  EXPECT_EQ(c[1].kind, LabelKind::waypoint);
  EXPECT_EQ(c[1].priority, 4);
  EXPECT_EQ(c[1].anchor_ecef, hut.marker_ecef);
  EXPECT_EQ(c[2].kind, LabelKind::place);

  scene.style.labels.enabled = false;
  EXPECT_TRUE(label_candidates(scene).empty());
}

}  // namespace
}  // namespace trailray::scene
