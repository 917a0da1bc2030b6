// The viewer's "record film": `trailray video`'s plan and recorder with the viewer's tracks,
// style and camera, its frames drawn between the window's (app/video/film_recorder.hpp).
#include <fmt/format.h>

#include <stdexcept>

#include "app/video/film_plan.hpp"
#include "app/video/video_options.hpp"
#include "app/view/film_settings.hpp"
#include "app/view/viewer_shell.hpp"

namespace trailray::app::view {
namespace {

using Clock = std::chrono::steady_clock;

// Film frames drawn in one window frame: at least one, more while this much time is left, so the
// window answers at a few frames per second even on a CPU renderer.
constexpr std::chrono::milliseconds kFilmBudget{40};

// The options `trailray video` would be given for the film: the plan reads them.
VideoArgs film_args(const FilmSettings& s, const scene::TrackSet& tracks, std::size_t followed) {
  VideoArgs a;
  for (const scene::Track& t : tracks.tracks()) a.tracks.push_back(t.source);
  a.output = s.path;
  a.force = true;
  a.size = fmt::format("{}x{}", s.width, s.height);
  a.duration = fmt::format("{}s", s.seconds);
  a.fps = s.fps;
  a.follow = static_cast<int>(followed) + 1;
  a.mode = s.camera == FilmCamera::orbit ? "orbit" : s.camera == FilmCamera::fixed ? "fixed" : "follow";
  return a;
}

}  // namespace

void ViewerApp::start_film() {
  if (film_) throw std::runtime_error("a film is already recording");
  if (model_.tracks.empty()) throw std::runtime_error("no track to film");
  FilmSettings& s = model_.film;
  if (s.path.empty()) s.path = default_film_path(model_.tracks);
  if (const std::string problem = film_settings_problem(s); !problem.empty()) throw std::runtime_error(problem);
  auto session = std::make_unique<FilmSession>();
  session->tracks = model_.tracks;
  session->waypoints = model_.waypoints;
  session->volumes = model_.volumes;
  const int preferred = model_.clock.follow != FollowMode::off ? model_.clock.follow_track : model_.selected_track;
  const std::size_t followed = film_follow_track(s, session->tracks, preferred);
  const VideoArgs a = film_args(s, session->tracks, followed);
  const FilmCameraMode mode = check_video_args(a);
  scene::Lens lens = camera().lens();
  lens.width_px = static_cast<std::uint32_t>(s.width);
  lens.height_px = static_cast<std::uint32_t>(s.height);

  FilmSetup setup;
  setup.clock = plan_film_clock(a, session->tracks);
  if (mode == FilmCameraMode::fixed) {
    // The view now, at the film's size.
    CameraRequest request;
    request.look_at = camera().view();
    setup.cameras.assign(setup.clock.timing.frames,
                         initial_camera(request, lens, session->tracks, neutral_, sources_.heights.get()));
  } else {
    setup.cameras = plan_film_cameras(a, mode, lens, setup.clock, session->tracks, neutral_, sources_.heights.get());
  }
  session->terrain = std::make_unique<scene::TerrainView>(sources_.heights.get(), sources_.imagery.get());
  setup.tracks = &session->tracks;
  setup.waypoints = &session->waypoints;
  setup.volumes = &session->volumes;
  setup.terrain = session->terrain.get();
  setup.tiles.wait = true;
  setup.tiles.timeout = std::chrono::milliseconds(static_cast<long long>(options_.timeout_s * 1000.0));
  setup.style = model_.settings.style;
  setup.color_range = model_.color_range();
  setup.overlay_legend = sources_.overlay_legend;
  setup.sun_time_unix_s = sun_unix_time();
  setup.neutral_ground_m = recorded_.lowest_m;
  setup.marker_ground_m = neutral_;
  setup.gauged = gauged_tracks(session->tracks, mode, a.follow);
  setup.attribution = map_attribution(sources_);
  session->renderer = std::make_unique<render::Renderer>();
  session->path = s.path;
  const std::size_t frames = setup.cameras.size();
  session->recorder = std::make_unique<FilmRecorder>(
      std::move(setup), open_video_file(s.path, {static_cast<std::uint32_t>(s.width),
                                                 static_cast<std::uint32_t>(s.height), s.fps, VideoArgs{}.crf}));
  film_ = std::move(session);
  film_error_.clear();
  model_.film_status = FilmStatus{true, s.path, 0, frames, 0.0, 0.0, false, {}};
  model_.settings.show_film = true;
  diagnostics_.note(fmt::format("film: {} frames at {} fps into {}", frames, s.fps, s.path));
}

void ViewerApp::step_film() {
  if (!film_) return;
  FilmRecorder& recorder = *film_->recorder;
  try {
    const Clock::time_point start = Clock::now();
    bool waiting = false;
    do {
      // The tiles load while the window draws: a frame is drawn once they are in (or, after the
      // timeout, with what has arrived, as `trailray video` would).
      if (!recorder.next_frame_ready()) {
        if (!film_->waiting_since) film_->waiting_since = Clock::now();
        if (Clock::now() - *film_->waiting_since < std::chrono::duration<double>(options_.timeout_s)) {
          waiting = true;
          break;
        }
      }
      film_->waiting_since.reset();
      recorder.draw_next(*film_->renderer);
    } while (!recorder.done() && Clock::now() - start < kFilmBudget);
    const FilmProgress p = recorder.progress();
    FilmStatus& status = model_.film_status;
    status.done = p.done;
    status.frames_per_s = p.frames_per_s;
    status.seconds_left = p.seconds_left;
    status.waiting = waiting;
    if (!recorder.done()) return;
    recorder.finish();
    const FilmSetup& setup = recorder.setup();
    const scene::Lens& lens = setup.cameras.front().lens();
    status.result = fmt::format("wrote {} ({} frames {}x{} at {} fps; {:.2f} frames/s)", film_->path, p.total,
                                lens.width_px, lens.height_px, setup.clock.timing.fps, p.frames_per_s);
    diagnostics_.info(status.result);
    status_ = status.result;
  } catch (const std::exception& e) {
    recorder.cancel();
    film_error_ = fmt::format("film {}: {}", film_->path, e.what());
    diagnostics_.error(film_error_);
    model_.errors.push_back(film_error_);
    model_.film_status.result = film_error_;
  }
  model_.film_status.recording = false;
  film_.reset();
}

void ViewerApp::cancel_film() {
  if (!film_) return;
  const std::size_t done = film_->recorder->progress().done;
  film_->recorder->cancel();  // the temporary file goes; an earlier film stays
  model_.film_status.recording = false;
  model_.film_status.result =
      fmt::format("cancelled after {} of {} frames: {} not written", done, model_.film_status.total, film_->path);
  diagnostics_.info(model_.film_status.result);
  film_.reset();
}

}  // namespace trailray::app::view
