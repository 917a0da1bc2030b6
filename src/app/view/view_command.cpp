#include "app/view/view_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <memory>

#include "app/common/track_arguments.hpp"
#include "app/options/camera_options.hpp"
#include "app/options/picture_options.hpp"
#include "app/options/scene_options.hpp"
#include "app/options/style_options.hpp"
#include "app/view/viewer_app.hpp"

namespace trailray::app {
namespace {

constexpr int kMaxFrames = 100000;

struct ViewArgs {
  std::vector<std::string> tracks;
  std::string size = "1280x720";
  CameraArgs camera;
  SceneArgs scene;  // what is drawn and how: as `render` and `video` (app/options/scene_options)
  bool verbose = false;
  int frames = 0;
  std::string script, screenshot;
  double timeout_s = 120.0;
  bool no_moving_frame = false;
};

int run_view(const ViewArgs& a) {
  view::ViewerOptions o;
  o.lens = parse_lens(a.size, a.camera.fov_deg);
  o.camera = parse_camera_request(a.camera, !a.tracks.empty());
  if (a.frames < 0 || a.frames > kMaxFrames)
    throw CLI::ValidationError("--frames", fmt::format("'{}' is not a frame count in 0..{}", a.frames, kMaxFrames));
  check_timeout_option(a.timeout_s);
  o.sun_time_unix = parse_sun_time(a.scene.style.time);  // a bad --time is a usage error, before any window
  o.tracks = a.tracks;
  o.style = parse_style(a.scene.style);
  o.read = a.scene.track_options.read;
  o.analysis = a.scene.track_options.analysis;
  o.terrain = a.scene.terrain;
  o.verbose = a.verbose;
  o.frames = a.frames;
  o.script = a.script;
  o.screenshot = a.screenshot;
  o.timeout_s = a.timeout_s;
  o.label_files = a.scene.waypoints.label_files;
  o.places_file = a.scene.waypoints.places_file;
  o.no_waypoints = a.scene.waypoints.no_waypoints;
  o.score = a.scene.waypoints.score;
  o.score_rules = a.scene.waypoints.score_rules;
  o.task_file = a.scene.waypoints.task_file;
  o.photos = a.scene.photos;
  o.airspace_files = a.scene.airspace.files;
  o.thermals = a.scene.waypoints.thermals_for(o.style.tracks.color_by);
  o.moving_frame = !a.no_moving_frame;
  return view::run_viewer(o);
}

}  // namespace

void add_view_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ViewArgs>();
  CLI::App* cmd = app.add_subcommand("view", "Tracks on the terrain in a window: fly around, inspect, replay");
  cmd->footer(
      "Mouse: left drag orbits around the ground point, right drag pans, the wheel zooms toward the cursor,\n"
      "double click flies there. Keys: W A S D or arrows move, Q E turn, Page Up/Down tilt, + - zoom,\n"
      "N north up, F fly to the selected track, Space play/pause the replay, P writes a screenshot.\n"
      "Files dropped on the window are opened. Needs a display (X11, Wayland, or xvfb-run).\n"
      "Scripted: --frames N renders N frames and prints the frame times; --script FILE runs commands\n"
      "(orbit DX DY, pan DX DY, zoom STEPS, select TRACK, hover X Y, print-hover, print-marker,\n"
      "print-camera, play SECONDS, speed X, wait FRAMES, screenshot PATH, window-screenshot PATH, print-frame-times,\n"
      "record-film PATH SECONDS (a film as the replay panel's \"record film\" makes it), start-film PATH SECONDS,\n"
      "cancel-film, film-size W H, film-fps N, film-camera follow|orbit|fixed);\n"
      "--screenshot OUT.png"
      " writes the picture at the end and exits.\n"
      "Exit status: 0 done, 1 a file, source, script or GL failed, 2 a usage error.");
  cmd->add_option(
         "TRACK", args->tracks,
         "Track files (GPX, IGC, TCX, FIT, KML, KMZ, GeoJSON), folders of them, or patterns ('flights/*.igc') to "
         "show (the view frames them)")
      ->type_name("FILE");
  cmd->add_option("--size", args->size, "Window size in pixels (default 1280x720)")->type_name("WxH");
  add_camera_options(*cmd, args->camera);
  add_shading_options(*cmd, args->scene.style);
  cmd->add_option("--timeout", args->timeout_s, "Seconds a scripted screenshot waits for terrain tiles (default 120)")
      ->type_name("S");
  cmd->add_flag("--verbose", args->verbose, "Log the GL context");
  cmd->add_flag("--no-moving-frame", args->no_moving_frame,
                "Draw the full frame while the camera moves too (by default a moving camera gets half the resolution, "
                "no ambient occlusion and the last shadows, and the full frame once it rests for 0.2 s)");
  cmd->add_option("--frames", args->frames,
                  "Render N frames, print their mean and median time to standard error, then exit")
      ->type_name("N");
  cmd->add_option("--script", args->script, "Run the commands in FILE, one per line, then exit")->type_name("FILE");
  cmd->add_option("--screenshot", args->screenshot, "At the end of a scripted run, write the view as a PNG and exit")
      ->type_name("OUT.png");
  add_scene_options(*cmd, args->scene);
  cmd->callback([args, &exit_code] {
    args->tracks = expand_track_arguments(args->tracks);
    exit_code = run_view(*args);
  });
}

}  // namespace trailray::app
