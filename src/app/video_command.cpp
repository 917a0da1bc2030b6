#include "app/video_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <memory>
#include <vector>

#include "app/airspace_options.hpp"
#include "app/output_file.hpp"
#include "app/render_report.hpp"
#include "app/scene_setup.hpp"
#include "app/terminal_diagnostics.hpp"
#include "app/track_arguments.hpp"
#include "app/video/film_plan.hpp"
#include "app/video/film_writer.hpp"
#include "app/video_options.hpp"
#include "render/platform/gl_context.hpp"
#include "render/renderer.hpp"
#include "scene/film/film_overlay.hpp"
#include "scene/film/film_profile.hpp"
#include "scene/film/film_tracks.hpp"
#include "scene/legend_content.hpp"
#include "scene/terrain_view.hpp"

namespace trailray::app {
namespace {

volatile std::sig_atomic_t interrupted = 0;
extern "C" void on_interrupt(int) { interrupted = 1; }

// Ctrl-C asks the frame loop to stop (after the frame it is drawing) instead of killing the
// process, so the temporary file is removed; the previous handler is back afterwards.
class InterruptGuard {
 public:
  InterruptGuard() {
    interrupted = 0;
    previous_int_ = std::signal(SIGINT, on_interrupt);
    previous_term_ = std::signal(SIGTERM, on_interrupt);
  }
  ~InterruptGuard() {
    std::signal(SIGINT, previous_int_);
    std::signal(SIGTERM, previous_term_);
  }

