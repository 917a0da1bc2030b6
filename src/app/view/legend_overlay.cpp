#include "app/view/legend_overlay.hpp"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

#include "scene/pictures/colormap.hpp"

namespace trailray::app::view {
namespace {

ImU32 to_imgui(const glm::vec3& srgb, float alpha = 1.0f) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(srgb.r, srgb.g, srgb.b, alpha));
}

constexpr float kMargin = 12.0f, kPadding = 8.0f;
const ImU32 kPanel = IM_COL32(20, 22, 26, 240);
const ImU32 kText = IM_COL32(255, 255, 255, 255);
const ImU32 kQuietText = IM_COL32(200, 202, 206, 255);  // "+N more", as in the rendered key

// Text measured with the interface's font, as ImGui::CalcTextSize does inside a frame, but also
// before the first one (the viewer frames its first view before it draws anything).
struct OverlayText {
  ImFont* font = nullptr;
  float size = 0.0f;  // the line height, ImGui::GetTextLineHeight()

  float width(const std::string& text) const {
    if (text.empty()) return 0.0f;
    return std::floor(font->CalcTextSizeA(size, FLT_MAX, 0.0f, text.c_str()).x + 0.99999f);
  }
};

OverlayText overlay_text() {
  ImGuiIO& io = ImGui::GetIO();
  if (!io.Fonts->IsBuilt()) {
    // What the OpenGL backend does on its first frame; it finds the atlas built then.
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  }
  ImFont* font = io.FontDefault != nullptr ? io.FontDefault : io.Fonts->Fonts[0];
  return {font, io.FontGlobalScale * font->FontSize * font->Scale};
}

// The sizes of everything in the legend window, shared by drawing it and by reporting where it
// is (for the framing to keep the tracks out of it).
struct OverlayLayout {
  float line = 0.0f;
  float bar_width = 0.0f, bar_height = 0.0f;
  float legend_width = 0.0f, legend_height = 0.0f;  // the colour bar's panel
  float swatch = 0.0f, key_width = 0.0f, key_height = 0.0f, key_row = 0.0f;
  // The names listed, and the rest counted in a last "+N more" row (as the rendered key does): a
  // season of tracks must not list a thousand names down past the window.
  std::size_t listed = 0, hidden = 0;
  std::string more;
  float width = 0.0f, height = 0.0f;  // the whole window
};

OverlayLayout overlay_layout(const std::optional<scene::ColorLegend>& legend,
                             const std::vector<scene::TrackKeyEntry>& key, float display_width, float display_height,
                             const OverlayText& text) {
  OverlayLayout l;
  l.line = text.size;
  if (legend) {
    l.bar_width = std::min(220.0f, display_width * 0.4f);
    l.bar_height = l.line * 0.8f;
    l.legend_width = std::max(l.bar_width, text.width(legend->title)) + 2.0f * kPadding;
    l.legend_height = 3.0f * l.line + l.bar_height + 2.0f * kPadding;
    l.height += l.legend_height + 0.5f * kMargin;
    l.width = std::max(l.width, l.legend_width);
  }
  if (!key.empty()) {
    l.swatch = 1.6f * l.line;
    l.key_row = l.line * 1.2f;
    // Rows that fit in what the window leaves (at least one), never more than the rendered key's.
    const float room = display_height - 2.0f * kMargin - l.height - 2.0f * kPadding;
    const std::size_t fit = static_cast<std::size_t>(std::max(1.0f, std::floor(room / l.key_row)));
    const std::size_t rows = std::min(fit, scene::kMaxTrackKeyRows);
    l.listed = key.size() <= rows ? key.size() : std::max<std::size_t>(rows, 2) - 1;
    l.hidden = key.size() - l.listed;
    float names = 0.0f;
    for (std::size_t i = 0; i < l.listed; ++i) names = std::max(names, text.width(key[i].name));
    if (l.hidden > 0) l.more = "+" + std::to_string(l.hidden) + " more";
    l.key_width = std::max(names + l.swatch + 3.0f * kPadding, text.width(l.more) + 2.0f * kPadding);
    const std::size_t row_count = l.listed + (l.hidden > 0 ? 1 : 0);
    l.key_height = static_cast<float>(row_count) * l.key_row + 2.0f * kPadding;
    l.height += l.key_height;
    l.width = std::max(l.width, l.key_width);
  }
  return l;
}

}  // namespace

