// The frame profiler: CPU time per pass, mean and median over a window of frames, the table,
// misuse reported as errors, and the GPU column consistent with the context's capabilities.

#include "render/gl/frame_profiler.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "gl_test_support.hpp"

namespace trailray::render {
namespace {

using namespace std::chrono_literals;

GlCapabilities without_gpu_timing() { return GlCapabilities{}; }

// By value: callers pass the temporary from times().
PassTimes row(const std::vector<PassTimes>& rows, std::string_view name) {
  for (const PassTimes& r : rows) {
    if (r.name == name) return r;
  }
  throw std::runtime_error("no row " + std::string(name));
}

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const ProfilerError& error) {
    return error.what();
  }
  return "(no error)";
}

// The table's line for a pass, split into words.
std::vector<std::string> table_words(const std::string& table, std::string_view pass) {
  std::istringstream lines(table);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::vector<std::string> out;
    for (std::string w; words >> w;) out.push_back(w);
    if (!out.empty() && out[0] == pass) return out;
  }
  return {};
}

TEST(FrameProfiler, APassThatSleepsFiveMillisecondsTakesAboutThat) {
  FrameProfiler profiler(without_gpu_timing(), 3);
  for (int frame = 0; frame < 3; ++frame) {
    profiler.begin_frame();
    {
      const FrameProfiler::Scope scope(profiler, "ssao");
      std::this_thread::sleep_for(5ms);
    }
    profiler.begin_pass("compose");
    profiler.end_pass("compose");
    profiler.end_frame();
  }
  const auto rows = profiler.times();
  const PassTimes& ssao = row(rows, "ssao");
  EXPECT_EQ(ssao.cpu_samples, 3u);
  EXPECT_GE(*ssao.cpu_median_ms, 4.0);
  EXPECT_GE(*ssao.cpu_mean_ms, 4.0);
  EXPECT_LT(*ssao.cpu_median_ms, 1000.0);  // milliseconds, not microseconds
  const PassTimes& compose = row(rows, "compose");
  EXPECT_EQ(compose.cpu_samples, 3u);
  EXPECT_LT(*compose.cpu_median_ms, *ssao.cpu_median_ms);
  EXPECT_EQ(profiler.frames_ended(), 3u);
}

TEST(FrameProfiler, PassesNeverBegunHaveNoSamplesAndReadNa) {
  FrameProfiler profiler(without_gpu_timing(), 4);
  profiler.begin_frame();
  profiler.begin_pass("tiles");
  profiler.end_pass("tiles");
  profiler.end_frame();
  const auto rows = profiler.times();
  // Every standard pass has a row, in the frame's order.
  ASSERT_GE(rows.size(), std::size(kStandardPasses));
  for (std::size_t i = 0; i < std::size(kStandardPasses); ++i) EXPECT_EQ(rows[i].name, kStandardPasses[i]);
  const PassTimes& tracks = row(rows, "tracks");
  EXPECT_EQ(tracks.cpu_samples, 0u);
  EXPECT_FALSE(tracks.cpu_mean_ms.has_value());
  EXPECT_FALSE(tracks.cpu_median_ms.has_value());
  const std::string table = profiler.table();
  EXPECT_EQ(table_words(table, "tracks"), (std::vector<std::string>{"tracks", "n/a", "n/a", "n/a", "n/a"})) << table;
  const auto tiles = table_words(table, "tiles");
  ASSERT_EQ(tiles.size(), 5u) << table;
  EXPECT_NE(tiles[1], "n/a");
  for (std::string_view pass : kStandardPasses) EXPECT_FALSE(table_words(table, pass).empty()) << pass;
}

TEST(FrameProfiler, MeanAndMedianOverTheLastFramesOnly) {
  FrameProfiler profiler(without_gpu_timing(), 3);
  // Frame 1 is slow; the window of 3 forgets it after frames 2..4, which are fast.
  for (int frame = 0; frame < 4; ++frame) {
    profiler.begin_frame();
    profiler.begin_pass("overlays");
    if (frame == 0) std::this_thread::sleep_for(30ms);
    profiler.end_pass("overlays");
    profiler.end_frame();
  }
  const PassTimes& overlays = row(profiler.times(), "overlays");
  EXPECT_EQ(overlays.cpu_samples, 3u);
  EXPECT_LT(*overlays.cpu_mean_ms, 25.0);
  EXPECT_NE(profiler.table().find("over 3 of 4 frames"), std::string::npos) << profiler.table();
}

TEST(FrameProfiler, APassRunTwiceInAFrameCountsOnceWithBothTimes) {
  FrameProfiler profiler(without_gpu_timing(), 5);
  profiler.begin_frame();
  for (int i = 0; i < 2; ++i) {
    profiler.begin_pass("tiles");
    std::this_thread::sleep_for(3ms);
    profiler.end_pass("tiles");
  }
  profiler.end_frame();
  const PassTimes& tiles = row(profiler.times(), "tiles");
  EXPECT_EQ(tiles.cpu_samples, 1u);
  EXPECT_GE(*tiles.cpu_mean_ms, 5.0);
}

TEST(FrameProfiler, OtherPassNamesFollowTheStandardOnes) {
  FrameProfiler profiler(without_gpu_timing(), 2);
  profiler.begin_frame();
  profiler.begin_pass("readback");
  profiler.end_pass("readback");
  profiler.end_frame();
  const auto rows = profiler.times();
  ASSERT_EQ(rows.size(), std::size(kStandardPasses) + 1);
  EXPECT_EQ(rows.back().name, "readback");
  EXPECT_EQ(rows.back().cpu_samples, 1u);
}

