// The viewer's first panel placement: inside the window, no two panels over each other, and the
// middle of the 3D view free on common window sizes, down to 960x540 where the secondary panels
// open collapsed.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "ui/panel_layout.hpp"

namespace trailray::ui {
namespace {

constexpr float kMenu = 19.0f;

bool overlap(const PanelRect& a, const PanelRect& b) {
  return a.x < b.right() && b.x < a.right() && a.y < b.bottom() && b.y < a.bottom();
}

std::vector<std::pair<std::string, PanelRect>> opened(const PanelLayout& l) {
  return {{"tracks", l.tracks}, {"statistics", l.statistics}, {"chart", l.chart}, {"replay", l.replay}};
}

class PanelLayoutAt : public ::testing::TestWithParam<std::pair<float, float>> {};

TEST_P(PanelLayoutAt, InsideTheWindowApartAndTheMiddleFree) {
  const auto [w, h] = GetParam();
  const PanelLayout l = default_panel_layout(w, h, kMenu);
  const auto panels = opened(l);
  for (const auto& [name, r] : panels) {
    EXPECT_GE(r.x, 0.0f) << name;
    EXPECT_GE(r.y, kMenu) << name << ": under the menu bar";
    EXPECT_LE(r.right(), w) << name;
    EXPECT_LE(r.bottom(), h) << name;
    EXPECT_GT(r.width, 150.0f) << name;
    EXPECT_GT(r.height, 100.0f) << name << ": room for its content once expanded";
  }
  for (std::size_t i = 0; i < panels.size(); ++i)
    for (std::size_t j = i + 1; j < panels.size(); ++j)
      EXPECT_FALSE(overlap(panels[i].second, panels[j].second)) << panels[i].first << " and " << panels[j].first;
  // The middle third of the free view (right of the column, above the chart) is not covered.
  const float free_left = l.tracks.right(), free_bottom = l.chart.y;
  const PanelRect middle{free_left + (w - free_left) / 3.0f, kMenu + (free_bottom - kMenu) / 3.0f,
                         (w - free_left) / 3.0f, (free_bottom - kMenu) / 3.0f, false};
  for (const auto& [name, r] : panels) EXPECT_FALSE(overlap(r, middle)) << name << " covers the middle";
  EXPECT_GT(middle.width, w * 0.2f);
  EXPECT_GT(middle.height, h * 0.15f);
}

INSTANTIATE_TEST_SUITE_P(WindowSizes, PanelLayoutAt,
                         ::testing::Values(std::pair{960.0f, 540.0f}, std::pair{1280.0f, 720.0f},
                                           std::pair{1920.0f, 1080.0f}, std::pair{2560.0f, 1440.0f}));

TEST(PanelLayout, SmallWindowsOpenTheSecondaryPanelsCollapsed) {
  const PanelLayout small = default_panel_layout(960.0f, 540.0f, kMenu);
  EXPECT_FALSE(small.tracks.collapsed);
  EXPECT_FALSE(small.chart.collapsed);
  EXPECT_TRUE(small.statistics.collapsed);
  EXPECT_TRUE(small.replay.collapsed);
  EXPECT_EQ(small.statistics.bottom(), small.statistics.y + kPanelTitleBarHeight);
  const PanelLayout large = default_panel_layout(1920.0f, 1080.0f, kMenu);
  EXPECT_FALSE(large.statistics.collapsed);
  EXPECT_FALSE(large.replay.collapsed);
  // The chart gets less of a small window's height than the old fixed 320 px.
  EXPECT_LE(small.chart.height, 540.0f * 0.3f + 0.5f);
}

}  // namespace
}  // namespace trailray::ui
