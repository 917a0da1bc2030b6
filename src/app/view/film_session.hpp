#pragma once
// A film the viewer records (internal to app/view): `trailray video`'s recorder over copies of
// the viewer's tracks, waypoints and volumes as they were when it started (edits and files
// dropped meanwhile do not reach it), with its own terrain view (it waits for its tiles, the
// window never does) and its own renderer on the window's GL context (the window's GPU caches
// stay the window's).

#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "app/video/film_recorder.hpp"
#include "render/renderer.hpp"
#include "scene/terrain_view.hpp"
#include "scene/tracks/track_set.hpp"
#include "scene/volumes/volumes.hpp"
#include "scene/pins/waypoints.hpp"

namespace trailray::app::view {

struct FilmSession {
  scene::TrackSet tracks;
  scene::WaypointSet waypoints;
  scene::VolumeSet volumes;
  std::unique_ptr<scene::TerrainView> terrain;
  std::unique_ptr<render::Renderer> renderer;
  std::unique_ptr<FilmRecorder> recorder;  // last: it refers to the above
  std::string path;
  std::optional<std::chrono::steady_clock::time_point> waiting_since;  // the next frame's tiles
};

}  // namespace trailray::app::view
