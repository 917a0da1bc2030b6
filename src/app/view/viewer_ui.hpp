#pragma once
// The viewer's interface (src/ui/: its model, panels, overlays, picking, replay) under app/view's
// own names: `trailray view` is that interface in a window with the desktop's extras (record film,
// scripts, the profiler's GL timings); the page (src/web/) is the same interface in a canvas.

#include "ui/viewer_model.hpp"

namespace trailray::app::view {

using namespace trailray::ui;  // NOLINT(google-build-using-namespace): one interface, two shells

}  // namespace trailray::app::view
