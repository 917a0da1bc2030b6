#pragma once
// Where the page opens the viewer's panels (ui/'s, drawn by draw_panels) and what framing keeps
// clear of them. A large window opens them as the desktop viewer does (ui/panel_layout). A
// small one (narrower than 1400 or lower than 800 CSS pixels: a laptop's browser window) shows
// the 3D view first: the track list opens where the desktop's does (at most 200 pixels high), the
// Statistics, Replay and Profile panels folded to their title bars (the Profile's at the bottom
// of the window), a click away.
// Only the first placement: the person moves, folds and resizes them from there. A panel
// unfolded where it would reach past the bottom of the window is moved up into it, and the
// Profile grows (upward) when a range's statistics would not fit under its chart.

#include <string>

#include "scene/camera/framing.hpp"
#include "ui/framing_room.hpp"
#include "ui/panel_layout.hpp"
#include "ui/viewer_model.hpp"

namespace trailray::web {

inline constexpr float kSmallPageWidth = 1400.0f, kSmallPageHeight = 800.0f;  // CSS pixels

// Whether a window of this size (CSS pixels) opens the panels folded.
bool small_page(float width, float height);

// The panels' first placement in a window of `width` x `height` CSS pixels with the menu bar
// `menu_height` high; `title_bar`: a folded panel's height.
ui::PanelLayout page_panel_layout(float width, float height, float menu_height, float title_bar);

// The placement of the Tracks, Statistics, Profile and Replay panels as ImGui's settings text
// ([Window][name] with Pos, Size, Collapsed), loaded before they first open: ImGui then places
// them so (their own first-use placement stands aside).
std::string panel_settings_ini(const ui::PanelLayout& layout);

// ui::panel_framing_room for the page's layout: the part of the picture that framing the tracks
// uses (right of the track list, above the Profile as it opens) and the corner kept clear (the
// legend's, or the Replay panel's).
ui::FramingRoom page_framing_room(const ui::ViewerSettings& settings, const scene::Lens& lens,
                                  const scene::KeptClearCorner& legend, double pixel_ratio);

// After the panels of a frame (inside an ImGui frame): moves a panel unfolded since the last call
// up into the window when it reaches past its bottom, and lets the Profile grow upward (just
// after a selection's statistics came) when its contents, a range's statistics under the chart,
// do not fit. True when a panel was moved or resized, or is to be (the interface is to be drawn
// again).
class PanelKeeper {
 public:
  bool keep_in_view(const ui::ViewerModel& model);

 private:
  bool folded_[4] = {false, false, false, false};  // as of the last call, by kPanelNames' order
  bool seen_[4] = {false, false, false, false};
  int grown_track_ = -1;  // the selection the Profile last grew for
  std::size_t grown_first_ = 0, grown_last_ = 0;
  int grow_wait_ = 0, grow_frames_ = 0;  // frames before it may grow, and in which it may
};

// The panels' names as ImGui knows them (ui/viewer_panels.cpp).
inline constexpr const char* kPanelNames[4] = {"Tracks", "Statistics", "Profile", "Replay"};

}  // namespace trailray::web