TEST(FrameProfiler, NestingAndMissingEndsAreErrors) {
  FrameProfiler profiler(without_gpu_timing(), 2);
  EXPECT_EQ(error_of([&] { profiler.begin_pass("tiles"); }),
            "frame profiler: pass 'tiles' begun outside a frame (begin_frame first)");
  profiler.begin_frame();
  EXPECT_EQ(error_of([&] { profiler.begin_frame(); }), "frame profiler: frame 2 begun before frame 1 ended");
  profiler.begin_pass("tiles");
  EXPECT_EQ(error_of([&] { profiler.begin_pass("tracks"); }),
            "frame profiler: pass 'tracks' begun while pass 'tiles' is still open in frame 1 (passes do not nest)");
  EXPECT_EQ(error_of([&] { profiler.end_pass("ssao"); }),
            "frame profiler: pass 'ssao' ended while pass 'tiles' is open in frame 1");
  EXPECT_EQ(error_of([&] { profiler.end_frame(); }),
            "frame profiler: frame 1 ended with pass 'tiles' still open (missing end_pass); the frame is not counted");
  // The broken frame left no sample, and the profiler goes on with the next frame.
  EXPECT_EQ(row(profiler.times(), "tiles").cpu_samples, 0u);
  EXPECT_EQ(error_of([&] { profiler.end_pass("tiles"); }),
            "frame profiler: pass 'tiles' ended but not begun in frame 2");
  EXPECT_EQ(error_of([&] { profiler.end_frame(); }), "frame profiler: frame 2 ended but not begun");
  profiler.begin_frame();
  profiler.begin_pass("tiles");
  profiler.end_pass("tiles");
  profiler.end_frame();
  EXPECT_EQ(row(profiler.times(), "tiles").cpu_samples, 1u);
}

class FrameProfilerGl : public test::GlTest {};

// GPU timing is on exactly when the context has EXT_disjoint_timer_query (llvmpipe: usually
// not); the table's GPU column says so either way, and real GL work gets GPU samples when on.
TEST_F(FrameProfilerGl, GpuColumnFollowsTheContextsCapabilities) {
  const GlCapabilities caps = query_gl_capabilities();
  FrameProfiler profiler(caps, 4);
  if (!caps.disjoint_timer_query) {
    EXPECT_FALSE(profiler.gpu_timing());
  }
  const test::RgbaTarget target(64, 64);
  const auto start = std::chrono::steady_clock::now();
  for (int frame = 0; frame < 4; ++frame) {
    profiler.begin_frame();
    {
      const FrameProfiler::Scope scope(profiler, "compose");
      glClearColor(0.2f, 0.3f, 0.4f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
    }
    profiler.end_frame();
  }
  profiler.finish();
  const double wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::cout << caps.renderer << ":\n" << profiler.table();  // which path ran, in the test log
  const PassTimes& compose = row(profiler.times(), "compose");
  const auto words = table_words(profiler.table(), "compose");
  ASSERT_EQ(words.size(), 5u) << profiler.table();
  EXPECT_EQ(compose.cpu_samples, 4u);
  if (profiler.gpu_timing()) {
    // Disjoint frames may drop samples, never add them.
    EXPECT_LE(compose.gpu_samples, 4u);
    if (compose.gpu_samples > 0) {
      EXPECT_GE(*compose.gpu_median_ms, 0.0);
      // No GPU time longer than the whole loop took (llvmpipe's first query reads hours).
      EXPECT_LE(*compose.gpu_mean_ms, wall_ms);
      EXPECT_NE(words[3], "n/a");
    }
    EXPECT_NE(profiler.table().find("GPU: EXT_disjoint_timer_query"), std::string::npos);
  } else {
    EXPECT_EQ(compose.gpu_samples, 0u);
    EXPECT_EQ(words[3], "n/a");
    EXPECT_EQ(words[4], "n/a");
    EXPECT_NE(profiler.table().find("GPU: n/a, no EXT_disjoint_timer_query"), std::string::npos);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// A frame ended with its pass open ends that pass's GPU query too: the next frames time
// normally and no GL error is left (GlTest checks).
TEST_F(FrameProfilerGl, AFrameLeftWithAnOpenPassDoesNotBreakTheNextOnes) {
  FrameProfiler profiler(query_gl_capabilities(), 4);
  const test::RgbaTarget target(16, 16);
  profiler.begin_frame();
  profiler.begin_pass("tiles");
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_THROW(profiler.end_frame(), ProfilerError);
  for (int frame = 0; frame < 3; ++frame) {
    profiler.begin_frame();
    profiler.begin_pass("tiles");
    glClear(GL_COLOR_BUFFER_BIT);
    profiler.end_pass("tiles");
    profiler.end_frame();
  }
  profiler.finish();
  const PassTimes& tiles = row(profiler.times(), "tiles");
  EXPECT_EQ(tiles.cpu_samples, 3u);
  EXPECT_LE(tiles.gpu_samples, 3u);
  if (!profiler.gpu_timing()) {
    EXPECT_EQ(tiles.gpu_samples, 0u);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace
}  // namespace trailray::render
