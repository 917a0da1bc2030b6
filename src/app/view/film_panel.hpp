#pragma once
// The viewer's "record film" (ImGui): a button in the replay panel that opens the film window,
// where the camera, the file, the length, the rate and the size are set, and which, while the
// film records, shows its progress (frames done of all, frames per second, time left) and a
// Cancel button. The recording itself is the shell's (viewer_film.cpp).

#include "app/view/viewer_ui.hpp"
#include "ui/panel_layout.hpp"
#include "ui/viewer_model.hpp"
#include "ui/viewer_panels.hpp"

namespace trailray::app::view {

// In the replay panel's first row: "record film..." (or the film's progress while it records);
// opens the film window.
void film_button(ViewerModel& model);

// The film window at `place` (first use); sets actions.record_film / cancel_film.
void film_window(ViewerModel& model, const PanelRect& place, PanelActions& actions);

}  // namespace trailray::app::view
