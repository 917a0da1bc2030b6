#pragma once
// The viewer's "record film" (in the replay panel) as plain data: what the user set up (the
// camera, the file, the length, the size) and how the recording goes, which the desktop's shell
// updates while it draws the film's frames between its own (app/view/viewer_film.cpp). The page
// records no film: its model keeps these at their defaults.

#include <cstddef>
#include <string>

namespace trailray::ui {

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

}  // namespace trailray::ui
