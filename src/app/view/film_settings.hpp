#pragma once
// The viewer's "record film" (in the replay panel) as plain data: what the user set up (the
// camera, the file, the length, the size) and how the recording goes, which the shell updates
// while it draws the film's frames between its own. The film is `trailray video`'s
// (app/video/film_recorder.hpp) with the viewer's style and tracks.

#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/track_set.hpp"

namespace trailray::app::view {

// The film's camera: behind the followed track, circling the tracks, or the view now.
enum class FilmCamera { follow, orbit, fixed };
inline constexpr const char* kFilmCameraNames[] = {"follow", "orbit", "fixed (this view)"};

struct FilmSettings {
  std::string path;  // empty: default_film_path of the tracks (the panel fills it in)
  FilmCamera camera = FilmCamera::follow;
  double seconds = 60.0;  // the film's length
  double fps = 30.0;
  int width = 1280, height = 720;
  bool replace = false;   // an existing file is replaced only when ticked
  int follow_track = -1;  // the track a follow camera follows; -1: the viewer's (see film_follow_track)
};

struct FilmStatus {
  bool recording = false;
  std::string path;  // the film being recorded
  std::size_t done = 0, total = 0;
  double frames_per_s = 0.0, seconds_left = 0.0;
  bool waiting = false;  // for the next frame's terrain tiles
  std::string result;    // "wrote ..." or "cancelled" after the last recording
};

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
