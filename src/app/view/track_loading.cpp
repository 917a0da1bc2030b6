#include "app/view/track_loading.hpp"

#include <cmath>
#include <exception>

#include "app/common/track_arguments.hpp"
#include "app/common/track_reading.hpp"
#include "scene/pins/thermal_markers.hpp"
#include "scene/pins/waypoint_building.hpp"

namespace trailray::app::view {

namespace {

// Warnings kept for the window, progress forwarded to the terminal (when there is one).
class LoadingDiagnostics : public scene::CollectedDiagnostics {
 public:
  explicit LoadingDiagnostics(scene::Diagnostics* progress) : progress_(progress) {}
  void progress(const std::string& status) override {
    if (progress_ != nullptr) progress_->progress(status);
  }
  void progress_done() override {
    if (progress_ != nullptr) progress_->progress_done();
  }

 private:
  scene::Diagnostics* progress_;
};

// Folders and patterns (files dropped on the window, or given again) become their track files;
// one that gives none is an error line, the others still load.
std::vector<std::string> expanded_paths(const std::vector<std::string>& paths, std::vector<std::string>& errors) {
  std::vector<std::string> out;
  for (const std::string& path : paths) {
    try {
      for (std::string& p : expand_track_arguments({path})) out.push_back(std::move(p));
    } catch (const TrackArgumentError& e) {
      errors.emplace_back(e.what());
    }
  }
  return out;
}

}  // namespace

LoadedViewerTracks load_viewer_tracks(const std::vector<std::string>& paths, const TrackLoadInputs& inputs) {
  LoadedViewerTracks out;
  LoadingDiagnostics diagnostics(inputs.progress);
  std::vector<scene::LoadedTrackFile> files;
  // Every file read on all cores; one that cannot be read is an error line, the others load.
  for (TrackFileOutcome& o :
       read_track_file_outcomes(expanded_paths(paths, out.errors), inputs.read, {0, false}, inputs.progress)) {
    for (std::string& w : o.warnings) diagnostics.warnings.push_back(std::move(w));
    if (o.error) {
      out.errors.push_back(std::move(*o.error));
      continue;
    }
    files.push_back(std::move(*o.loaded));
    out.recorded.add(files.back().file);
  }
  if (!files.empty()) {
    scene::TrackBuildOptions options;
    options.heights = inputs.heights;
    options.surface = inputs.surface;
    options.analysis = inputs.analysis;
    options.inspect = true;
    // The neutral ground (under points without elevation): as given, else the lowest point.
    options.neutral_ground_m =
        std::isnan(inputs.neutral_ground_m) ? out.recorded.lowest_or_sea_level() : inputs.neutral_ground_m;
    scene::TrackStyle style = inputs.style;
    // Per-track --color counts the command line's tracks; later files take the palette.
    if (inputs.tracks_open > 0 && style.colors.size() != 1) style.colors.clear();
    try {
      out.tracks = build_tracks_parallel(files, style, options, diagnostics, inputs.tracks_open);
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
