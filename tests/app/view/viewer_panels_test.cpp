// The viewer's ImGui panels without a window or a renderer: a context with a built font atlas,
// frames driven by hand (display size, mouse position and button). Checks the chart's pure
// mouse-to-point mapping, that hovering the chart sets HoverState and dragging across it selects a
// range with its statistics, the colour of a point as the 3D view draws it, and the profiler table.

#include <gtest/gtest.h>

#include <imgui.h>
#include <imgui_internal.h>

#include <cmath>
#include <optional>
#include <vector>

#include "app/view/legend_overlay.hpp"
#include "app/view/profiler_table.hpp"
#include "app/view/viewer_ui.hpp"
#include "render/gl/frame_profiler.hpp"
#include "scene/pictures/colormap.hpp"
#include "ui/profile_chart.hpp"
#include "ui/viewer_model.hpp"
#include "ui/viewer_panels.hpp"
#include "viewer_test_tracks.hpp"

namespace trailray::app::view {
namespace {

using namespace test_tracks;

// 101 points 10 m and 1 s apart, climbing 1 m a point from 1000 m.
scene::Track ramp() {
  track::Segment s = line(101, 10.0, 1.0, 0.0);
  for (std::size_t i = 0; i < s.points.size(); ++i) s.points[i].ele = 1000.0 + static_cast<double>(i);
  return viewer_tracks({file_of("ramp.gpx", {track_of("ramp", {s})})})[0];
}

class HeadlessImGui : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(1280, 720);
    io.DeltaTime = 1.0f / 60.0f;
    io.IniFilename = nullptr;  // no imgui.ini written by tests
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // builds the atlas; no texture upload needed
  }
  void TearDown() override { ImGui::DestroyContext(); }

  // One frame of every open panel; returns the draw data's vertex count.
  int frame(ViewerModel& model, double wall_seconds = 0.0) {
    ImGui::NewFrame();
    draw_panels(model, wall_seconds);
    ImGui::Render();
    return ImGui::GetDrawData()->TotalVtxCount;
  }
};

TEST(ChartMapping, MousePixelToNearestPoint) {
  const scene::Track t = ramp();
  const auto extent = chart_extent(t, ChartAxis::distance);
  ASSERT_TRUE(extent.has_value());
  EXPECT_DOUBLE_EQ(extent->x_min, 0.0);
  EXPECT_NEAR(extent->x_max, 1000.0, 5.0);
  EXPECT_DOUBLE_EQ(extent->y_min, 1000.0);
  EXPECT_DOUBLE_EQ(extent->y_max, 1100.0);
  // A plot 500 px wide at x = 100: its left edge is point 0, its right edge the last point, the
  // middle point 50, and the mouse outside the plot clamps to its ends.
  EXPECT_EQ(hover_point(t, ChartAxis::distance, 100.0f, 100.0f, 500.0f), 0u);
  EXPECT_EQ(hover_point(t, ChartAxis::distance, 600.0f, 100.0f, 500.0f), 100u);
  EXPECT_EQ(hover_point(t, ChartAxis::distance, 350.0f, 100.0f, 500.0f), 50u);
  EXPECT_EQ(hover_point(t, ChartAxis::distance, 124.0f, 100.0f, 500.0f), 5u);  // 4.8 % of the way
  EXPECT_EQ(hover_point(t, ChartAxis::distance, 10.0f, 100.0f, 500.0f), 0u);
  EXPECT_EQ(hover_point(t, ChartAxis::distance, 900.0f, 100.0f, 500.0f), 100u);
  // Time axis: 100 s over the same plot.
  EXPECT_EQ(hover_point(t, ChartAxis::time, 100.0f + 500.0f * 0.3f, 100.0f, 500.0f), 30u);
  // The inverse mapping puts a point's x back on its pixel.
  EXPECT_NEAR(pixel_at_x(chart_x(t, ChartAxis::distance, 50), 100.0f, 500.0f, *extent), 350.0f, 0.5f);
}

TEST(ChartMapping, PointsWithoutTimeAreNotOnTheTimeAxis) {
  scene::Track t = ramp();
  for (std::size_t i = 0; i < 10; ++i) t.time_unix_s[i] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(point_at_x(t, ChartAxis::time, 0.0), 10u);
  for (double& e : t.time_unix_s) e = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(point_at_x(t, ChartAxis::time, 0.0).has_value());
  EXPECT_FALSE(chart_extent(t, ChartAxis::time).has_value());
}