scene::PixelRect legend_overlay_rect(const std::optional<scene::ColorLegend>& legend,
                                     const std::vector<scene::TrackKeyEntry>& key, float display_width,
                                     float display_height) {
  if (!legend && key.empty()) return {};
  const OverlayLayout l = overlay_layout(legend, key, display_width, display_height, overlay_text());
  // Whole pixels that cover the window.
  const float top = display_height - kMargin - l.height;
  return {static_cast<int>(std::floor(kMargin)), static_cast<int>(std::floor(top)),
          static_cast<int>(std::ceil(kMargin + l.width) - std::floor(kMargin)),
          static_cast<int>(std::ceil(display_height - kMargin) - std::floor(top))};
}

namespace {
void draw_legend_window(const char* name, float raise, const std::optional<scene::ColorLegend>& legend,
                        const std::vector<scene::TrackKeyEntry>& key) {
  if (!legend && key.empty()) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const OverlayLayout l = overlay_layout(legend, key, display.x, display.y, overlay_text());
  // A window of its own (no title, sized to its content), first in the bottom-left corner (raised
  // above another legend's window): it stacks with the panels and can be moved out of their way.
  ImGui::SetNextWindowPos(ImVec2(kMargin, display.y - kMargin - raise), ImGuiCond_FirstUseEver, ImVec2(0.0f, 1.0f));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0.0f, 0.0f));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  ImGui::PushStyleColor(ImGuiCol_WindowBg, IM_COL32(0, 0, 0, 0));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoScrollbar |
                                 ImGuiWindowFlags_NoSavedSettings;
  const bool open = ImGui::Begin(name, nullptr, flags);
  ImGui::PopStyleColor();
  ImGui::PopStyleVar(2);
  if (!open) {
    ImGui::End();
    return;
  }
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float line = l.line;
  float top = origin.y;
  if (legend) {
    const float bar_width = l.bar_width, bar_height = l.bar_height;
    const ImVec2 corner(origin.x, top);
    draw->AddRectFilled(corner, ImVec2(corner.x + l.legend_width, corner.y + l.legend_height), kPanel, 6.0f);
    draw->AddText(ImVec2(corner.x + kPadding, corner.y + kPadding), kText, legend->title.c_str());
    // The bar from the same table the track pass samples, a step per entry.
    const scene::ColormapTable& table = scene::colormap_table(legend->map);
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
    for (const scene::LegendTick& tick : legend->ticks) {
      const float x = bar_x + bar_width * static_cast<float>(tick.position);
      draw->AddLine(ImVec2(x, bar_y), ImVec2(x, bar_y + bar_height), kText);
      const float w = ImGui::CalcTextSize(tick.label.c_str()).x;
      draw->AddText(ImVec2(x - 0.5f * w, label_y), kText, tick.label.c_str());
    }
    top += l.legend_height + 0.5f * kMargin;
  }
  if (!key.empty()) {
    const ImVec2 corner(origin.x, top);
    draw->AddRectFilled(corner, ImVec2(corner.x + l.key_width, corner.y + l.key_height), kPanel, 6.0f);
    float y = corner.y + kPadding;
    for (std::size_t i = 0; i < l.listed; ++i) {
      const scene::TrackKeyEntry& entry = key[i];
      const float mid = y + 0.5f * line;
      const float x0 = corner.x + kPadding;
      if (entry.dashed) {  // a route, dashed as it is drawn
        const int width = static_cast<int>(std::lround(l.swatch));
        for (const auto& [start, length] : scene::swatch_dashes(width))
          draw->AddLine(ImVec2(x0 + static_cast<float>(start), mid), ImVec2(x0 + static_cast<float>(start + length), mid),
                        to_imgui(entry.color_srgb), 0.35f * line);
      } else {
        draw->AddLine(ImVec2(x0, mid), ImVec2(x0 + l.swatch, mid), to_imgui(entry.color_srgb), 0.35f * line);
      }
      draw->AddText(ImVec2(corner.x + 2.0f * kPadding + l.swatch, y), kText, entry.name.c_str());
      y += l.key_row;
    }
    if (l.hidden > 0) draw->AddText(ImVec2(corner.x + kPadding, y), kQuietText, l.more.c_str());
  }
  ImGui::Dummy(ImVec2(l.width, l.height));  // the window's size
  ImGui::End();
}
}  // namespace

void draw_legend_overlay(const std::optional<scene::ColorLegend>& legend,
                         const std::vector<scene::TrackKeyEntry>& key) {
  draw_legend_window("Legend", 0.0f, legend, key);
}

void draw_overlay_legend(const scene::ColorLegend& overlay, const std::optional<scene::ColorLegend>& legend,
                         const std::vector<scene::TrackKeyEntry>& key) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float below = legend || !key.empty()
                          ? overlay_layout(legend, key, display.x, display.y, overlay_text()).height + 0.5f * kMargin
                          : 0.0f;
  draw_legend_window("Overlay legend", below, overlay, {});
}

}  // namespace trailray::app::view
