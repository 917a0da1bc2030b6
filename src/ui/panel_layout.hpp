#pragma once
// Where the viewer's panels open: a column on the left (tracks, statistics), the profile chart
// along the bottom and the replay controls top right, sized from the window so that the middle
// of the 3D view stays free. On a small window the secondary panels open collapsed (title bar
// only). Only the first placement: the user moves and resizes them from there.

namespace trailray::ui {

inline constexpr float kPanelTitleBarHeight = 22.0f;  // a collapsed panel, with the default font

struct PanelRect {
  float x = 0.0f, y = 0.0f, width = 0.0f, height = 0.0f;  // height: when expanded
  bool collapsed = false;                                 // opens as its title bar only

  float right() const { return x + width; }
  float bottom() const { return y + (collapsed ? kPanelTitleBarHeight : height); }  // as it opens
};

struct PanelLayout {
  PanelRect tracks, statistics, chart, replay;
  PanelRect shading, occlusion, profiler;  // closed at start; auto-sized, only x and y are used
  PanelRect film;                          // "record film", opened from the replay panel; likewise, x its right edge
};

// `menu_height`: the main menu bar's height at the top (0 without it).
PanelLayout default_panel_layout(float width, float height, float menu_height);

}  // namespace trailray::ui