TEST(ChartMapping, PointColourFollowsTheColourScale) {
  scene::TrackSet tracks;
  tracks.add(ramp());
  ViewerSettings settings;
  EXPECT_EQ(point_color(tracks[0], settings, std::nullopt, 5), tracks[0].color_srgb);
  apply_color_metric(tracks, track::ColorMetric::altitude);
  settings.style.tracks.color_by = track::ColorMetric::altitude;
  settings.style.tracks.colormap = scene::Colormap::viridis;
  const track::ValueRange range{1000.0, 1100.0};
  EXPECT_EQ(point_color(tracks[0], settings, range, 0), scene::colormap_color(scene::Colormap::viridis, 0.0f));
  EXPECT_EQ(point_color(tracks[0], settings, range, 100), scene::colormap_color(scene::Colormap::viridis, 1.0f));
  tracks[0].by_value = false;
  EXPECT_EQ(point_color(tracks[0], settings, range, 100), tracks[0].color_srgb);
}

TEST(StatisticsLines, FiguresWithUnitsAndDashes) {
  track::Statistics s;
  s.points = 12;
  s.segments = 2;
  s.distance_2d_m = 1234.5;
  s.duration_s = 3725.0;
  s.elevation_gain_m = 250.4;
  const auto lines = statistics_lines(s);
  ASSERT_GE(lines.size(), 5u);
  EXPECT_EQ(lines[0], "points: 12, segments: 2");
  EXPECT_EQ(lines[1], "distance: 1.234 km");  // 1.2345 rounds to even
  EXPECT_EQ(lines[2], "duration: 1:02:05, moving: \u2014");
  EXPECT_EQ(lines[3], "climb: +250 m, descent: \u2014");
}

TEST_F(HeadlessImGui, EveryPanelDrawsWithAndWithoutTracks) {
  ViewerModel empty;
  empty.settings.show_shading = empty.settings.show_occlusion = empty.settings.show_profiler = true;
  EXPECT_GT(frame(empty), 0);
  ViewerModel model;
  model.tracks.add(ramp());
  model.settings.show_shading = model.settings.show_occlusion = model.settings.show_profiler = true;
  model.errors.push_back("bad.gpx: not a track file");
  model.profile.rows.push_back({"tiles", 1.5, std::nullopt});
  EXPECT_GT(frame(model), 0);
  EXPECT_GT(frame(model), 0);
  // The replay clock found the track's times, and the shading panel started its sun there.
  ASSERT_TRUE(model.clock.span().has_value());
  EXPECT_DOUBLE_EQ(model.clock.span()->start, kT0);
  EXPECT_DOUBLE_EQ(model.clock.span()->end, kT0 + 100.0);
  EXPECT_DOUBLE_EQ(model.settings.sun_time_unix, kT0);
}

TEST_F(HeadlessImGui, DrawPanelsRunsTheReplayClock) {
  ViewerModel model;
  model.tracks.add(ramp());
  frame(model);
  model.clock.set_speed(10.0);
  model.clock.play();
  frame(model, 0.5);
  EXPECT_DOUBLE_EQ(model.clock.time(), kT0 + 5.0);
}