 private:
  void (*previous_int_)(int) = SIG_DFL;
  void (*previous_term_)(int) = SIG_DFL;
};

// Every camera is known before the first frame: while a frame is drawn, the tiles of one a little
// later are already loading (the frame itself still waits for all of its own).
constexpr std::size_t kPrefetchFrames = 10;
void prefetch_tiles(scene::TerrainView& terrain, const scene::Camera& later, double neutral_ground_m) {
  if (terrain.heights() == nullptr && terrain.imagery() == nullptr) return;
  scene::TileLoadPolicy waiting = terrain.policy(), asking = waiting;
  asking.wait = false;
  terrain.set_policy(asking);
  terrain.tiles_for(later, neutral_ground_m);
  terrain.set_policy(std::move(waiting));
}

std::string clock_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  return s >= 3600 ? fmt::format("{}:{:02d}:{:02d}", s / 3600, (s / 60) % 60, s % 60)
                   : fmt::format("{}:{:02d}", s / 60, s % 60);
}

// A folder of frames: an earlier film's frames are replaced (all of them) only with --force.
void check_frames_dir(const std::string& dir, bool force) {
  std::error_code error;
  if (!std::filesystem::exists(dir, error)) return;
  if (!std::filesystem::is_directory(dir, error)) throw std::runtime_error(dir + ": is not a folder");
  std::vector<std::filesystem::path> earlier;
  for (const auto& entry : std::filesystem::directory_iterator(dir, error))
    if (entry.path().filename().string().rfind("frame_", 0) == 0 && entry.path().extension() == ".png")
      earlier.push_back(entry.path());
  if (!earlier.empty() && !force) throw std::runtime_error(dir + ": already holds frames (--force replaces them)");
  // A shorter film must not leave the earlier one's last frames behind.
  for (const auto& path : earlier) std::filesystem::remove(path, error);
}

int run_video(const VideoArgs& a) {
  InterruptGuard guard;  // from the start: Ctrl-C while the tracks load stops before the first frame too
  const FilmCameraMode mode = check_video_args(a);
  const scene::Lens lens = parse_lens(a.size, a.camera.fov_deg);
  StyleArgs style_args = a.style;
  if (a.fast) style_args.no_shadows = style_args.no_ssao = true;  // two thirds of a frame on llvmpipe
  const scene::Style style = parse_style(style_args);
  const scene::TrailMode trail = [&] {
    auto parsed = scene::parse_trail_mode(a.trail);
    if (!parsed.ok()) throw CLI::ValidationError("--trail", parsed.error);
    return *parsed.value;
  }();
  const scene::OverlayLevel overlay = [&] {
    auto parsed = scene::parse_overlay_level(a.overlay);
    if (!parsed.ok()) throw CLI::ValidationError("--overlay", parsed.error);
    return *parsed.value;
  }();
  const std::optional<double> sun = parse_sun_time(a.style.time);
  if (!a.output.empty()) {
    check_output_path(a.output, a.tracks, a.force);
    if (!codec_for_path(a.output))
      throw CLI::ValidationError("--output", a.output + ": a film is .mp4 (H.264) or .webm (VP9), or use --frames-dir");
    if (lens.width_px % 2 != 0 || lens.height_px % 2 != 0)
      throw CLI::ValidationError("--size", "a video needs an even width and height");
  } else {
    check_frames_dir(a.frames_dir, a.force);
  }
  TerminalDiagnostics diagnostics(a.verbose);

  const TerrainSources sources = open_terrain_sources(a.terrain, diagnostics);
  scene::TerrainView terrain(sources.heights.get(), sources.imagery.get());
  // Every frame waits for its tiles: a film never shows missing terrain.
  terrain.set_policy({true, std::chrono::milliseconds(static_cast<long long>(a.timeout_s * 1000.0)),
                      [&diagnostics](const terrain::LoadProgress& p) { diagnostics.progress(tiles_status(p)); }});
  SceneTracks loaded = load_scene_tracks(a.tracks, a.read, style.tracks, {sources.heights.get(), 0.0, a.analysis},
                                         diagnostics, a.waypoints);
  if (sources.heights)  // the markers' stems reach down to the ground
    for (scene::Track& t : loaded.tracks.tracks()) scene::set_ground_heights(t, *sources.heights);
  const double neutral_ground = loaded.recorded.lowest_or_sea_level();
  // The task's cylinders (--task) and the airspaces of --airspace, as `render` draws them; a film
  // always has tracks, so the region never comes from the camera.
  scene::VolumeSet volumes = loaded.volumes;
  add_airspace_volumes(volumes, a.airspace.files, airspace_region(loaded.tracks, loaded.waypoints, CameraRequest{}),
                       sources.heights.get(), diagnostics);

  const FilmClock clock = plan_film_clock(a, loaded.tracks);
  const std::vector<scene::Camera> cameras =
      plan_film_cameras(a, mode, lens, clock, loaded.tracks, neutral_ground, sources.heights.get());
  scene::FilmTracks film(loaded.tracks, loaded.waypoints, trail, neutral_ground);
  film.set_clock_offsets(clock.offsets);

  scene::Scene scene;
  scene.terrain = &terrain;
  if (!volumes.volumes.empty()) scene.volumes = &volumes;
  scene.style = style;
  scene.color_range = scene::color_range(loaded.tracks, style);
  scene.sun_time_unix_s = sun_time(sun, loaded.recorded);
  scene.neutral_ground_m = loaded.recorded.lowest_m;

  // The legend lists the tracks, not their trails and ghosted futures.
  scene::Scene legend_scene = scene;
  legend_scene.tracks = &loaded.tracks;

  // The gauges: of the followed track, else of every recorded track with times.
  std::vector<std::size_t> gauged;
  for (std::size_t i = 0; i < loaded.tracks.size(); ++i) {
    const scene::Track& t = loaded.tracks[i];
    const bool followed = static_cast<int>(i) + 1 == a.follow;
    if (mode == FilmCameraMode::follow ? followed : (!t.is_route && t.start_time())) gauged.push_back(i);
  }
  scene::TextRasterizer text;
  // The map data's credits, as the sources give them.
  std::string attribution;
  for (const std::string& credit : {sources.heights ? sources.heights->info().attribution : std::string(),
                                    sources.imagery ? sources.imagery->info().attribution : std::string()})
    if (!credit.empty() && attribution.find(credit) == std::string::npos)
      attribution += (attribution.empty() ? "" : " | ") + credit;
  // The mini profile (full overlay): the first gauged track's, over the part filmed.
  scene::FilmProfile profile;
  if (overlay == scene::OverlayLevel::full && !gauged.empty()) {
    const std::size_t k = gauged.front();
    const scene::TimeSpan own{clock.timing.span.start + clock.offsets[k], clock.timing.span.end + clock.offsets[k]};
    profile =
        scene::film_profile(loaded.tracks[k], own, scene::film_profile_panel(lens.width_px, lens.height_px).width - 8);
  }

  render::GlContext gl = render::GlContext::create_headless();
  for (const std::string& line : gl.describe()) diagnostics.note(line);
  render::Renderer renderer;
  render::ImageTarget picture;
  picture.pixel_ratio = a.pixel_ratio;
  const std::size_t frames = clock.timing.frames;
  diagnostics.note(
      fmt::format("film: {} frames at {} fps, replay {:.1f}x", frames, clock.timing.fps, clock.timing.speed()));

  std::unique_ptr<FilmWriter> writer =
      a.output.empty() ? open_frames_folder(a.frames_dir)
                       : open_video_file(a.output, {lens.width_px, lens.height_px, clock.timing.fps, a.crf});
  const auto started = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < frames; ++i) {
    if (interrupted != 0) {
      writer.reset();  // removes the temporary file
      diagnostics.progress_done();
      diagnostics.error(fmt::format("interrupted after {} of {} frames: {} not written", i, frames,
                                    a.output.empty() ? "the film" : a.output));
      return 130;
    }
    const double time = clock.timing.time_of(i);
    film.set_time(time);
    scene.tracks = &film.tracks();
    scene.waypoints = &film.waypoints();
    std::vector<scene::GaugeReadings> gauges;
    for (std::size_t k : gauged) gauges.push_back(scene::gauge_readings(loaded.tracks[k], film.positions()[k]));
    scene.label_keep_out =
        scene::film_overlay_panels(lens.width_px, lens.height_px, text, overlay, gauges, attribution);
    if (!profile.altitude_m.empty())
      scene.label_keep_out.push_back(scene::film_profile_panel(lens.width_px, lens.height_px));
    prefetch_tiles(terrain, cameras[std::min(frames - 1, i + kPrefetchFrames)], scene.neutral_ground_m);
    renderer.draw(scene, cameras[i], picture);
    scene::draw_scene_legend(picture.image, legend_scene);
    scene::draw_film_overlay(picture.image, text, overlay, time, gauges, attribution);
    if (!gauged.empty()) scene::draw_film_profile(picture.image, profile, time + clock.offsets[gauged.front()]);
    writer->add(picture.image);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const double rate = static_cast<double>(i + 1) / std::max(elapsed, 1e-9);
    diagnostics.progress(fmt::format("frame {}/{}  {:.2f} fps  {} left", i + 1, frames, rate,
                                     clock_text(static_cast<double>(frames - i - 1) / rate)));
  }
  writer->finish();
  diagnostics.progress_done();
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  diagnostics.info(fmt::format("wrote {} ({} frames {}x{} at {} fps, {:.1f} s of film; {:.2f} frames/s)",
                               a.output.empty() ? a.frames_dir : a.output, frames, lens.width_px, lens.height_px,
                               clock.timing.fps, clock.timing.film_seconds(), static_cast<double>(frames) / elapsed));
  return 0;
}

}  // namespace

void add_video_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<VideoArgs>();
  CLI::App* cmd = app.add_subcommand("video", "A film of tracks replayed on the terrain: MP4, WebM or PNG frames");
  add_video_options(*cmd, *args);
  cmd->callback([args, &exit_code] {
    args->tracks = expand_track_arguments(args->tracks);
    exit_code = run_video(*args);
  });
}

}  // namespace trailray::app
