#include "app/view/viewer_app.hpp"

#include <GLFW/glfw3.h>
#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

#include "app/common/interrupt_guard.hpp"
#include "app/common/parallel_jobs.hpp"
#include "app/drawing/photo_drawing.hpp"
#include "app/options/places_options.hpp"
#include "app/view/film_panel.hpp"
#include "app/view/legend_overlay.hpp"
#include "app/view/profiler_table.hpp"
#include "app/view/viewer_shell.hpp"
#include "app/view/viewer_ui.hpp"
#include "scene/text/legend_content.hpp"
#include "scene/pins/place_labels.hpp"
#include "scene/pins/waypoint_building.hpp"
#include "ui/viewer_overlay.hpp"
#include "ui/viewer_panels.hpp"
#include "ui/waypoint_view.hpp"

namespace trailray::app::view {
namespace {

using Clock = std::chrono::steady_clock;

// A scripted frame counts as this much time for the moving frame's rest (moving_frame.hpp), so
// scripts see the same frames reduced on any machine: after a move, 6 frames, then the full one.
constexpr double kScriptedFrameS = 1.0 / 30.0;

// "frames: 100, mean 41.2 ms, median 40.8 ms (24.5 fps)".
std::string frame_time_summary(const std::string& what, std::vector<double> ms) {
  const double mean = std::accumulate(ms.begin(), ms.end(), 0.0) / static_cast<double>(ms.size());
  std::sort(ms.begin(), ms.end());
  const std::size_t n = ms.size();
  const double median = n % 2 == 1 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
  return fmt::format("{}: {}, mean {:.1f} ms, median {:.1f} ms ({:.1f} fps)", what, n, mean, median,
                     median > 0.0 ? 1000.0 / median : 0.0);
}

render::WindowOptions window_options(const ViewerOptions& o) {
  render::WindowOptions w;
  w.width_px = o.lens.width_px;
  w.height_px = o.lens.height_px;
  w.title = o.tracks.empty() ? std::string("trailray") : "trailray - " + o.tracks.front();
  w.vsync = o.frames == 0 && o.script.empty();  // scripted runs go as fast as they can
  return w;
}

}  // namespace

// The start, in the order that lets each step use the one before: sources, tracks (errors
// kept for the window), the window and GL, the camera.
ViewerApp::ViewerApp(const ViewerOptions& o)
    : options_(o),
      diagnostics_(o.verbose, false),
      sources_(open_terrain_sources(o.terrain, diagnostics_)),
      window_(window_options(o)),
      imgui_(window_),
      terrain_(sources_.drawn(), sources_.imagery.get()),
      profiler_(window_.capabilities(), 60) {
  for (const std::string& line : window_.describe()) diagnostics_.note(line);
  // Tracks are read before the first frame (like `render`); later files load in the background.
  TrackLoadInputs first_inputs = load_inputs(std::numeric_limits<double>::quiet_NaN());
  TerminalDiagnostics loading_progress(false);  // "reading 120/10000 files" on a terminal
  first_inputs.progress = &loading_progress;
  LoadedViewerTracks first = load_viewer_tracks(o.tracks, first_inputs);
  recorded_ = first.recorded;
  neutral_ = recorded_.lowest_or_sea_level();
  model_.neutral_ground_m = neutral_;
  model_.settings.style = o.style;
  model_.settings.sun_time_unix = sun_time(o.sun_time_unix, recorded_);
  model_.analysis = o.analysis;
  model_.parallel_for = parallel_for();
  model_.settings.show_waypoints = !o.no_waypoints;
  model_.settings.moving_frame = o.moving_frame;
  // What the session leaves to the window: where the panels and the legend leave room for a
  // framing, and a photo's larger picture (decoded from its file).
  session_.set_framing_room([this](const scene::Lens& lens) { return framing_room(lens); });
  session_.set_larger_photo([this](scene::Waypoint& w, int long_side_px) { decode_larger_photo(w, long_side_px); });
  // The tracks first: the legend they call for is kept clear by the first view's framing.
  adopt(std::move(first));
  // --surface: the canopy cut along the first tracks under cover, before any tile is drawn
  // (tracks opened later keep the canopy over them).
  sources_.cut_canopy(model_.tracks);
  // Place labels: a file that cannot be read stops the start, as in `render`.
  for (scene::Waypoint& w :
       scene::read_place_labels(o.label_files, o.read, {sources_.heights.get(), neutral_}, diagnostics_))
    model_.waypoints.points.push_back(std::move(w));
  if (!o.places_file.empty()) {  // --places: labels around the first tracks, their summits and huts
    std::vector<track::places::Place> places = places_around(o.places_file, model_.tracks, model_.waypoints, diagnostics_);
    for (scene::Waypoint& w : scene::osm_place_waypoints(places, o.places_file, {sources_.heights.get(), neutral_}))
      model_.waypoints.points.push_back(std::move(w));
    model_.visit_places = visit_places(std::move(places));
  }
  scene::set_waypoints_visible(model_.waypoints, model_.settings.show_waypoints);
  if (o.score) {  // after the visibility: the turnpoints were asked for explicitly
    scene::ScoredRouteDrawing drawing =
        scored_route_of(o.tracks, o.score_rules, o.style.tracks, {sources_.heights.get(), neutral_, o.analysis},
                        {sources_.heights.get(), neutral_}, diagnostics_);
    for (scene::Track& t : drawing.tracks) model_.tracks.add(std::move(t));
    for (scene::Waypoint& w : drawing.waypoints) model_.waypoints.points.push_back(std::move(w));
  }
  if (!o.task_file.empty()) {
    scene::TaskDrawing drawing = task_drawing_of(o.task_file, scene::highest_recorded_m(model_.tracks), o.style.tracks,
                                                 {sources_.heights.get(), neutral_, o.analysis},
                                                 {sources_.heights.get(), neutral_}, diagnostics_);
    for (scene::Track& t : drawing.tracks) model_.tracks.add(std::move(t));
    for (scene::Waypoint& w : drawing.waypoints) model_.waypoints.points.push_back(std::move(w));
    model_.volumes = std::move(drawing.volumes);
  }
  // --photos: placed on the first tracks, their pins with thumbnails.
  for (const track::PlacedPhoto& p :
       add_scene_photos(o.photos, model_.tracks, model_.waypoints, {sources_.heights.get(), neutral_}, diagnostics_).placed)
    photo_orientations_[p.photo.path] = p.photo.orientation;
  // The task's cylinders, then the airspaces; every volume placed on the terrain.
  add_airspace_volumes(model_.volumes, o.airspace_files, airspace_region(model_.tracks, model_.waypoints, o.camera),
                       sources_.heights.get(), diagnostics_);
  session_.place_camera(first_view(o, model_.tracks, model_.waypoints, sources_.heights.get(), neutral_,
                                   framing_room(o.lens), &diagnostics_),
                        o.lens);
  session_.set_ground([this](double lat, double lon) { return terrain_.height_in_memory(lat, lon); });
}

TrackLoadInputs ViewerApp::load_inputs(double neutral) const {
  TrackLoadInputs inputs{options_.read,    options_.analysis, options_.style.tracks, sources_.heights.get(), neutral, 0,
                         options_.thermals};
  inputs.surface = sources_.surface.get();
  return inputs;
}

double ViewerApp::sun_unix_time() const {
  return std::isnan(model_.settings.sun_time_unix) ? sun_time(std::nullopt, recorded_) : model_.settings.sun_time_unix;
}

void ViewerApp::adopt(LoadedViewerTracks loaded) {
  // Said on the terminal too; the session keeps them for the window.
  for (const std::string& w : loaded.warnings) diagnostics_.warning(w);
  for (const std::string& e : loaded.errors) diagnostics_.error(e);
  session_.adopt(std::move(loaded));
}

// The legend window's key: the tracks' names (several solid tracks), then the airspace classes.
std::vector<scene::TrackKeyEntry> ViewerApp::legend_key(const scene::TrackStyle& style) const {
  std::vector<scene::TrackKeyEntry> key = scene::track_key_for(style, model_.tracks);
  scene::Scene with_volumes;
  with_volumes.volumes = &model_.volumes;
  for (scene::TrackKeyEntry& entry : scene::airspace_key_for(with_volumes)) key.push_back(std::move(entry));
  return key;
}

// The scene as the panels have it now (visible tracks, style, the sun's time).
scene::Scene ViewerApp::scene() {
  scene::Scene s;
  s.terrain = &terrain_;
  s.tracks = &model_.tracks;
  s.waypoints = &model_.waypoints;
  if (!model_.volumes.volumes.empty()) s.volumes = &model_.volumes;
  s.style = model_.settings.style;
  s.color_range = model_.color_range();
  s.sun_time_unix_s = sun_unix_time();
  s.neutral_ground_m = neutral_;
  // Labels stay out from under the legend window where it first appears.
  if (panels_ && s.style.legend)
    s.label_keep_out.push_back(legend_overlay_rect(
        scene::color_legend_for(s.style.tracks, s.color_range), legend_key(s.style.tracks),
        static_cast<float>(window_.framebuffer_width()), static_cast<float>(window_.framebuffer_height())));
  return s;
}

void ViewerApp::frame(double wall_s, bool scripted) {
  const Clock::time_point start = Clock::now();
  window_.poll_events();
  take_dropped_files();
  step_film();  // the film's frames first: the panels show how far it is
  const std::uint32_t width = window_.framebuffer_width(), height = window_.framebuffer_height();
  std::optional<std::array<float, 2>> cursor;
  if (scripted) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    cursor = script_cursor_ ? std::array<float, 2>{static_cast<float>(script_cursor_->x) / scale.x,
                                                   static_cast<float>(script_cursor_->y) / scale.y}
                            : std::array<float, 2>{nan, nan};
  }
  imgui_.begin_frame(cursor);
  if (width > 0 && height > 0) camera().set_image_size(width, height);
  if (!scripted) {
    handle_mouse();
    handle_keys(wall_s);
  }
  session_.update(wall_s);
  session_.follow_replay();
  static const FilmPanel film{film_button, film_window};
  const PanelActions actions = panels_ ? draw_panels(model_, scripted ? 0.0 : wall_s, &film) : PanelActions{};
  if (actions.record_film) {
    try {
      start_film();
    } catch (const std::exception& e) {
      model_.errors.push_back(fmt::format("record film: {}", e.what()));
    }
  }
  if (actions.cancel_film) cancel_film();
  session_.apply(actions);
  const scene::Camera seen = camera().camera();  // as this frame draws it
  frame_moving_ = motion_.moving(seen, scripted ? kScriptedFrameS : wall_s);
  if (scripted && script_cursor_) session_.hover_at(script_cursor_->x, script_cursor_->y, seen);

