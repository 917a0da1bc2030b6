#pragma once
// The viewer's tracks built from the shared in-memory track files (app/track_model_builders.hpp).

#include <string>
#include <vector>

#include "app/options/style_options.hpp"
#include "app/track_model_builders.hpp"
#include "app/view/viewer_ui.hpp"
#include "scene/tracks/track_building.hpp"
#include "ui/viewer_model.hpp"

namespace trailray::app::view::test_tracks {

using namespace trailray::app::test_tracks;  // line, track_of, file_of, kLat, kLon, kT0, kNoTime

// As the viewer builds them (inspect: summaries), without terrain.
inline scene::TrackSet viewer_tracks(const std::vector<scene::LoadedTrackFile>& files, StyleArgs args = {}) {
  scene::TrackBuildOptions options;
  options.inspect = true;
  scene::CollectedDiagnostics ignored;
  scene::TrackSet set;
  for (scene::Track& t : scene::build_tracks(files, parse_style(args).tracks, options, ignored)) set.add(std::move(t));
  return set;
}

}  // namespace trailray::app::view::test_tracks
