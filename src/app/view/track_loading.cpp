#include "app/view/track_loading.hpp"

#include <cmath>
#include <exception>

#include "scene/colormap.hpp"

namespace trailray::app::view {

LoadedViewerTracks load_viewer_tracks(const std::vector<std::string>& paths, const TrackLoadInputs& inputs) {
  LoadedViewerTracks out;
  const auto warn = [&out](const std::string& w) { out.warnings.push_back(w); };
  std::vector<std::string> readable;
  for (const std::string& path : paths) {
    try {
      TrackPoints one = load_track_points({path}, inputs.read, warn);
      for (LoadedTrackFile& f : one.files) add_track_points(out.points, std::move(f));
      readable.push_back(path);
    } catch (const std::exception& e) {
      out.errors.emplace_back(e.what());
    }
  }
  if (out.points.files.empty()) return out;
  // The neutral ground (under points without elevation): as given, else the lowest point.
  double neutral = inputs.neutral_ground_m;
  if (std::isnan(neutral)) neutral = lowest_height(out.points.points);
  if (std::isnan(neutral)) neutral = 0.0;
  TrackStyle style = inputs.style;
  // Per-track --color counts the command line's tracks; later files take the palette.
  if (inputs.tracks_open > 0 && style.colors.size() != 1) style.colors.clear();
  TrackSceneInputs scene_inputs;
  scene_inputs.heights = inputs.heights;
  scene_inputs.neutral_ground_m = neutral;
  scene_inputs.analysis = inputs.analysis;
  try {
    out.tracks = build_viewer_tracks(out.points.files, style, scene_inputs, warn);
  } catch (const std::exception& e) {
    out.errors.emplace_back(e.what());
    out.tracks.clear();
    return out;
  }
  if (inputs.tracks_open > 0 && style.colors.empty())
    for (std::size_t i = 0; i < out.tracks.size(); ++i)
      out.tracks[i].color_srgb = scene::palette_color(inputs.tracks_open + i);
  return out;
}

std::future<LoadedViewerTracks> load_viewer_tracks_async(std::vector<std::string> paths, TrackLoadInputs inputs) {
  return std::async(std::launch::async, [paths = std::move(paths), inputs = std::move(inputs)] {
    return load_viewer_tracks(paths, inputs);
  });
}

}  // namespace trailray::app::view
