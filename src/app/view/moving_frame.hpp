#pragma once
// The viewer's cheaper frame while the camera moves (a drag, keys, a fly-to, the replay's
// follow): half the resolution each way, scaled up into the window, the shadow maps of an earlier
// frame and no ambient occlusion; the full frame once the camera has rested `rest_s` (the picture
// at rest is the one `render` makes). Resting a moment before the full frame, rather than drawing
// it at the first still frame, keeps a drag that pauses between mouse events from paying for a
// full frame each time. No GL here: the decision alone, tested in tests/app/view.

#include <glm/glm.hpp>

#include <optional>

#include "scene/camera/camera.hpp"
#include "scene/style.hpp"

namespace trailray::app::view {

inline constexpr double kMovingFrameRestS = 0.2;  // at rest once the camera has not moved this long
inline constexpr int kMovingFrameDivisor = 2;     // the moving frame's pixels: the window's / 2 each way

class MotionWatch {
 public:
  explicit MotionWatch(double rest_s = kMovingFrameRestS) : rest_s_(rest_s) {}

  // The camera of the frame about to be drawn and the time since the last one: true while the
  // camera has moved within the last rest_s (the frame that moves it included). The first frame
  // is at rest.
  bool moving(const scene::Camera& camera, double elapsed_s);

 private:
  struct Pose {
    glm::dvec3 position, forward, up;
    double fov_deg;
    std::uint32_t width_px, height_px;
    bool operator==(const Pose&) const = default;
  };
  double rest_s_;
  std::optional<Pose> last_;
  double since_move_s_ = 0.0;
  bool moved_ = false;  // the camera has moved at least once
};

// The camera of the moving frame: the same view and field of view at 1/divisor the pixels
// (rounded up).
scene::Camera reduced_camera(const scene::Camera& full, int divisor = kMovingFrameDivisor);
// The style for it: sizes in pixels (tracks, pins) divided too, so that scaled up into the window
// they keep the width they have in the full frame.
scene::Style reduced_style(scene::Style style, int divisor = kMovingFrameDivisor);

}  // namespace trailray::app::view