  OverlayState overlay{
      model_, seen, progress_, status_, camera().view().heading_deg, scripted ? script_cursor_ : std::nullopt};
  if (panels_ && draw_overlays(overlay)) camera().reset_north();
  if (panels_ && model_.settings.style.legend) {
    const scene::TrackStyle& style = model_.settings.style.tracks;
    const auto legend = scene::color_legend_for(style, model_.color_range());
    const auto key = legend_key(style);
    draw_legend_overlay(legend, key);
    if (sources_.overlay_legend) draw_overlay_legend(*sources_.overlay_legend, legend, key);
  }
  if (width > 0 && height > 0) draw_scene_into_window(wall_s, frame_moving_ && model_.settings.moving_frame);
  imgui_.render();
  if (!window_grab_.empty() && width > 0 && height > 0) {
    scene::write_srgb_png(window_grab_, window_.read_pixels());
    diagnostics_.info(fmt::format("wrote {} ({}x{}, the window)", window_grab_, width, height));
    window_grab_.clear();
  }
  window_.swap_buffers();
  frame_times_.push_back({std::chrono::duration<double, std::milli>(Clock::now() - start).count(), frame_moving_});
}

// The scene without waiting for tiles, straight into the window; the profiler's figures.
void ViewerApp::draw_scene_into_window(double wall_s, bool reduced) {
  // Never wait: the tiles stream in coarse-to-fine while the loaders work between frames.
  scene::TileLoadPolicy never_wait;
  never_wait.wait = false;
  terrain_.set_policy(never_wait);
  render::DefaultFramebufferTarget window;
  window.profiler = &profiler_;
  window.pixel_ratio = window_.content_scale();
  const scene::Camera full = camera().camera();
  render::FrameReport drawn;
  if (reduced) {
    // Fewer pixels, scaled up into the window; labels shrink with them to keep their place.
    window.window_width_px = static_cast<int>(full.lens().width_px);
    window.window_height_px = static_cast<int>(full.lens().height_px);
    window.pixel_ratio /= kMovingFrameDivisor;
    render::FrameOptions moving;
    moving.reuse_shadow_maps = true;
    moving.ssao = false;
    scene::Scene s = scene();
    s.style = reduced_style(s.style);
    for (scene::PixelRect& r : s.label_keep_out)  // in the reduced frame's pixels (rounded outwards)
      r = {r.x / kMovingFrameDivisor, r.y / kMovingFrameDivisor,
           (r.width + 2 * kMovingFrameDivisor - 1) / kMovingFrameDivisor,
           (r.height + 2 * kMovingFrameDivisor - 1) / kMovingFrameDivisor};
    drawn = renderer_.draw(s, reduced_camera(full), window, moving);
  } else {
    drawn = renderer_.draw(scene(), full, window);
  }
  progress_ = drawn.terrain.progress;
  model_.loading = progress_.pending() > 0;
  model_.profile = profiler_table(profiler_, wall_s);
  model_.profile.mesh_bytes = drawn.gpu_meshes.bytes;
  model_.profile.mesh_budget_bytes = drawn.gpu_meshes.budget_bytes;
  model_.profile.imagery_bytes = drawn.gpu_imagery.bytes;
  model_.profile.imagery_budget_bytes = drawn.gpu_imagery.budget_bytes;
}

