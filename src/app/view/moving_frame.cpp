#include "app/view/moving_frame.hpp"

namespace trailray::app::view {

bool MotionWatch::moving(const scene::Camera& camera, double elapsed_s) {
  const Pose pose{camera.position(),      camera.axes().forward,  camera.axes().up, camera.lens().vertical_fov_deg,
                  camera.lens().width_px, camera.lens().height_px};
  since_move_s_ += elapsed_s;
  if (last_ && !(*last_ == pose)) {
    since_move_s_ = 0.0;
    moved_ = true;
  }
  last_ = pose;
  return moved_ && since_move_s_ < rest_s_;
}

scene::Camera reduced_camera(const scene::Camera& full, int divisor) {
  scene::Lens lens = full.lens();
  const auto d = static_cast<std::uint32_t>(divisor);
  lens.width_px = (lens.width_px + d - 1) / d;
  lens.height_px = (lens.height_px + d - 1) / d;
  return {full.position(), full.heading_deg(), full.pitch_deg(), lens, full.depth_range()};
}

scene::Style reduced_style(scene::Style style, int divisor) {
  const double d = divisor;
  if (style.tracks.width.unit == scene::TrackWidth::Unit::pixels) style.tracks.width.value /= d;
  style.tracks.min_width_px /= d;
  scene::PinStyle& pins = style.pins;
  for (double* px : {&pins.marker_px, &pins.place_marker_px, &pins.stem_px, &pins.lift_px, &pins.place_lift_px})
    *px /= d;
  return style;
}

}  // namespace trailray::app::view