TEST_F(HeadlessImGui, HoveringTheChartSetsHoverAndDraggingSelectsARange) {
  ViewerModel model;
  model.tracks.add(ramp());
  model.settings.show_tracks = model.settings.show_statistics = model.settings.show_replay = false;
  model.settings.show_menu = false;
  frame(model);
  ImGuiWindow* window = ImGui::FindWindowByName("Profile");
  ASSERT_NE(window, nullptr);
  // Find the plot's top: move the mouse down the window's middle until the chart reports a hover.
  ImGuiIO& io = ImGui::GetIO();
  float plot_top = -1.0f;
  for (float y = window->InnerRect.Min.y; y < window->InnerRect.Max.y && plot_top < 0.0f; y += 2.0f) {
    io.MousePos = ImVec2(window->InnerRect.GetCenter().x, y);
    frame(model);
    if (model.hover.track == 0) plot_top = y;
  }
  ASSERT_GE(plot_top, 0.0f) << "the chart's plot was not found under the mouse";
  const float y = plot_top + 20.0f;
  // The plot starts 48 px right of the window's content (axis labels) and spans the rest.
  const float left = window->ContentRegionRect.Min.x + 48.0f;
  const float width = window->ContentRegionRect.GetWidth() - 48.0f;

  io.MousePos = ImVec2(left + width * 0.25f, y);
  frame(model);
  EXPECT_EQ(model.hover.track, 0);
  EXPECT_TRUE(model.hover.from_chart);
  EXPECT_NEAR(static_cast<double>(model.hover.point),
              static_cast<double>(*hover_point(model.tracks[0], ChartAxis::distance, io.MousePos.x, left, width)), 1.0);
  EXPECT_NEAR(static_cast<double>(model.hover.point), 25.0, 1.0);

  // The mouse leaves: the chart's hover is cleared; a hover from the 3D view stays and is drawn.
  io.MousePos = ImVec2(5.0f, 5.0f);
  frame(model);
  EXPECT_EQ(model.hover.track, -1);
  model.hover = {0, 70, false};
  frame(model);
  EXPECT_EQ(model.hover.point, 70u);
  EXPECT_FALSE(model.hover.from_chart);

  // Drag from 20 % to 60 % of the plot: points ~20..60 are selected with their statistics.
  io.MousePos = ImVec2(left + width * 0.2f, y);
  frame(model);
  io.MouseDown[0] = true;
  frame(model);
  for (float f = 0.25f; f <= 0.6f; f += 0.05f) {
    io.MousePos = ImVec2(left + width * f, y);
    frame(model);
  }
  io.MousePos = ImVec2(left + width * 0.6f, y);
  frame(model);
  io.MouseDown[0] = false;
  frame(model);
  EXPECT_EQ(model.selection.track, 0);
  EXPECT_NEAR(static_cast<double>(model.selection.first), 20.0, 1.0);
  EXPECT_NEAR(static_cast<double>(model.selection.last), 60.0, 1.0);
  ASSERT_TRUE(model.selection.statistics.has_value());
  const auto expected = scene::range_statistics(model.tracks[0], model.selection.first, model.selection.last);
  EXPECT_EQ(model.selection.statistics->points, model.selection.last - model.selection.first + 1);
  EXPECT_DOUBLE_EQ(model.selection.statistics->distance_2d_m, expected->distance_2d_m);
  EXPECT_NEAR(model.selection.statistics->elevation_gain_m.value_or(-1.0),
              static_cast<double>(model.selection.last - model.selection.first), 1e-9);

  // A click without a drag clears the selection.
  io.MouseDown[0] = true;
  frame(model);
  io.MouseDown[0] = false;
  frame(model);
  EXPECT_EQ(model.selection.track, -1);
}

// Where the viewer frames the tracks around the legend window: the rectangle it reports is the
// window ImGui shows, for a colour bar and for a key.
TEST_F(HeadlessImGui, LegendOverlayRectIsTheLegendWindow) {
  const scene::ColorLegend bar{"Vertical speed (m/s)", scene::Colormap::diverging, "\u22123.2", "3.2", {}};
  const std::vector<scene::TrackKeyEntry> key{{"Morning flight", {1.0f, 0.0f, 0.0f}}, {"B", {0.0f, 0.0f, 1.0f}}};
  for (const bool with_bar : {true, false}) {
    SCOPED_TRACE(with_bar ? "colour bar" : "key");
    ImGui::DestroyContext();
    SetUp();
    const std::optional<scene::ColorLegend> legend = with_bar ? std::optional(bar) : std::nullopt;
    const std::vector<scene::TrackKeyEntry> names = with_bar ? std::vector<scene::TrackKeyEntry>{} : key;
    const scene::PixelRect rect = legend_overlay_rect(legend, names, 1280.0f, 720.0f);
    for (int i = 0; i < 3; ++i) {  // an auto-sized window takes its size over the first frames
      ImGui::NewFrame();
      draw_legend_overlay(legend, names);
      ImGui::Render();
    }
    const ImGuiWindow* window = ImGui::FindWindowByName("Legend");
    ASSERT_NE(window, nullptr);
    EXPECT_GT(rect.width, 50);
    EXPECT_GT(rect.height, 20);
    EXPECT_NEAR(window->Pos.x, rect.x, 1.0);
    EXPECT_NEAR(window->Pos.y, rect.y, 1.0);
    EXPECT_NEAR(window->Pos.x + window->Size.x, rect.right(), 1.0);
    EXPECT_NEAR(window->Pos.y + window->Size.y, rect.bottom(), 1.0);
  }
  EXPECT_TRUE(legend_overlay_rect(std::nullopt, {}, 1280.0f, 720.0f).empty());
}

