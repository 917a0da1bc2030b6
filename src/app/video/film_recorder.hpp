#pragma once
// A film's frame loop, shared by `trailray video` and the viewer's "record film": for each
// planned camera the tracks are cut at that frame's time, the scene is drawn by the renderer
// (waiting for its tiles), the legend, the overlay and the mini profile are painted over it, and
// the frame goes to a FilmWriter. One frame per call, so a window can draw itself between them;
// `trailray video` calls it in a loop. The same setup gives the same frames.

#include <chrono>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/drawing/scene_setup.hpp"
#include "app/video/film_plan.hpp"
#include "app/video/film_writer.hpp"
#include "render/renderer.hpp"
#include "scene/film/film_overlay.hpp"
#include "scene/film/film_photos.hpp"
#include "scene/film/film_profile.hpp"
#include "scene/film/film_tracks.hpp"
#include "scene/pins/photo_image.hpp"
#include "scene/scene.hpp"
#include "scene/terrain_view.hpp"

namespace trailray::app {

// What a film shows, planned before its first frame. The pointers must outlive the recorder.
struct FilmSetup {
  const scene::TrackSet* tracks = nullptr;        // the tracks as loaded (whole)
  const scene::WaypointSet* waypoints = nullptr;  // the files' waypoints and places
  const scene::VolumeSet* volumes = nullptr;      // airspaces and task cylinders (nullptr: none)
  scene::TerrainView* terrain = nullptr;          // the film's own: its policy is set per frame
  scene::TileLoadPolicy tiles;                    // how a frame waits for its tiles (wait = true)
  scene::Style style;
  std::optional<track::ValueRange> color_range;
  std::optional<scene::ColorLegend> overlay_legend;  // --overlay's colour bar
  double sun_time_unix_s = 0.0;
  double neutral_ground_m = 0.0;  // the scene's (NaN: the lowest terrain loaded for the view)
  double marker_ground_m = 0.0;   // where a marker's stem ends when the ground is unknown
  scene::TrailMode trail;
  scene::OverlayLevel overlay = scene::OverlayLevel::full;
  FilmClock clock;
  std::vector<scene::Camera> cameras;  // one per frame, all of the film's size
  std::vector<std::size_t> gauged;     // the tracks with a panel of gauges (the first: the profile's)
  std::string attribution;             // the map data's credits ("" : none)
  double pixel_ratio = 1.0;            // the labels' device pixels per pixel
  // --photos with --photo-seconds: the film's frames (the clock's, and pauses at the photos:
  // scene::film_frames_with_photos) and each photo shown large with its caption. No frames: the
  // clock's frames as they are.
  struct Photo {
    std::shared_ptr<const scene::PhotoImage> image;  // nullptr: it could not be decoded (not shown)
    std::string caption;
  };
  std::vector<scene::FilmFrame> frames;
  std::vector<Photo> photos;
  std::size_t frame_count() const { return frames.empty() ? cameras.size() : frames.size(); }
};

// The tracks with gauges: the followed one (a follow camera), else every recorded track with
// times. `follow` counts from 1.
std::vector<std::size_t> gauged_tracks(const scene::TrackSet& tracks, FilmCameraMode mode, int follow);

// The credits of the height and imagery sources, each once, joined by " | ".
std::string map_attribution(const TerrainSources& sources);

struct FilmProgress {
  std::size_t done = 0, total = 0;
  double frames_per_s = 0.0;  // since the first frame
  double seconds_left = 0.0;  // at that rate
};
// "frame 12/300  2.41 fps  1:59 left".
std::string film_progress_text(const FilmProgress& progress);

class FilmRecorder {
 public:
  // Throws std::invalid_argument for a setup without cameras or tracks, and what the writer throws.
  FilmRecorder(FilmSetup setup, std::unique_ptr<FilmWriter> writer);
  ~FilmRecorder();
  FilmRecorder(const FilmRecorder&) = delete;
  FilmRecorder& operator=(const FilmRecorder&) = delete;

  // Whether the next frame's tiles are all in memory: asks for them without waiting (a window
  // calls it each of its frames and draws the film's frame only once they are in).
  bool next_frame_ready();
  // Draws the next frame with `renderer` (its GL context current) and hands it to the writer.
  // Throws RenderError and the writer's errors.
  void draw_next(render::Renderer& renderer);
  bool done() const { return next_ == setup_.frame_count(); }
  FilmProgress progress() const;
  // After the last frame: the film put in place. Throws the writer's errors.
  void finish();
  // Stops: no film is left (a video file's temporary is removed), an earlier one stays.
  void cancel();

  const FilmSetup& setup() const { return setup_; }
  const scene::RgbaImage& last_frame() const { return picture_.image; }

 private:
  FilmSetup setup_;
  std::unique_ptr<FilmWriter> writer_;
  scene::FilmTracks film_;
  scene::Scene scene_, legend_scene_;
  scene::TextRasterizer text_;
  scene::FilmProfile profile_;
  render::ImageTarget picture_;
  std::size_t next_ = 0;
  std::optional<std::chrono::steady_clock::time_point> started_;
  double elapsed_s_ = 0.0;  // from the first frame's start to the last frame's end
};

}  // namespace trailray::app
