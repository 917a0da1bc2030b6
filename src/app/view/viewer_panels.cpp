// The viewer's ImGui windows (stub: filled in next).
#include <imgui.h>

#include "app/view/viewer_model.hpp"

namespace trailray::app::view {

PanelActions draw_panels(ViewerModel& model, double wall_seconds) {
  model.clock.advance(wall_seconds);
  return {};
}

}  // namespace trailray::app::view