// A picture as `render` makes it: the scene once its tiles are in, with the legend.
void ViewerApp::screenshot(const std::string& path, bool status) {
  const scene::Scene s = scene();
  scene::TileLoadPolicy wait;
  wait.timeout = std::chrono::milliseconds(static_cast<long long>(options_.timeout_s * 1000.0));
  terrain_.set_policy(wait);
  render::ImageTarget picture;
  picture.pixel_ratio = window_.content_scale();
  const render::FrameReport drawn = renderer_.draw(s, camera().camera(), picture);
  if (drawn.terrain.timed_out)
    diagnostics_.warning(
        fmt::format("tiles still loading after {} s: the picture has what had arrived", options_.timeout_s));
  scene::draw_scene_legend(picture.image, s);
  scene::write_srgb_png(path, picture.image);
  const std::string wrote = fmt::format("wrote {} ({}x{})", path, picture.image.width, picture.image.height);
  if (status) status_ = wrote;
  diagnostics_.info(wrote);
}

void ViewerApp::print_frame_times(const std::vector<double>& all_ms, const std::vector<double>& settled_ms) {
  diagnostics_.info(frame_time_summary("frames", all_ms));
  if (settled_ms.size() != all_ms.size())
    diagnostics_.info(settled_ms.empty() ? std::string("frames with every tile loaded: none")
                                         : frame_time_summary("frames with every tile loaded", settled_ms));
  if (options_.verbose) {
    // The renderer's share of those frames, per pass (the last 60 frames).
    profiler_.finish();
    fmt::print(stderr, "{}", profiler_.table());
  }
}

