#pragma once
// The viewer's shell (internal to app/view): the window, the renderer and the model together.
// What a viewer is (the model, the camera, hover, keys, fly-to, the first view) is ui::ViewerSession,
// shared with the page; this shell hands it the window's input and time and draws what it holds.
// Its parts live in viewer_app.cpp (start, frame, pictures, loop), viewer_input.cpp (mouse and
// keys handed to the session, dropped files), viewer_camera.cpp (the first view, where framing may
// put the tracks, photos decoded larger), viewer_film.cpp (record film) and
// viewer_script_runner.cpp (--script).

#include <future>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "app/options/airspace_options.hpp"
#include "app/drawing/scene_setup.hpp"
#include "app/common/terminal_diagnostics.hpp"
#include "app/view/film_session.hpp"
#include "app/view/moving_frame.hpp"
#include "app/view/track_loading.hpp"
#include "app/view/viewer_app.hpp"
#include "app/view/viewer_ui.hpp"
#include "render/gl/frame_profiler.hpp"
#include "render/platform/imgui_layer.hpp"
#include "render/platform/window.hpp"
#include "render/renderer.hpp"
#include "scene/camera/camera_controller.hpp"
#include "scene/camera/framing.hpp"
#include "scene/text/legend.hpp"
#include "scene/scene.hpp"
#include "scene/terrain_view.hpp"
#include "scene/volumes/volume_shapes.hpp"
#include "ui/framing_room.hpp"
#include "ui/viewer_model.hpp"
#include "ui/viewer_session.hpp"
#include "ui/view_script.hpp"

namespace trailray::app::view {

class ViewerApp {
 public:
  explicit ViewerApp(const ViewerOptions& options);
  int run();

 private:
  // One frame: input (unless scripted), scene, panels, overlays, swap. `wall_s` drives the
  // replay clock and the camera's flights.
  void frame(double wall_s, bool scripted);
  // `reduced`: the moving frame (moving_frame.hpp).
  void draw_scene_into_window(double wall_s, bool reduced);
  void handle_mouse();
  void handle_keys(double wall_s);
  void take_dropped_files();
  void adopt(LoadedViewerTracks loaded);
  scene::Scene scene();
  scene::KeptClearCorner legend_corner(const scene::Lens& lens);
  FramingRoom framing_room(const scene::Lens& lens);
  std::vector<scene::TrackKeyEntry> legend_key(const scene::TrackStyle& style) const;
  // A photo's picture decoded again at `long_side_px` for its enlarged pin (the session's hook).
  void decode_larger_photo(scene::Waypoint& photo, int long_side_px);
  scene::CameraController& camera() { return session_.camera(); }
  // `status`: say so in the window too (the P key; not scripted pictures).
  void screenshot(const std::string& path, bool status = false);
  void run_script(const ViewScript& script);
  // Carries out one command; the frames to draw after it.
  int run_script_command(const ScriptCommand& command, const ViewScript& script);
  // Starts recording the film model_.film describes; throws std::runtime_error (and the
  // planner's CLI::ValidationError) when it cannot.
  void start_film();
  // Each frame: the film's next frames (within a time budget, once their tiles are in); at the
  // end the film is put in place.
  void step_film();
  void cancel_film();
  void print_frame_times(const std::vector<double>& all_ms, const std::vector<double>& settled_ms);
  // `print-frame-times`: the frames drawn since the last call, moving and at rest apart.
  std::string frame_times_since_last_print();
  double sun_unix_time() const;
  TrackLoadInputs load_inputs(double neutral) const;

  ViewerOptions options_;
  TerminalDiagnostics diagnostics_;
  TerrainSources sources_;
  double neutral_ = 0.0;
  scene::RecordedPoints recorded_;
  ui::ViewerSession session_;        // the model, the camera, what input does to them
  ViewerModel& model_ = session_.model();  // the session's model by its short name
  // GL objects after the window (the context) and before nothing else: destroyed first.
  render::Window window_;
  render::ImGuiLayer imgui_;
  scene::TerrainView terrain_;  // the tiles for a camera (GL-free; its loaders read sources_)
  render::Renderer renderer_;
  render::FrameProfiler profiler_;
  MotionWatch motion_;
  bool frame_moving_ = false;  // the last frame's camera was moving
  struct TimedFrame {
    double ms;
    bool moving;
  };
  std::vector<TimedFrame> frame_times_;  // since the last print-frame-times
  std::vector<std::future<LoadedViewerTracks>> loading_;
  terrain::LoadProgress progress_;
  std::string status_;                       // a line at the bottom (screenshot written, ...)
  std::optional<glm::dvec2> script_cursor_;  // `hover X Y`
  bool panels_ = true;                       // false: `hide-panels`
  std::string window_grab_;                  // `window-screenshot PATH`: after the next frame's UI
  std::string film_error_;                   // why the last film stopped ("" : it did not fail)
  std::unordered_map<std::string, int> photo_orientations_;  // --photos: each placed photo's EXIF orientation
  std::unique_ptr<FilmSession> film_;        // a film recording; last: destroyed with the context current
};

// The first view (ui::first_view, as the page's) from the options' camera, else framed on the
// tracks where the panels and the legend leave the window free; the pivot on the ground. Throws
// std::runtime_error when there is nothing to look at, CLI::ValidationError for a camera that
// cannot be made.
scene::LookAt first_view(const ViewerOptions& options, const scene::TrackSet& tracks,
                         const scene::WaypointSet& waypoints, terrain::HeightSource* heights, double neutral,
                         const FramingRoom& room, scene::Diagnostics* diagnostics = nullptr);

}  // namespace trailray::app::view
