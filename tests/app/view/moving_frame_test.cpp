// The moving frame's decision (moving_frame.hpp): reduced from the frame that moves the camera
// until it has rested for the rest time, never before the camera first moves; its camera sees
// the same view with fewer pixels, and its style halves the sizes given in pixels.
#include <gtest/gtest.h>

#include "app/view/moving_frame.hpp"

namespace trailray::app::view {
namespace {

scene::Camera camera_heading(double heading_deg, std::uint32_t width = 1280, std::uint32_t height = 720) {
  auto made = scene::camera_at({{46.7, 7.85, 3000.0}, heading_deg, -30.0}, scene::Lens{45.0, width, height}, 500.0);
  if (!made.ok()) throw std::runtime_error(made.error);
  return *made.value;
}

TEST(MotionWatch, AStillCameraIsAtRestFromTheStart) {
  MotionWatch watch(0.2);
  for (int i = 0; i < 10; ++i) EXPECT_FALSE(watch.moving(camera_heading(10.0), 0.05)) << i;
}

TEST(MotionWatch, MovingUntilTheCameraRestedTheRestTime) {
  MotionWatch watch(0.2);
  EXPECT_FALSE(watch.moving(camera_heading(10.0), 0.0));
  EXPECT_TRUE(watch.moving(camera_heading(11.0), 0.05)) << "the frame that moves it";
  EXPECT_TRUE(watch.moving(camera_heading(12.0), 0.05));
  // Still from here: 0.05, 0.10, 0.15 s rested, then 0.20.
  EXPECT_TRUE(watch.moving(camera_heading(12.0), 0.05));
  EXPECT_TRUE(watch.moving(camera_heading(12.0), 0.05));
  EXPECT_TRUE(watch.moving(camera_heading(12.0), 0.05));
  EXPECT_FALSE(watch.moving(camera_heading(12.0), 0.05)) << "rested 0.2 s: the full frame";
  EXPECT_FALSE(watch.moving(camera_heading(12.0), 0.05));
  // A long frame counts whole: one slow still frame can end the motion.
  EXPECT_TRUE(watch.moving(camera_heading(13.0), 0.05));
  EXPECT_FALSE(watch.moving(camera_heading(13.0), 0.5));
}

TEST(MotionWatch, AResizedWindowCountsAsMoving) {
  MotionWatch watch(0.2);
  EXPECT_FALSE(watch.moving(camera_heading(10.0), 0.0));
  EXPECT_TRUE(watch.moving(camera_heading(10.0, 1000, 600), 0.01));
}

TEST(ReducedCamera, SeesTheSameViewWithHalfThePixels) {
  const scene::Camera full = camera_heading(30.0, 1281, 721);
  const scene::Camera reduced = reduced_camera(full, 2);
  EXPECT_EQ(reduced.lens().width_px, 641u);  // rounded up
  EXPECT_EQ(reduced.lens().height_px, 361u);
  EXPECT_EQ(reduced.position(), full.position());
  EXPECT_DOUBLE_EQ(reduced.lens().vertical_fov_deg, full.lens().vertical_fov_deg);
  // A point in view lands at half its pixel coordinates (within the rounding of the odd size).
  const glm::dvec3 point = full.position() + 2000.0 * full.axes().forward + 300.0 * full.axes().right;
  const auto a = full.project(point), b = reduced.project(point);
  ASSERT_TRUE(a && b);
  EXPECT_NEAR(b->x_px, a->x_px / 2.0, 0.6);
  EXPECT_NEAR(b->y_px, a->y_px / 2.0, 0.6);
}

TEST(ReducedStyle, HalvesWhatIsGivenInPixels) {
  scene::Style style;
  style.tracks.width = {6.0, scene::TrackWidth::Unit::pixels};
  style.tracks.min_width_px = 1.5;
  const scene::Style reduced = reduced_style(style, 2);
  EXPECT_DOUBLE_EQ(reduced.tracks.width.value, 3.0);
  EXPECT_DOUBLE_EQ(reduced.tracks.min_width_px, 0.75);
  EXPECT_DOUBLE_EQ(reduced.pins.marker_px, style.pins.marker_px / 2.0);
  EXPECT_DOUBLE_EQ(reduced.pins.lift_px, style.pins.lift_px / 2.0);
  style.tracks.width = {8.0, scene::TrackWidth::Unit::metres};
  EXPECT_DOUBLE_EQ(reduced_style(style, 2).tracks.width.value, 8.0) << "metres stay metres";
}

}  // namespace
}  // namespace trailray::app::view
