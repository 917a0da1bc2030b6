#pragma once
// The viewer's windows (ImGui): track list, statistics, shading, occlusion, profiler, profile
// chart, replay, errors. Each edits the model in place.

#include <functional>
#include <optional>

#include "scene/pins/waypoints.hpp"
#include "ui/panel_layout.hpp"
#include "ui/viewer_model.hpp"

namespace trailray::ui {

// What the user asked for in the panels this frame, for the shell to carry out.
struct PanelActions {
  int fly_to_track = -1;     // "fly to" pressed on a track (-1: none)
  int fly_to_waypoint = -1;  // a waypoint clicked in the track list (index into the model's waypoints)
  std::optional<scene::Waypoint> fly_to_point;  // a thermal clicked in the statistics (its marker)
  bool record_film = false;                     // "record film" pressed (ViewerModel::film says how)
  bool cancel_film = false;                     // "cancel" pressed while a film records
};

// The desktop's "record film" (app/view/film_panel.hpp): the replay panel's button and the film
// window it opens. Without it (the page records no film) neither is shown, nor its menu entry.
struct FilmPanel {
  std::function<void(ViewerModel&)> button;
  std::function<void(ViewerModel&, const PanelRect& place, PanelActions&)> window;
};

// Draws every open window and applies their edits to the model. Call each frame between
// ImGui::NewFrame and ImGui::Render; `wall_seconds` since the last frame drives the replay clock.
// Colour-by and curtain changes recompute the tracks' values (their revisions change).
PanelActions draw_panels(ViewerModel& model, double wall_seconds, const FilmPanel* film = nullptr);

}  // namespace trailray::ui
