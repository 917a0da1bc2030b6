#pragma once
// The viewer's tracks built from the shared in-memory track files (app/track_model_builders.hpp).

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "app/track_model_builders.hpp"
#include "app/track_scene.hpp"
#include "app/track_style_options.hpp"
#include "app/view/viewer_model.hpp"

namespace trailray::app::view::test_tracks {

using namespace trailray::app::test_tracks;  // line, track_of, file_of, kLat, kLon, kT0, kNoTime

inline std::vector<ViewerTrack> viewer_tracks(const std::vector<LoadedTrackFile>& files, TrackStyleArgs args = {}) {
  return build_viewer_tracks(files, parse_track_style(args), TrackSceneInputs{}, [](const std::string&) {});
}

}  // namespace trailray::app::view::test_tracks
