#pragma once
// What the viewer draws over the 3D view with ImGui each frame: the tooltip of the track point
// under the cursor, a marker where the profile chart points, the replay markers, the loading
// indicator, a status line and the compass (click: north up).

#include <glm/glm.hpp>

#include <optional>
#include <string>

#include "scene/camera/camera.hpp"
#include "terrain/loading/tile_loader.hpp"
#include "ui/viewer_model.hpp"

namespace trailray::ui {

struct OverlayState {
  const ViewerModel& model;
  const scene::Camera& camera;
  const terrain::LoadProgress& progress;
  const std::string& status;
  double heading_deg = 0.0;
  std::optional<glm::dvec2> cursor;  // a scripted cursor (pixels): the tooltip goes there
};

// Call between ImGui::NewFrame and ImGui::Render. True when the compass was clicked.
bool draw_overlays(const OverlayState& state);

}  // namespace trailray::ui
