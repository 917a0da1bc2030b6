#include "app/video/video_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "app/common/interrupt_guard.hpp"
#include "app/common/output_file.hpp"
#include "app/common/terminal_diagnostics.hpp"
#include "app/common/track_arguments.hpp"
#include "app/drawing/photo_drawing.hpp"
#include "app/drawing/scene_setup.hpp"
#include "app/options/airspace_options.hpp"
#include "app/pictures/render_report.hpp"
#include "app/video/film_recorder.hpp"
#include "app/video/film_writer.hpp"
#include "app/video/video_options.hpp"
#include "render/platform/gl_context.hpp"
#include "render/renderer.hpp"
#include "scene/pins/photo_decode.hpp"
#include "scene/terrain_view.hpp"

namespace trailray::app {
namespace {

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
    auto parsed = scene::parse_overlay_level(a.gauges);
    if (!parsed.ok()) throw CLI::ValidationError("--gauges", parsed.error);
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
  scene::TerrainView terrain(sources.drawn(), sources.imagery.get());
  scene::TrackBuildOptions build{sources.heights.get(), 0.0, a.track_options.analysis};
  build.surface = sources.surface.get();
  SceneTracks loaded = load_scene_tracks(a.tracks, a.track_options.read, style.tracks, build, diagnostics, a.waypoints);
  sources.cut_canopy(loaded.tracks);
  if (sources.heights)  // the markers' stems reach down to the ground
    for (scene::Track& t : loaded.tracks.tracks()) scene::set_ground_heights(t, *sources.heights);
  const double neutral_ground = loaded.recorded.lowest_or_sea_level();
  // --photos: pins with thumbnails, and the film stops at each (--photo-seconds).
  const ScenePhotos photos =
      add_scene_photos(a.photos, loaded.tracks, loaded.waypoints, {sources.heights.get(), neutral_ground}, diagnostics);
  // The task's cylinders (--task) and the airspaces of --airspace, as `render` draws them; a film
  // always has tracks, so the region never comes from the camera.
  scene::VolumeSet volumes = loaded.volumes;
  add_airspace_volumes(volumes, a.airspace.files, airspace_region(loaded.tracks, loaded.waypoints, CameraRequest{}),
                       sources.heights.get(), diagnostics);

  const FilmClock clock = plan_film_clock(a, loaded.tracks);
  FilmSetup setup;
  setup.tracks = &loaded.tracks;
  setup.waypoints = &loaded.waypoints;
  setup.volumes = &volumes;
  setup.terrain = &terrain;
  // Every frame waits for its tiles: a film never shows missing terrain.
  setup.tiles = {true, timeout_of(a),
                 [&diagnostics](const terrain::LoadProgress& p) { diagnostics.progress(tiles_status(p)); }};
  setup.style = style;
  setup.color_range = scene::color_range(loaded.tracks, style);
  setup.overlay_legend = sources.overlay_legend;
  setup.sun_time_unix_s = sun_time(sun, loaded.recorded);
  setup.neutral_ground_m = loaded.recorded.lowest_m;
  setup.marker_ground_m = neutral_ground;
  setup.trail = trail;
  setup.overlay = overlay;
  setup.cameras = plan_film_cameras(a, mode, lens, clock, loaded.tracks, neutral_ground, sources.heights.get());
  setup.clock = clock;
  // The gauges: of the followed track, else of every recorded track with times.
  setup.gauged = gauged_tracks(loaded.tracks, mode, a.follow);
  setup.attribution = map_attribution(sources);
  setup.pixel_ratio = a.pixel_ratio;
  if (!photos.placed.empty() && a.photo_seconds > 0.0) {
    // Each photo shown large, decoded again at the size it is shown; its time on the film's clock
    // (a track's time is the clock's plus its offset, --align start).
    const int long_side = static_cast<int>(std::max(lens.width_px, lens.height_px) * 0.8);
    const std::optional<int> zone = photo_placement_options(a.photos).default_offset_s;
    std::vector<double> times;
    for (const track::PlacedPhoto& p : photos.placed) {
      std::shared_ptr<const scene::PhotoImage> large;
      try {
        large = scene::make_photo_image(scene::decode_photo(p.photo.path, long_side, p.photo.orientation));
      } catch (const scene::PhotoDecodeError&) {
        // Warned about with its thumbnail: no pause shows it.
      }
      setup.photos.push_back({large, photo_caption(p, zone)});
      times.push_back(large ? p.time_unix_s - clock.offsets.at(p.track) : track::kMissing);
    }
    setup.frames = scene::film_frames_with_photos(clock.timing, times, a.photo_seconds);
  }

  render::GlContext gl = render::GlContext::create_headless();
  for (const std::string& line : gl.describe()) diagnostics.note(line);
  render::Renderer renderer;
  const std::size_t frames = setup.frame_count();
  diagnostics.note(fmt::format("film: {} frames at {} fps, replay {:.1f}x ({} frames of stops at photos)", frames,
                               clock.timing.fps, clock.timing.speed(), frames - clock.timing.frames));

  FilmRecorder recorder(std::move(setup), a.output.empty() ? open_frames_folder(a.frames_dir)
                                                           : open_video_file(a.output, {lens.width_px, lens.height_px,
                                                                                        clock.timing.fps, a.crf}));
  const auto started = std::chrono::steady_clock::now();
  while (!recorder.done()) {
    if (interrupt_requested()) {
      recorder.cancel();  // removes the temporary file
      diagnostics.progress_done();
      diagnostics.error(fmt::format("interrupted after {} of {} frames: {} not written", recorder.progress().done,
                                    frames, a.output.empty() ? "the film" : a.output));
      return 130;
    }
    recorder.draw_next(renderer);
    diagnostics.progress(film_progress_text(recorder.progress()));
  }
  recorder.finish();
  diagnostics.progress_done();
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  diagnostics.info(fmt::format("wrote {} ({} frames {}x{} at {} fps, {:.1f} s of film; {:.2f} frames/s)",
                               a.output.empty() ? a.frames_dir : a.output, frames, lens.width_px, lens.height_px,
                               clock.timing.fps, static_cast<double>(frames) / clock.timing.fps,
                               static_cast<double>(frames) / elapsed));
  return 0;
}

}  // namespace

void add_video_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<VideoArgs>();
  CLI::App* cmd = app.add_subcommand("video", "A film of tracks replayed on the terrain: MP4, WebM or PNG frames");
  add_video_options(*cmd, *args);
  cmd->callback([args, &exit_code] {
    args->tracks = expand_track_arguments(args->tracks);
    // --overlay none|minimal|full was the gauges' option before the map overlay took the name.
    const std::string& o = args->terrain.overlay;
    if (o == "none" || o == "minimal" || o == "full") {
      fmt::print(stderr, "trailray: warning: video --overlay {} is now --gauges {} (--overlay draws a heatmap or "
                         "other imagery over the ground)\n", o, o);
      args->gauges = o;
      args->terrain.overlay.clear();
    }
    exit_code = run_video(*args);
  });
}

}  // namespace trailray::app