std::string ViewerApp::frame_times_since_last_print() {
  std::vector<double> moving, resting;
  for (const TimedFrame& f : frame_times_) (f.moving ? moving : resting).push_back(f.ms);
  frame_times_.clear();
  const auto part = [](const char* what, const std::vector<double>& ms) {
    return ms.empty() ? fmt::format("{}: none", what) : frame_time_summary(what, ms);
  };
  return part("frames while moving", moving) + "; " + part("frames at rest", resting);
}

int ViewerApp::run() {
  const bool scripted = options_.frames > 0 || !options_.script.empty() || !options_.screenshot.empty();
  // Ctrl-C in the terminal (or SIGTERM) closes the window as its close button does: a film
  // being recorded is cancelled and leaves no temporary file; the exit status is then 130.
  const InterruptGuard guard;
  if (!scripted) {
    Clock::time_point last = Clock::now();
    while (!window_.should_close() && !interrupt_requested()) {
      const Clock::time_point now = Clock::now();
      frame(std::chrono::duration<double>(now - last).count(), false);
      last = now;
    }
    cancel_film();
    return interrupt_requested() ? 130 : 0;
  }
  // The script is read first: a typo fails before any frame is drawn.
  const std::optional<ViewScript> script =
      options_.script.empty() ? std::nullopt : std::optional<ViewScript>(load_view_script(options_.script));
  frame(0.0, true);
  if (options_.frames > 0) {
    // Timed frames, as a person would see them (tiles stream in meanwhile), to standard error.
    std::vector<double> all_ms, settled_ms;
    for (int i = 0; i < options_.frames && !interrupt_requested(); ++i) {
      const Clock::time_point start = Clock::now();
      frame(0.0, true);
      const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
      all_ms.push_back(ms);
      if (progress_.done()) settled_ms.push_back(ms);
    }
    print_frame_times(all_ms, settled_ms);
  }
  if (script) run_script(*script);
  if (interrupt_requested()) {
    cancel_film();
    return 130;
  }
  if (!options_.screenshot.empty()) screenshot(options_.screenshot);
  return 0;
}

int run_viewer(const ViewerOptions& options) {
  // A script that does not parse fails before a window opens.
  if (!options.script.empty()) load_view_script(options.script);
  ViewerApp app(options);
  return app.run();
}

}  // namespace trailray::app::view
