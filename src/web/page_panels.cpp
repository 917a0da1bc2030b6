#include "web/page_panels.hpp"

#include <fmt/format.h>
#include <imgui.h>
#include <imgui_internal.h>  // ImGuiWindow: a panel's place, fold and contents

#include <algorithm>
#include <cmath>

namespace trailray::web {
namespace {

constexpr float kMargin = 10.0f;  // ui/panel_layout's

}  // namespace

bool small_page(float width, float height) { return width < kSmallPageWidth || height < kSmallPageHeight; }

ui::PanelLayout page_panel_layout(float width, float height, float menu_height, float title_bar) {
  ui::PanelLayout l = ui::default_panel_layout(width, height, menu_height);
  if (!small_page(width, height)) return l;
  // The track list no taller than a few tracks' rows (it scrolls), the others folded under it.
  l.tracks.height = std::min(l.tracks.height, 200.0f);
  l.statistics.y = l.tracks.bottom() + kMargin;
  l.statistics.collapsed = l.replay.collapsed = l.chart.collapsed = true;
  // The Profile's title bar along the bottom, where the chart opens (it is moved up into the
  // window when unfolded: PanelKeeper).
  l.chart.y = std::max(menu_height + kMargin, height - title_bar - kMargin);
  return l;
}

std::string panel_settings_ini(const ui::PanelLayout& layout) {
  const ui::PanelRect* rects[4] = {&layout.tracks, &layout.statistics, &layout.chart, &layout.replay};
  std::string out;
  for (int i = 0; i < 4; ++i) {
    const ui::PanelRect& r = *rects[i];
    out += fmt::format("[Window][{}]\nPos={},{}\nSize={},{}\nCollapsed={}\n\n", kPanelNames[i], std::lround(r.x),
                       std::lround(r.y), std::lround(r.width), std::lround(r.height), r.collapsed ? 1 : 0);
  }
  return out;
}

ui::FramingRoom page_framing_room(const ui::ViewerSettings& s, const scene::Lens& lens,
                                  const scene::KeptClearCorner& legend, double pixel_ratio) {
  const double r = pixel_ratio > 0.0 ? pixel_ratio : 1.0;
  const auto w = static_cast<float>(lens.width_px / r), h = static_cast<float>(lens.height_px / r);
  if (!small_page(w, h)) return ui::panel_framing_room(s, lens, legend, pixel_ratio);
  // The default framing's reasoning, beside the page's folded layout.
  const float menu = s.show_menu ? ui::kPanelTitleBarHeight : 0.0f;
  return ui::framing_room_beside(page_panel_layout(w, h, menu, ui::kPanelTitleBarHeight), s, lens, legend, pixel_ratio);
}

bool PanelKeeper::keep_in_view(const ui::ViewerModel& model) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float top = (model.settings.show_menu ? ImGui::GetFrameHeight() : 0.0f) + kMargin;
  bool changed = false;
  for (int i = 0; i < 4; ++i) {
    ImGuiWindow* window = ImGui::FindWindowByName(kPanelNames[i]);
    if (window == nullptr || !window->Active) continue;  // closed
    const bool unfolded = seen_[i] && folded_[i] && !window->Collapsed;
    seen_[i] = true;
    folded_[i] = window->Collapsed;
    if (window->Collapsed) continue;
    float height = window->SizeFull.y;
    bool grown = false;
    // The Profile with a range's statistics that do not fit under its chart (the chart keeps its
    // least height): taller, upward, in the frames after the selection's statistics came (the
    // first lays the chart out for them, the next measures it), then left to the person.
    const ui::ChartSelection& sel = model.selection;
    if (i == 2 && sel.statistics) {
      if (sel.track != grown_track_ || sel.first != grown_first_ || sel.last != grown_last_) {
        grown_track_ = sel.track;
        grown_first_ = sel.first;
        grown_last_ = sel.last;
        grow_wait_ = 2;
        grow_frames_ = 3;
      }
      if (grow_wait_ > 0) {
        --grow_wait_;
        changed = true;  // frames must come for it
      } else if (grow_frames_ > 0) {
        --grow_frames_;
        changed = changed || grow_frames_ > 0;
        if (window->ScrollMax.y > 0.0f) {
          height = std::min(height + std::ceil(window->ScrollMax.y), std::max(height, display.y - top - kMargin));
          // Its bottom edge stays where it is.
          const float bottom = window->Pos.y + window->SizeFull.y;
          ImGui::SetWindowSize(window->Name, ImVec2(window->SizeFull.x, height));
          ImGui::SetWindowPos(window->Name, ImVec2(window->Pos.x, std::max(top, bottom - height)));
          grown = true;
        }
      }
    }
    if ((unfolded || grown) && window->Pos.y + height > display.y)
      ImGui::SetWindowPos(window->Name, ImVec2(window->Pos.x, std::max(top, display.y - height - kMargin)));
    changed = changed || unfolded || grown;
  }
  return changed;
}

}  // namespace trailray::web
