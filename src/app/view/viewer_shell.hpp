#pragma once
// The viewer's shell (internal to app/view): the window, the renderer and the model together.
// Its parts live in viewer_app.cpp (start, frame, pictures, loop), viewer_input.cpp (mouse, keys,
// dropped files, hover), viewer_camera.cpp (first view, fly-to, replay follow, where framing may
// put the tracks), viewer_film.cpp (record film) and viewer_script_runner.cpp (--script).

#include <future>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "app/airspace_options.hpp"
#include "app/scene_setup.hpp"
#include "app/terminal_diagnostics.hpp"
#include "app/view/film_session.hpp"
#include "app/view/moving_frame.hpp"
#include "app/view/track_loading.hpp"
#include "app/view/view_script.hpp"
#include "app/view/viewer_app.hpp"
#include "app/view/viewer_ui.hpp"
#include "render/gl/frame_profiler.hpp"
#include "render/platform/imgui_layer.hpp"
#include "render/platform/window.hpp"
#include "render/renderer.hpp"
#include "scene/camera_controller.hpp"
#include "scene/framing.hpp"
#include "scene/legend.hpp"
#include "scene/scene.hpp"
#include "scene/terrain_view.hpp"
#include "scene/volume_shapes.hpp"
#include "ui/framing_room.hpp"
#include "ui/viewer_model.hpp"

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
  void handle_mouse(const scene::Camera& camera);
  void handle_keys(double wall_s);
  void take_dropped_files();
  void adopt(LoadedViewerTracks loaded);
  scene::Scene scene();
  scene::KeptClearCorner legend_corner(const scene::Lens& lens);
  FramingRoom framing_room(const scene::Lens& lens);
  void update_hover(double x_px, double y_px, const scene::Camera& camera);
  // The airspace wall under the pixel, in front of the terrain `ground_m` away (infinity: none).
  int pick_airspace(double x_px, double y_px, const scene::Camera& camera, double ground_m);
  std::vector<scene::TrackKeyEntry> legend_key(const scene::TrackStyle& style) const;
  void fly_to_track(int index);
  void fly_to_waypoint(int index);  // index into model_.waypoints (a photo's: also shown larger)
  // The photo of waypoint `index` shown larger over its pin (decoded again at the size it is
  // drawn), every other photo at its thumbnail's size.
  void enlarge_photo(int index);
  void follow_replay();             // the replay's camera follow (chase, or orbit round the marker)
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
  // The airspaces' walls as the hover picks them, made again when the set's revision changes.
  std::vector<scene::VolumeShape> volume_shapes_;
  std::uint64_t volume_shapes_revision_ = ~std::uint64_t{0};
  scene::RecordedPoints recorded_;
  ViewerModel model_;
  // GL objects after the window (the context) and before nothing else: destroyed first.
  render::Window window_;
  render::ImGuiLayer imgui_;
  scene::TerrainView terrain_;  // the tiles for a camera (GL-free; its loaders read sources_)
  render::Renderer renderer_;
  render::FrameProfiler profiler_;
  scene::CameraController controller_;
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

// The first view: the options' camera, else framed on the tracks where the panels and the
// legend leave the window free; the pivot on the ground.
scene::CameraController first_view(const ViewerOptions& options, const scene::TrackSet& tracks,
                                   const scene::WaypointSet& waypoints, terrain::HeightSource* heights, double neutral,
                                   const FramingRoom& room, scene::Diagnostics* diagnostics = nullptr);

}  // namespace trailray::app::view
