#include "ui/framing_room.hpp"

#include <algorithm>

#include "ui/panel_layout.hpp"

namespace trailray::ui {

FramingRoom panel_framing_room(const ViewerSettings& s, const scene::Lens& lens, const scene::KeptClearCorner& legend,
                               double pixel_ratio) {
  const double r = pixel_ratio > 0.0 ? pixel_ratio : 1.0;
  const auto w = static_cast<float>(lens.width_px / r), h = static_cast<float>(lens.height_px / r);
  return framing_room_beside(default_panel_layout(w, h, s.show_menu ? kPanelTitleBarHeight : 0.0f), s, lens, legend,
                             pixel_ratio);
}

FramingRoom framing_room_beside(const PanelLayout& l, const ViewerSettings& s, const scene::Lens& lens,
                                const scene::KeptClearCorner& legend, double pixel_ratio) {
  const double r = pixel_ratio > 0.0 ? pixel_ratio : 1.0;
  const auto w = static_cast<float>(lens.width_px / r);
  const float menu = s.show_menu ? kPanelTitleBarHeight : 0.0f;
  scene::ImageArea area{0.0, menu * r, static_cast<double>(lens.width_px), static_cast<double>(lens.height_px)};
  if (s.show_tracks || s.show_statistics) area.left_px = l.tracks.right() * r;
  if (s.show_chart) area.bottom_px = l.chart.y * r;
  const double margin = scene::FramingOptions{}.margin_fraction;
  if (!legend.empty() && legend.width_px > area.left_px) {
    scene::ImageArea above_legend = area;
    above_legend.bottom_px = std::min(area.bottom_px, static_cast<double>(lens.height_px) - legend.height_px);
    // A tall key (many tracks) under a wide one leaves too little above it: the legend's corner
    // is kept clear instead, the area stays beside the panels.
    if (!scene::area_holds_centre(above_legend, lens, margin) && scene::area_holds_centre(area, lens, margin))
      return {legend, area};
    area = above_legend;
  }
  // A window too small for the panels and a view (the free part, less its margins, misses the
  // window's centre, which framing needs): frame on all of it.
  if (!scene::area_holds_centre(area, lens, margin)) return {legend, std::nullopt};
  scene::KeptClearCorner replay;
  if (s.show_replay) replay = {scene::ImageCorner::top_right, (w - l.replay.x) * r, l.replay.bottom() * r};
  return {replay, area};
}

}  // namespace trailray::ui
