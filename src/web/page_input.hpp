#pragma once
// The pointer, wheel and keys the page's JavaScript hands over between frames, given to Dear
// ImGui one frame at a time. ImGui 1.86 reads states (io.MouseDown, io.KeysDown), not events:
// a press and a release that arrive between two frames are spread over two, so a quick click
// or key tap is not lost. Positions are CSS pixels of the canvas (ImGui's display units; the
// device pixel ratio is io.DisplayFramebufferScale).

#include <imgui.h>

#include <deque>
#include <optional>

namespace trailray::web {

class PageInput {
 public:
  PageInput();

  // `buttons`: the DOM's bit mask (1 left, 2 right, 4 middle); x NaN: the pointer left the canvas.
  void pointer(double x_css, double y_css, int buttons);
  // Wheel steps (DOM deltas already turned into lines; positive: away from the user, as ImGui).
  void wheel(double steps_y, double steps_x);
  // `key_code`: the DOM's keyCode (0..511); the modifiers as the event had them.
  void key(int key_code, bool down, bool ctrl, bool shift, bool alt, bool meta);
  void character(unsigned codepoint);

  // The next frame's input into `io` (and the key map on first use). True when a button, a key or
  // the wheel changed this frame: what the interface then shows may have been edited.
  bool apply(ImGuiIO& io);
  // Whether events wait for a frame.
  bool pending() const { return !events_.empty(); }
  // The pointer's position at the last apply (CSS pixels), nullopt when off the canvas.
  std::optional<ImVec2> position() const;
  // Whether it moved at the last apply.
  bool moved() const { return moved_; }

 private:
  struct Event {
    enum class Kind { pointer, wheel, key, character } kind;
    double x = 0.0, y = 0.0;
    int value = 0;  // buttons, key code, code point
    bool down = false, ctrl = false, shift = false, alt = false, meta = false;
  };
  std::deque<Event> events_;
  ImVec2 position_{-1.0f, -1.0f};
  bool inside_ = false;
  bool moved_ = false;
};

}  // namespace trailray::web
