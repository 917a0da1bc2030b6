#include "ui/panel_layout.hpp"

#include <algorithm>

namespace trailray::ui {
namespace {

constexpr float kMargin = 10.0f;

}  // namespace

PanelLayout default_panel_layout(float width, float height, float menu_height) {
  PanelLayout l;
  const float top = menu_height + kMargin;
  // Below about 1100x650 the panels would cover the middle: only the track list and the chart
  // open expanded.
  const bool small = width < 1100.0f || height < 650.0f;
  const float column = std::clamp(width * 0.26f, 240.0f, 330.0f);
  const float chart_height = std::clamp(height * 0.3f, 150.0f, 300.0f);

  l.chart.x = column + 2.0f * kMargin;
  l.chart.width = std::max(200.0f, width - l.chart.x - kMargin);
  l.chart.height = chart_height;
  l.chart.y = std::max(top, height - chart_height - kMargin);

  l.tracks = {kMargin, top, column, std::clamp((height - top) * 0.45f, 160.0f, 330.0f), false};
  l.statistics = {kMargin, l.tracks.bottom() + kMargin, column, 230.0f, small};

  // Four rows (play and clock, speed, scrub bar, camera follow) and no more: it sits in the sky.
  const float replay_width = std::min(330.0f, std::max(200.0f, width - l.chart.x - kMargin));
  l.replay = {std::max(l.chart.x, width - replay_width - kMargin), top, replay_width, 140.0f, small};

  // Opened from the menu: to the right of the column, below the menu.
  l.shading = {l.chart.x, top, 0.0f, 0.0f, false};
  l.occlusion = {l.chart.x, top + 170.0f, 0.0f, 0.0f, false};
  l.profiler = {l.chart.x, top + 300.0f, 0.0f, 0.0f, false};
  // Below the replay panel (expanded); x is its right edge (it grows to the left).
  l.film = {l.replay.right(), l.replay.y + l.replay.height + kMargin, 0.0f, 0.0f, false};
  return l;
}

}  // namespace trailray::ui
