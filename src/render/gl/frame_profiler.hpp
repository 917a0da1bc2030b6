#pragma once
// Time per render pass, per frame, averaged over the last frames: what `--profile` prints.
// CPU time is the wall time between begin and end of a pass (std::chrono::
// steady_clock: what the pass costs the calling thread, including waits on the driver). GPU
// time comes from EXT_disjoint_timer_query (GL_TIME_ELAPSED_EXT queries) where the context has
// it: results are read a frame later (reading them at once would stall the pipeline), and a
// frame during which the GPU reported a disjoint event (clock change, power state), or with a
// GPU time longer than the wall time since the frame began, has its GPU times dropped, since
// they are meaningless. Without the extension the GPU column reads "n/a".
//
// Passes are flat: one pass at a time, begin and end by name. Misuse (a pass begun while another
// is open, an end that does not match, a frame ended with a pass open) throws ProfilerError
// naming the passes and the frame: a profile with silently wrong rows is worse than none.

#include <chrono>
#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "render/gl/gl_capabilities.hpp"
#include "render/gl/gl_objects.hpp"
#include "render/gl/render_error.hpp"

namespace trailray::render {

class ProfilerError : public RenderError {
 public:
  using RenderError::RenderError;
};

// The passes of a frame (DESIGN.md "The frame"), in the order the table lists them; other names
// are welcome and listed after these in the order first seen.
inline constexpr std::string_view kStandardPasses[] = {"shadows",    "tiles",    "tracks",  "ssao",  "compose",
                                                       "atmosphere", "overlays", "volumes", "labels"};

// Mean and median over the frames that ran a pass (milliseconds); nullopt: no sample.
struct PassTimes {
  std::string name;
  std::size_t cpu_samples = 0, gpu_samples = 0;
  std::optional<double> cpu_mean_ms, cpu_median_ms, gpu_mean_ms, gpu_median_ms;
};

class FrameProfiler {
 public:
  // GPU timing is on when `caps` has EXT_disjoint_timer_query and its entry points are found
  // (eglGetProcAddress); otherwise the GPU column is "n/a". Keeps the last `frame_window` frames
  // (at least 1). With GPU timing, the GL context must be current while profiling and when the
  // profiler is destroyed (it owns its queries).
  FrameProfiler(const GlCapabilities& caps, std::size_t frame_window);
  ~FrameProfiler();
  FrameProfiler(const FrameProfiler&) = delete;
  FrameProfiler& operator=(const FrameProfiler&) = delete;

  bool gpu_timing() const { return gpu_timing_; }
  std::size_t frames_ended() const { return frames_ended_; }

  // A frame, and the passes in it. begin_frame also collects the GPU results that have come in.
  void begin_frame();
  void begin_pass(std::string_view name);
  void end_pass(std::string_view name);
  void end_frame();
  // Waits for every outstanding GPU result (glFinish) and collects it: call before reading the
  // times after the last frame.
  void finish();

  // Times a pass for the scope's lifetime. A scope left by an exception still ends its pass.
  class Scope {
   public:
    Scope(FrameProfiler& profiler, std::string_view name);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    FrameProfiler& profiler_;
    std::string name_;
  };

  // Every standard pass, then the others; passes never run have no samples.
  std::vector<PassTimes> times() const;
  // One row per pass: "pass  CPU mean  CPU median  GPU mean  GPU median" in ms, "n/a" where
  // there is no sample, and a header naming the frame count.
  std::string table() const;

 private:
  struct PassRecord;
  struct PendingQuery;
  struct GlTimerFunctions;

  PassRecord& record_for(std::string_view name);
  void collect_gpu_results(bool wait);

  bool gpu_timing_ = false;
  std::size_t frame_window_;
  std::size_t frames_ended_ = 0;
  bool in_frame_ = false;
  std::optional<std::string> open_pass_;
  std::chrono::steady_clock::time_point open_since_;
  std::vector<PassRecord> passes_;
  std::deque<PendingQuery> pending_;
  std::vector<Query> free_queries_;
  const GlTimerFunctions* gl_ = nullptr;
};

// Blocks until the GPU has done everything asked of it so far: wall-clock timings (where the
// context has no timer queries) then cover the GPU's work.
void wait_for_gpu();

}  // namespace trailray::render
