#include "app/view/track_loading.hpp"

#include <cmath>
#include <exception>

#include "scene/thermal_markers.hpp"
#include "scene/waypoint_building.hpp"

namespace trailray::app::view {

LoadedViewerTracks load_viewer_tracks(const std::vector<std::string>& paths, const TrackLoadInputs& inputs) {
  LoadedViewerTracks out;
  scene::CollectedDiagnostics diagnostics;
  std::vector<scene::LoadedTrackFile> files;
  for (const std::string& path : paths) {
    try {
      files.push_back(scene::read_track_file(path, inputs.read, diagnostics));
      out.recorded.add(files.back().file);
    } catch (const std::exception& e) {
      out.errors.emplace_back(e.what());
    }
  }
  if (!files.empty()) {
    scene::TrackBuildOptions options;
    options.heights = inputs.heights;
    options.analysis = inputs.analysis;
    options.inspect = true;
    // The neutral ground (under points without elevation): as given, else the lowest point.
    options.neutral_ground_m =
        std::isnan(inputs.neutral_ground_m) ? out.recorded.lowest_or_sea_level() : inputs.neutral_ground_m;
    scene::TrackStyle style = inputs.style;
    // Per-track --color counts the command line's tracks; later files take the palette.
    if (inputs.tracks_open > 0 && style.colors.size() != 1) style.colors.clear();
    try {
      out.tracks = scene::build_tracks(files, style, options, diagnostics, inputs.tracks_open);
      out.waypoints = scene::file_waypoints(files, {inputs.heights, options.neutral_ground_m});
      if (inputs.thermals)
        for (const scene::Track& t : out.tracks)
          for (scene::Waypoint& w : scene::thermal_markers(t)) out.waypoints.push_back(std::move(w));
    } catch (const std::exception& e) {
      out.errors.emplace_back(e.what());
    }
  }
  out.warnings = std::move(diagnostics.warnings);
  return out;
}

std::future<LoadedViewerTracks> load_viewer_tracks_async(std::vector<std::string> paths, TrackLoadInputs inputs) {
  return std::async(std::launch::async, [paths = std::move(paths), inputs = std::move(inputs)] {
    return load_viewer_tracks(paths, inputs);
  });
}

}  // namespace trailray::app::view
