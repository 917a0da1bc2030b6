#include "app/view/profiler_table.hpp"

namespace trailray::app::view {

ProfilerTable profiler_table(const render::FrameProfiler& profiler, double frame_seconds) {
  ProfilerTable table;
  for (const render::PassTimes& p : profiler.times()) {
    if (p.cpu_samples == 0 && p.gpu_samples == 0) continue;
    table.rows.push_back({p.name, p.cpu_mean_ms, p.gpu_mean_ms});
  }
  if (frame_seconds > 0.0) {
    table.frame_ms = frame_seconds * 1000.0;
    table.fps = 1.0 / frame_seconds;
  }
  return table;
}

}  // namespace trailray::app::view
