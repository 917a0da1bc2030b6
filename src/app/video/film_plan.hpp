#pragma once
// A film planned before its first frame (`trailray video`): the clock (which times, how many
// frames, each track's offset for --align start) and the camera of every frame, from the options
// and the loaded tracks.

#include <vector>

#include "app/video/video_options.hpp"
#include "scene/camera/camera.hpp"
#include "scene/film/film_camera.hpp"
#include "scene/film/film_timing.hpp"
#include "scene/tracks/track_set.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::app {

struct FilmClock {
  scene::FilmTiming timing;
  std::vector<double> offsets;  // per track: added to the film's clock (--align start), else 0
};
// Throws CLI::ValidationError naming the option (--from/--to/--duration/--speed/--fps/--align),
// std::runtime_error when no track has times.
FilmClock plan_film_clock(const VideoArgs& args, const scene::TrackSet& tracks);

// Heights for the film cameras: the source's (sampled in batches) where it has them, the neutral
// ground elsewhere and without a source.
scene::HeightBatch film_heights(terrain::HeightSource* heights, double neutral_ground_m);

// The camera of every frame. Throws CLI::ValidationError for a camera the options make impossible.
std::vector<scene::Camera> plan_film_cameras(const VideoArgs& args, FilmCameraMode mode, const scene::Lens& lens,
                                             const FilmClock& clock, const scene::TrackSet& tracks,
                                             double neutral_ground_m, terrain::HeightSource* heights);

}  // namespace trailray::app
