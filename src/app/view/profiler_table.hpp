#pragma once
// The frame profiler's averages as the viewer's profiler panel lists them (viewer_model.hpp's
// ProfilerTable: plain data, so the panel and its tests need no GL context).

#include "app/view/viewer_ui.hpp"
#include "render/gl/frame_profiler.hpp"
#include "ui/viewer_model.hpp"

namespace trailray::app::view {

// One row per pass that has a sample (the profiler's order: the standard passes first), with the
// CPU and GPU means; `frame_seconds` is the wall time of the last frame (0: unknown), giving FPS.
ProfilerTable profiler_table(const render::FrameProfiler& profiler, double frame_seconds);

}  // namespace trailray::app::view
