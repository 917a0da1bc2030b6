#pragma once
// From track files to what the renderer draws: per track (and route) the cleaned points as ECEF
// polylines (one per segment: gaps are never bridged), the colour values of the chosen metric,
// heights above the ground for curtains, a colour, and the colour scale's range over all tracks.
// Points without an elevation are placed on the terrain (or the neutral ground).

#include <glm/glm.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/track_style_options.hpp"
#include "render/passes/track_buffer.hpp"
#include "terrain/tile_source.hpp"
#include "track/model.hpp"
#include "track/summary.hpp"

namespace trailray::app {

struct LoadedTrackFile {
  std::string path;
  track::TrackFile file;
};

struct SceneTrack {
  std::string name;  // the track's (or route's) name, else the file's name and its number
  scene::TrackGeometry geometry;
  glm::vec3 color_srgb{1.0f, 0.0f, 0.0f};
  std::size_t points_with_value = 0;

  // Only with TrackSceneInputs::keep_analysis (else empty): what the geometry was made from.
  track::TrackSummary summary;                 // raw and clean statistics, as `trailray stats` prints them
  track::Track cleaned;                        // after clean_track (every raw segment, maybe emptied)
  track::TrackMetrics metrics;                 // compute_metrics(cleaned)
  std::vector<std::vector<double>> ground_m;   // terrain below each cleaned point (NaN: none); empty without terrain
};

struct TrackScene {
  std::vector<SceneTrack> tracks;
  std::optional<track::ValueRange> range;  // the colour scale (--range or automatic); nullopt: solid
  std::size_t points = 0;
};

struct TrackSceneInputs {
  terrain::HeightSource* heights = nullptr;  // nullptr: no terrain (agl impossible)
  double neutral_ground_m = 0.0;             // where there is no terrain height
  track::AnalysisOptions analysis;           // cleaning and metric windows
  // Keep each track's cleaned points, metrics, summary and ground heights (sampled for every
  // point when there is terrain) in SceneTrack, for a viewer that inspects them; `render` does
  // not need them.
  bool keep_analysis = false;
};

// The terrain height below every point of `t`, per segment; NaN everywhere without `heights`.
std::vector<std::vector<double>> sample_ground_heights(const track::Track& t, terrain::HeightSource* heights);

// Throws std::runtime_error for what the user must change (agl without terrain, a --color count
// that matches neither 1 nor the number of tracks). `warn` gets notes (no values for a metric).
TrackScene build_track_scene(const std::vector<LoadedTrackFile>& files, const TrackStyle& style,
                             const TrackSceneInputs& inputs, const std::function<void(const std::string&)>& warn);

}  // namespace trailray::app
