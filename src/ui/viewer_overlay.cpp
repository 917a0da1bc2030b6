#include "ui/viewer_overlay.hpp"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "scene/volumes/volume_shapes.hpp"
#include "ui/tooltip.hpp"
#include "ui/track_picking.hpp"
#include "ui/waypoint_view.hpp"

namespace trailray::ui {
namespace {

ImU32 colour_of(const glm::vec3& srgb, float alpha = 1.0f) {
  return ImGui::ColorConvertFloat4ToU32({srgb.r, srgb.g, srgb.b, alpha});
}

// ImGui draws in window coordinates; the camera's pixels are the framebuffer's.
ImVec2 to_screen(const glm::dvec2& px) {
  const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
  return {static_cast<float>(px.x / scale.x), static_cast<float>(px.y / scale.y)};
}

void marker(ImDrawList* list, const ImVec2& at, ImU32 fill, float radius) {
  list->AddCircleFilled(at, radius + 2.0f, IM_COL32(255, 255, 255, 230));
  list->AddCircleFilled(at, radius, fill);
}

// The replay's markers: 6 px discs for a few tracks, smaller as more share the view (a season of
// a thousand tracks would otherwise be a carpet of discs over its own tracks), down to 2 px.
constexpr std::size_t kFullSizeMarkers = 50;

float replay_marker_radius(std::size_t markers) {
  constexpr float kFull = 6.0f, kSmallest = 2.0f;
  if (markers <= kFullSizeMarkers) return kFull;
  return std::max(kSmallest, kFull * std::sqrt(static_cast<float>(kFullSizeMarkers) / static_cast<float>(markers)));
}

// ImGui's draw lists index their vertices with 16 bits here (the ES 3 backend has no base vertex):
// a list over 65,536 vertices aborts. Discs take about 30 vertices each (two circles of 8 sides,
// anti-aliased); beyond kMaxDiscs the markers are 4-vertex squares, and beyond kMaxSquares the
// view is cut into cells that each keep their first marker (10,000 tracks: about 7,600 squares).
constexpr std::size_t kMaxDiscs = 600, kMaxSquares = 8000;

void replay_markers(const OverlayState& s, ImDrawList* list) {
  if (!s.model.clock.span()) return;
  std::vector<std::pair<ImVec2, ImU32>> shown;
  for (const scene::Track& t : s.model.tracks.tracks()) {
    if (!t.visible) continue;
    const TrackPosition p = position_at(t, s.model.clock.time());
    if (!p.valid) continue;
    if (const auto px = screen_position(s.camera, p.ecef)) shown.emplace_back(to_screen(*px), colour_of(t.color_srgb));
  }
  const float radius = replay_marker_radius(shown.size());
  if (shown.size() <= kMaxDiscs) {
    const int sides = shown.size() <= kFullSizeMarkers ? 0 : 8;  // 0: ImGui's smooth circle
    for (const auto& [at, fill] : shown) {
      list->AddCircleFilled(at, radius * 4.0f / 3.0f, IM_COL32(255, 255, 255, 230), sides);
      list->AddCircleFilled(at, radius, fill, sides);
    }
    return;
  }
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float cell = std::max(1.0f, std::ceil(std::sqrt(display.x * display.y / static_cast<float>(kMaxSquares))));
  const auto columns = static_cast<std::size_t>(display.x / cell) + 1;
  std::vector<bool> taken(columns * (static_cast<std::size_t>(display.y / cell) + 1), false);
  for (const auto& [at, fill] : shown) {
    if (at.x < 0.0f || at.y < 0.0f || at.x >= display.x || at.y >= display.y) continue;
    const std::size_t index = static_cast<std::size_t>(at.y / cell) * columns + static_cast<std::size_t>(at.x / cell);
    if (shown.size() > kMaxSquares && taken[index]) continue;
    taken[index] = true;
    list->AddRectFilled(ImVec2(at.x - radius, at.y - radius), ImVec2(at.x + radius, at.y + radius), fill);
  }
}

void waypoint_hover(const OverlayState& s, const scene::Waypoint& w) {
  if (s.cursor) {
    const ImVec2 at = to_screen(*s.cursor);
    ImGui::SetNextWindowPos({at.x + 16.0f, at.y + 8.0f});
  }
  ImGui::BeginTooltip();
  ImGui::TextUnformatted(w.name.empty() ? "(waypoint without a name)" : w.name.c_str());
  ImGui::Separator();
  for (const std::string& line : waypoint_tooltip_lines(w)) ImGui::TextUnformatted(line.c_str());
  ImGui::EndTooltip();
}

void volume_hover(const OverlayState& s, const scene::Volume& v) {
  if (s.cursor) {
    const ImVec2 at = to_screen(*s.cursor);
    ImGui::SetNextWindowPos({at.x + 16.0f, at.y + 8.0f});
  }
  ImGui::BeginTooltip();
  const std::vector<std::string> lines = scene::volume_tooltip_lines(v);
  ImGui::TextUnformatted(lines.front().c_str());
  ImGui::Separator();
  for (std::size_t i = 1; i < lines.size(); ++i) ImGui::TextUnformatted(lines[i].c_str());
  ImGui::EndTooltip();
}

void hover(const OverlayState& s, ImDrawList* list) {
  const HoverState& h = s.model.hover;
  if (h.waypoint >= 0 && h.waypoint < static_cast<int>(s.model.waypoints.points.size()))
    return waypoint_hover(s, s.model.waypoints.points[static_cast<std::size_t>(h.waypoint)]);
  if (h.track < 0 && h.volume >= 0 && h.volume < static_cast<int>(s.model.volumes.volumes.size()))
    return volume_hover(s, s.model.volumes.volumes[static_cast<std::size_t>(h.volume)]);
  if (h.track < 0 || h.track >= static_cast<int>(s.model.tracks.size())) return;
  const scene::Track& t = s.model.tracks[static_cast<std::size_t>(h.track)];
  if (h.point >= t.point_count()) return;
  if (const auto px = screen_position(s.camera, t.ecef(h.point)))
    marker(list, to_screen(*px), IM_COL32(20, 20, 20, 255), 4.0f);
  if (h.from_chart) return;
  if (s.cursor) {
    const ImVec2 at = to_screen(*s.cursor);
    ImGui::SetNextWindowPos({at.x + 16.0f, at.y + 8.0f});
  }
  ImGui::BeginTooltip();
  ImGui::TextUnformatted(t.name.c_str());
  ImGui::Separator();
  for (const std::string& line : tooltip_lines(t, h.point)) ImGui::TextUnformatted(line.c_str());
  ImGui::EndTooltip();
}

void bottom_lines(const OverlayState& s) {
  std::string text;
  if (s.progress.pending() > 0)
    text = fmt::format("Loading terrain: {}/{} tiles", s.progress.loaded + s.progress.no_data + s.progress.failed,
                       s.progress.wanted);
  if (!s.status.empty()) text += (text.empty() ? "" : "   ") + s.status;
  if (text.empty()) return;
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::GetForegroundDrawList()->AddText({10.0f, size.y - ImGui::GetTextLineHeight() - 8.0f},
                                          IM_COL32(255, 255, 255, 230), text.c_str());
}

bool compass(double heading_deg) {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  // Right, under where the replay panel opens (top right).
  ImGui::SetNextWindowPos({size.x - 10.0f, 215.0f}, ImGuiCond_Always, {1.0f, 0.0f});
  ImGui::SetNextWindowBgAlpha(0.5f);
  bool clicked = false;
  if (ImGui::Begin("##compass", nullptr,
                   ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing)) {
    // The needle points to north on screen: against the heading.
    const ImVec2 c = ImGui::GetCursorScreenPos();
    const float r = 18.0f;
    const ImVec2 centre{c.x + r, c.y + r};
    clicked = ImGui::InvisibleButton("north", {2.0f * r, 2.0f * r});
    ImDrawList* list = ImGui::GetWindowDrawList();
    list->AddCircle(centre, r, IM_COL32(255, 255, 255, 200), 24, 1.5f);
    const double a = -heading_deg * 3.14159265358979323846 / 180.0;
    const ImVec2 tip{centre.x + static_cast<float>(std::sin(a)) * (r - 3.0f),
                     centre.y - static_cast<float>(std::cos(a)) * (r - 3.0f)};
    list->AddLine(centre, tip, IM_COL32(230, 60, 50, 255), 3.0f);
    list->AddText({tip.x - 4.0f, tip.y - 7.0f}, IM_COL32(255, 255, 255, 255), "N");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("North up (N)");
  }
  ImGui::End();
  return clicked;
}

}  // namespace

bool draw_overlays(const OverlayState& s) {
  ImDrawList* list = ImGui::GetBackgroundDrawList();  // under the panels, over the 3D view
  replay_markers(s, list);
  hover(s, list);
  bottom_lines(s);
  return compass(s.heading_deg);
}

}  // namespace trailray::ui
