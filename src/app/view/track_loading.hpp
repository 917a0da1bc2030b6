#pragma once
// Track files into scene tracks without GL (so a background thread can do it while the window
// keeps drawing): the files read and built on all cores (app/common/track_reading), each on its own, so
// one that cannot be read becomes an error line and the others still load (everything already
// open stays). A folder or a pattern among the paths stands for its track files.

#include <future>
#include <string>
#include <vector>

#include "scene/style.hpp"
#include "scene/tracks/track_building.hpp"
#include "scene/tracks/track_files.hpp"
#include "scene/tracks/track_set.hpp"
#include "scene/pins/waypoints.hpp"
#include "ui/loaded_tracks.hpp"

namespace trailray::app::view {

// What a load gives, as the session adopts it (ui/loaded_tracks.hpp: the page's loads too).
using LoadedViewerTracks = ui::LoadedTracks;

struct TrackLoadInputs {
  track::ReadOptions read;
  track::AnalysisOptions analysis;
  scene::TrackStyle style;
  terrain::HeightSource* heights = nullptr;  // ground heights under the points (may load tiles)
  double neutral_ground_m = 0.0;             // NaN: the lowest point of the files read
  // Tracks already open: a new file continues the palette after them and, when --color gave
  // one colour per track, gets the palette's colour.
  std::size_t tracks_open = 0;
  bool thermals = false;  // a marker per thermal of the flights (--thermals) among the waypoints
  // Where the progress line of many files goes (null: nowhere); used from the loading thread only.
  scene::Diagnostics* progress = nullptr;
  terrain::HeightSource* surface = nullptr;  // --surface: each point's cover (scene::Track::cover)
};

LoadedViewerTracks load_viewer_tracks(const std::vector<std::string>& paths, const TrackLoadInputs& inputs);

// The same on a worker thread (files dropped on the window). The inputs' source must outlive it.
std::future<LoadedViewerTracks> load_viewer_tracks_async(std::vector<std::string> paths, TrackLoadInputs inputs);

}  // namespace trailray::app::view
