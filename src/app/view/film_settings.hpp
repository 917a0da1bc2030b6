#pragma once
// The viewer's "record film" (ui/film_state.hpp: the settings and the recording's status): its
// default file, the track a follow camera follows, and what is wrong with the settings. The film
// is `trailray video`'s (app/video/film_recorder.hpp) with the viewer's style and tracks.

#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/tracks/track_set.hpp"
#include "ui/film_state.hpp"

namespace trailray::app::view {

using ui::FilmCamera;
using ui::FilmSettings;
using ui::FilmStatus;
using ui::kFilmCameraNames;

// "trailray-film-<the first track's name>.mp4" in the current folder, the name reduced to
// letters, digits, '-', '_' and '.' (others become '-'); "trailray-film.mp4" without a track.
std::string default_film_path(const scene::TrackSet& tracks);

// The track a follow camera follows: the settings' when it has times, else `preferred` (the
// replay's followed or the selected track) when it has, else the first track with times (0
// without one).
std::size_t film_follow_track(const FilmSettings& settings, const scene::TrackSet& tracks, int preferred);

// What is wrong with the settings before a recording starts ("" : nothing): the extension, an
// existing file without `replace`, an odd or too large size, a length or rate out of range.
std::string film_settings_problem(const FilmSettings& settings);

}  // namespace trailray::app::view
