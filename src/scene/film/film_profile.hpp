#pragma once
// The film's mini profile (`--overlay full`): the followed track's altitude over the part filmed,
// the ground below it shaded, and where the replay is now; painted on the CPU bottom right.

#include <vector>

#include "scene/pictures/image_paint.hpp"
#include "scene/tracks/replay_position.hpp"
#include "scene/pictures/rgba_image.hpp"
#include "scene/tracks/track_set.hpp"

namespace trailray::scene {

// A profile sampled once per column of its panel: altitude and ground (NaN: none) at evenly
// spaced times over `span`.
struct FilmProfile {
  TimeSpan span;
  std::vector<double> altitude_m, ground_m;
  double low_m = 0.0, high_m = 1.0;  // the vertical range drawn
};
// `columns` samples of `track` over `span` (empty altitude_m: no altitude to draw).
FilmProfile film_profile(const Track& track, const TimeSpan& span, int columns);

// The panel the profile takes in a width x height picture (bottom right, above nothing else).
PixelRect film_profile_panel(std::uint32_t width, std::uint32_t height);

// Paints the profile and a marker at `time_unix_s` into its panel; returns the panel (empty when
// there was nothing to draw).
PixelRect draw_film_profile(RgbaImage& image, const FilmProfile& profile, double time_unix_s);

}  // namespace trailray::scene
