#pragma once
// The viewer's keys as actions, whatever sends them: each front end maps its own key codes (the
// desktop GLFW's, the page the DOM's) to these, and the session (viewer_session.hpp) carries
// them out the same way.
//
//   W / up, S / down, D / right, A / left   move the camera forward, back, right, left
//   Q, E                                    orbit left, right
//   Page Up, Page Down                      tilt up, down
//   = / keypad +, - / keypad -              zoom in, out (toward the picture's centre)
//   N                                       turn to north
//   F                                       fly to the selected track
//   space                                   play or pause the replay

#include <bitset>
#include <cstddef>

namespace trailray::ui {

enum class ViewerKey {
  forward,
  back,
  right,
  left,
  orbit_left,
  orbit_right,
  tilt_up,
  tilt_down,
  zoom_in,
  zoom_out,
  north,
  fly_to_selected,
  play_pause,
};
inline constexpr std::size_t kViewerKeyCount = static_cast<std::size_t>(ViewerKey::play_pause) + 1;

// One frame's keys: those held down (the moves act each frame they are held, by the frame's
// time) and those pressed this frame (the rest act once per press).
struct KeyInput {
  std::bitset<kViewerKeyCount> held, pressed;
  void hold(ViewerKey k) { held.set(static_cast<std::size_t>(k)); }
  void press(ViewerKey k) { pressed.set(static_cast<std::size_t>(k)); }
  bool is_held(ViewerKey k) const { return held.test(static_cast<std::size_t>(k)); }
  bool was_pressed(ViewerKey k) const { return pressed.test(static_cast<std::size_t>(k)); }
};

}  // namespace trailray::ui
