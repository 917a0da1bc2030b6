#pragma once
// `trailray view --script FILE` (and the page's trailray_run_script): simple commands, one per
// line, that drive the viewer for tests and scripted pictures. Blank lines and lines starting with
// '#' are skipped. The commands on the session (script_session.hpp) run alike in both front ends;
// pictures, frames, panels and films are the desktop's.
//
//   orbit DX DY       a left drag of DX, DY pixels (heading and pitch around the pivot)
//   pan DX DY         a right drag of DX, DY pixels from the image centre
//   zoom STEPS        wheel steps toward the image centre (negative: out)
//   select TRACK      the statistics panel's track (0-based), and the camera flies to it
//   select-waypoint N the camera flies to waypoint N (0-based: the files' waypoints, then places)
//   print-waypoints   prints each waypoint's pin position (pixels) and where it is on the chart's track
//   hover X Y         the cursor at pixel (X, Y): picks the track point there
//   print-hover       prints the hovered point's tooltip to standard output
//   print-marker      prints each track's replay marker position (pixels) to standard output
//   print-camera      prints the camera's pivot, distance, heading and pitch
//   print-state       prints what the viewer shows as one line of JSON (ui/session_state.hpp: the
//                     tracks, the selected track's statistics, the hover, the camera, the
//                     enlarged photo, warnings), as the page's status gives it
//   play SECONDS      the replay runs SECONDS of wall time at its speed, then pauses
//   speed X           the replay's speed (1..1000 times real time)
//   wait FRAMES       renders FRAMES frames
//   screenshot PATH   waits for the view's tiles, then writes the picture (as `render` would)
//   window-screenshot PATH  the window as shown, panels included (after the next frame)
//   hide-panels       draws the 3D view alone from now on (no panels, markers or tooltip)
//   print-frame-times prints the times of the frames drawn since the last print (or the start),
//                     those drawn while the camera moved and those at rest apart; draws no frame
//                     (with --verbose also the profiler's table of the last 60 frames)
//   record-film PATH SECONDS  records a film of SECONDS (as the "record film" window is set:
//                     camera, size, rate), drawing frames until it is written
//   start-film PATH SECONDS   starts recording it and goes on (`wait` draws its frames meanwhile)
//   cancel-film       stops the film recording: no file is left
//   film-size W H     the film's size in pixels (default 1280 720)
//   film-fps N        the film's frames per second (default 30)
//   film-camera MODE  follow (default), orbit or fixed (the view at the start)
//
// Errors name the file and the line: "view.txt:3: orbit expects two numbers, got 'left'".

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace trailray::ui {

class ScriptError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ScriptCommand {
  enum class Kind {
    orbit,
    pan,
    zoom,
    select,
    select_waypoint,
    print_waypoints,
    hover,
    print_hover,
    print_marker,
    print_camera,
    print_state,
    play,
    speed,
    wait,
    screenshot,
    window_screenshot,
    hide_panels,
    print_frame_times,
    record_film,
    start_film,
    cancel_film,
    film_size,
    film_fps,
    film_camera
  };
  Kind kind = Kind::wait;
  double x = 0.0, y = 0.0;  // the numbers (one or two)
  std::string path;         // screenshot, window-screenshot, record-film, start-film; film-camera's mode
  int line = 0;             // 1-based, for messages
};

struct ViewScript {
  std::string file;
  std::vector<ScriptCommand> commands;
};

// Throws ScriptError "FILE:LINE: ..." for an unknown command, a wrong number of arguments, or a
// number that is not one (or out of range: negative frames, track or seconds).
ViewScript parse_view_script(std::string_view text, const std::string& file);
// Reads and parses a file; ScriptError names it when it cannot be read.
ViewScript load_view_script(const std::string& path);

}  // namespace trailray::ui