// A season of tracks: the key lists at most the rendered key's rows, the last one "+N more", and
// stays inside a small window.
TEST_F(HeadlessImGui, LegendOverlayKeyOfManyTracksEndsInMore) {
  std::vector<scene::TrackKeyEntry> key;
  for (int i = 0; i < 1000; ++i) key.push_back({"flight " + std::to_string(i), {1.0f, 0.0f, 0.0f}});
  const std::vector<scene::TrackKeyEntry> few(key.begin(), key.begin() + 3);
  const scene::PixelRect three = legend_overlay_rect(std::nullopt, few, 1280.0f, 720.0f);
  const scene::PixelRect many = legend_overlay_rect(std::nullopt, key, 1280.0f, 720.0f);
  // Rows are the same height: the many-track key has kMaxTrackKeyRows of them.
  const double row = (many.height - three.height) / static_cast<double>(scene::kMaxTrackKeyRows - 3);
  EXPECT_GT(row, 10.0);
  EXPECT_NEAR(three.height - 3.0 * row, many.height - scene::kMaxTrackKeyRows * row, 1.0);
  // A window too low for twelve rows gets fewer, still inside it.
  const scene::PixelRect low = legend_overlay_rect(std::nullopt, key, 1280.0f, 200.0f);
  EXPECT_GE(low.y, 0);
  EXPECT_LE(low.bottom(), 200);
  for (int i = 0; i < 3; ++i) {
    ImGui::NewFrame();
    draw_legend_overlay(std::nullopt, key);
    ImGui::Render();
  }
  const ImGuiWindow* window = ImGui::FindWindowByName("Legend");
  ASSERT_NE(window, nullptr);
  EXPECT_NEAR(window->Pos.y + window->Size.y, 720.0 - 12.0, 1.0);
  EXPECT_NEAR(window->Size.y, many.height, 1.0);
}

// A season in the track list: rows out of sight cost nothing (the draw data stays as small as a
// short list's), the list is still as long as all rows, and the filter lists the matching names.
TEST_F(HeadlessImGui, TrackListOfManyTracksDrawsTheRowsInSight) {
  const auto model_of = [](int count) {
    ViewerModel model;
    model.settings.show_statistics = false;
    const scene::Track t = ramp();
    for (int i = 0; i < count; ++i) {
      scene::Track copy = t;
      copy.name = "flight " + std::to_string(i);
      copy.source = "flight" + std::to_string(i) + ".gpx";
      model.tracks.add(std::move(copy));
    }
    return model;
  };
  ViewerModel few = model_of(30), many = model_of(3000);
  int few_vertices = 0, many_vertices = 0;
  for (int i = 0; i < 3; ++i) few_vertices = frame(few);
  for (int i = 0; i < 3; ++i) many_vertices = frame(many);
  EXPECT_LT(many_vertices, few_vertices * 3 / 2);
  const ImGuiWindow* list = ImGui::FindWindowByName("Tracks");
  ASSERT_NE(list, nullptr);
  // Every row still takes its place: the list is as long as 3000 rows.
  const float row = many.track_row_heights[0];
  EXPECT_GT(row, 10.0f);
  EXPECT_GT(list->ContentSize.y, 2990.0f * row);

  many.track_filter = "FLIGHT 299";  // any case: flight 299, 2990..2999
  frame(many);
  frame(many);
  const ImGuiWindow* filtered = ImGui::FindWindowByName("Tracks");
  EXPECT_LT(filtered->ContentSize.y, 40.0f * row);
  EXPECT_GT(filtered->ContentSize.y, 11.0f * row);
}

TEST(ProfilerTable, RowsForPassesThatRanAndFps) {
  render::FrameProfiler profiler(render::GlCapabilities{}, 4);  // no timer query: CPU times only
  profiler.begin_frame();
  profiler.begin_pass("tiles");
  profiler.end_pass("tiles");
  profiler.begin_pass("tracks");
  profiler.end_pass("tracks");
  profiler.end_frame();
  const ProfilerTable table = profiler_table(profiler, 0.025);
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[0].pass, "tiles");
  EXPECT_EQ(table.rows[1].pass, "tracks");
  EXPECT_TRUE(table.rows[0].cpu_ms.has_value());
  EXPECT_FALSE(table.rows[0].gpu_ms.has_value());
  EXPECT_DOUBLE_EQ(table.fps, 40.0);
  EXPECT_DOUBLE_EQ(table.frame_ms, 25.0);
}

}  // namespace
}  // namespace trailray::app::view
