#pragma once
// The replay's camera follow (the replay panel's "camera follows"), for both viewers: each frame
// the pivot jumps to the followed track's marker; a chase camera also looks along the way the
// track goes from there, from behind.

#include "scene/camera/camera_controller.hpp"
#include "ui/viewer_model.hpp"

namespace trailray::ui {

// Moves `controller` as the model's clock says. False when nothing follows (off, no such track,
// the clock outside the track's times): the camera is left as it is.
bool follow_replay(const ViewerModel& model, scene::CameraController& controller);

}  // namespace trailray::ui
