#include "web/page_input.hpp"

#include <cfloat>
#include <cmath>

namespace trailray::web {
namespace {

// ImGui's keys as the DOM's keyCode values, the indices PageInput uses in io.KeysDown.
void map_keys(ImGuiIO& io) {
  io.KeyMap[ImGuiKey_Tab] = 9;
  io.KeyMap[ImGuiKey_LeftArrow] = 37;
  io.KeyMap[ImGuiKey_RightArrow] = 39;
  io.KeyMap[ImGuiKey_UpArrow] = 38;
  io.KeyMap[ImGuiKey_DownArrow] = 40;
  io.KeyMap[ImGuiKey_PageUp] = 33;
  io.KeyMap[ImGuiKey_PageDown] = 34;
  io.KeyMap[ImGuiKey_Home] = 36;
  io.KeyMap[ImGuiKey_End] = 35;
  io.KeyMap[ImGuiKey_Insert] = 45;
  io.KeyMap[ImGuiKey_Delete] = 46;
  io.KeyMap[ImGuiKey_Backspace] = 8;
  io.KeyMap[ImGuiKey_Space] = 32;
  io.KeyMap[ImGuiKey_Enter] = 13;
  io.KeyMap[ImGuiKey_Escape] = 27;
  io.KeyMap[ImGuiKey_KeyPadEnter] = 13;
  io.KeyMap[ImGuiKey_A] = 65;
  io.KeyMap[ImGuiKey_C] = 67;
  io.KeyMap[ImGuiKey_V] = 86;
  io.KeyMap[ImGuiKey_X] = 88;
  io.KeyMap[ImGuiKey_Y] = 89;
  io.KeyMap[ImGuiKey_Z] = 90;
}

int button_mask(const ImGuiIO& io) {
  return (io.MouseDown[0] ? 1 : 0) | (io.MouseDown[1] ? 2 : 0) | (io.MouseDown[2] ? 4 : 0);
}

}  // namespace

PageInput::PageInput() = default;

void PageInput::pointer(double x, double y, int buttons) { events_.push_back({Event::Kind::pointer, x, y, buttons}); }
void PageInput::wheel(double steps_y, double steps_x) { events_.push_back({Event::Kind::wheel, steps_x, steps_y}); }
void PageInput::key(int key_code, bool down, bool ctrl, bool shift, bool alt, bool meta) {
  if (key_code < 0 || key_code >= 512) return;
  events_.push_back({Event::Kind::key, 0.0, 0.0, key_code, down, ctrl, shift, alt, meta});
}
void PageInput::character(unsigned codepoint) {
  events_.push_back({Event::Kind::character, 0.0, 0.0, static_cast<int>(codepoint)});
}

bool PageInput::apply(ImGuiIO& io) {
  if (io.KeyMap[ImGuiKey_Tab] != 9) map_keys(io);
  io.MouseWheel = io.MouseWheelH = 0.0f;
  const ImVec2 before = position_;
  const bool was_inside = inside_;
  bool changed = false;  // a state change applied: later ones wait for the next frame
  while (!events_.empty()) {
    const Event& e = events_.front();
    if (e.kind == Event::Kind::pointer) {
      const bool press = (e.value & ~button_mask(io)) != 0 || (button_mask(io) & ~e.value) != 0;
      if (press && changed) break;
      inside_ = !std::isnan(e.x);
      if (inside_) position_ = ImVec2(static_cast<float>(e.x), static_cast<float>(e.y));
      for (int b = 0; b < 3; ++b) io.MouseDown[b] = (e.value >> b) & 1;
      changed = changed || press;
    } else if (e.kind == Event::Kind::wheel) {
      io.MouseWheel += static_cast<float>(e.y);
      io.MouseWheelH += static_cast<float>(e.x);
      changed = true;
    } else if (e.kind == Event::Kind::key) {
      if (changed && io.KeysDown[e.value] != e.down) break;
      changed = changed || io.KeysDown[e.value] != e.down;
      io.KeysDown[e.value] = e.down;
      io.KeyCtrl = e.ctrl;
      io.KeyShift = e.shift;
      io.KeyAlt = e.alt;
      io.KeySuper = e.meta;
    } else {
      io.AddInputCharacter(static_cast<unsigned>(e.value));
      changed = true;
    }
    events_.pop_front();
  }
  io.MousePos = inside_ ? position_ : ImVec2(-FLT_MAX, -FLT_MAX);
  moved_ = inside_ != was_inside || position_.x != before.x || position_.y != before.y;
  return changed;
}

std::optional<ImVec2> PageInput::position() const {
  if (!inside_) return std::nullopt;
  return position_;
}

}  // namespace trailray::web
