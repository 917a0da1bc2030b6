#include "app/view/legend_overlay.hpp"

#include <imgui.h>

#include <algorithm>
#include <string>

#include "render/colormap.hpp"

namespace trailray::app::view {
namespace {

ImU32 to_imgui(const glm::vec3& srgb, float alpha = 1.0f) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(srgb.r, srgb.g, srgb.b, alpha));
}

constexpr float kMargin = 12.0f, kPadding = 8.0f;
const ImU32 kPanel = IM_COL32(20, 22, 26, 240);
const ImU32 kText = IM_COL32(255, 255, 255, 255);

}  // namespace

void draw_legend_overlay(const std::optional<render::ColorLegend>& legend,
                         const std::vector<render::TrackKeyEntry>& key) {
  if (!legend && key.empty()) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float line = ImGui::GetTextLineHeight();
  // A window of its own (no title, sized to its content), first in the bottom-left corner: it
  // stacks with the panels and can be moved out of their way.
  ImGui::SetNextWindowPos(ImVec2(kMargin, display.y - kMargin), ImGuiCond_FirstUseEver, ImVec2(0.0f, 1.0f));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0.0f, 0.0f));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  ImGui::PushStyleColor(ImGuiCol_WindowBg, IM_COL32(0, 0, 0, 0));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoScrollbar |
                                 ImGuiWindowFlags_NoSavedSettings;
  const bool open = ImGui::Begin("Legend", nullptr, flags);
  ImGui::PopStyleColor();
  ImGui::PopStyleVar(2);
  if (!open) {
    ImGui::End();
    return;
  }
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  float top = origin.y;
  float total_width = 0.0f;
  if (legend) {
    const float bar_width = std::min(220.0f, display.x * 0.4f), bar_height = line * 0.8f;
    const float width = std::max(bar_width, ImGui::CalcTextSize(legend->title.c_str()).x) + 2.0f * kPadding;
    const float height = 3.0f * line + bar_height + 2.0f * kPadding;
    const ImVec2 corner(origin.x, top);
    draw->AddRectFilled(corner, ImVec2(corner.x + width, corner.y + height), kPanel, 6.0f);
    draw->AddText(ImVec2(corner.x + kPadding, corner.y + kPadding), kText, legend->title.c_str());
    // The bar from the same table the track pass samples, a step per entry.
    const render::ColormapTable& table = render::colormap_table(legend->map);
    const float bar_x = corner.x + kPadding, bar_y = corner.y + kPadding + 1.4f * line;
    for (std::size_t i = 0; i < table.size(); ++i) {
      const float x0 = bar_x + bar_width * static_cast<float>(i) / static_cast<float>(table.size());
      const float x1 = bar_x + bar_width * static_cast<float>(i + 1) / static_cast<float>(table.size());
      const glm::u8vec3 c = table[i];
      draw->AddRectFilled(ImVec2(x0, bar_y), ImVec2(x1 + 0.5f, bar_y + bar_height), IM_COL32(c.r, c.g, c.b, 255));
    }
    const float label_y = bar_y + bar_height + 0.3f * line;
    draw->AddText(ImVec2(bar_x, label_y), kText, legend->min_label.c_str());
    const float max_width = ImGui::CalcTextSize(legend->max_label.c_str()).x;
    draw->AddText(ImVec2(bar_x + bar_width - max_width, label_y), kText, legend->max_label.c_str());
    for (const render::LegendTick& tick : legend->ticks) {
      const float x = bar_x + bar_width * static_cast<float>(tick.position);
      draw->AddLine(ImVec2(x, bar_y), ImVec2(x, bar_y + bar_height), kText);
      const float w = ImGui::CalcTextSize(tick.label.c_str()).x;
      draw->AddText(ImVec2(x - 0.5f * w, label_y), kText, tick.label.c_str());
    }
    top += height + 0.5f * kMargin;
    total_width = std::max(total_width, width);
  }
  if (!key.empty()) {
    float width = 0.0f;
    for (const auto& entry : key) width = std::max(width, ImGui::CalcTextSize(entry.name.c_str()).x);
    const float swatch = 1.6f * line;
    width += swatch + 3.0f * kPadding;
    const float height = static_cast<float>(key.size()) * line * 1.2f + 2.0f * kPadding;
    const ImVec2 corner(origin.x, top);
    draw->AddRectFilled(corner, ImVec2(corner.x + width, corner.y + height), kPanel, 6.0f);
    float y = corner.y + kPadding;
    for (const auto& entry : key) {
      const float mid = y + 0.5f * line;
      draw->AddLine(ImVec2(corner.x + kPadding, mid), ImVec2(corner.x + kPadding + swatch, mid),
                    to_imgui(entry.color_srgb), 0.35f * line);
      draw->AddText(ImVec2(corner.x + 2.0f * kPadding + swatch, y), kText, entry.name.c_str());
      y += line * 1.2f;
    }
    top += height;
    total_width = std::max(total_width, width);
  }
  ImGui::Dummy(ImVec2(total_width, top - origin.y));  // the window's size
  ImGui::End();
}

}  // namespace trailray::app::view
