#include "app/render_command.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "app/scene_inputs.hpp"
#include "app/terrain_options.hpp"
#include "app/track_options.hpp"
#include "app/track_legend.hpp"
#include "app/track_scene.hpp"
#include "app/track_style_options.hpp"
#include "scene/camera.hpp"
#include "render/gl/frame_profiler.hpp"
#include "scene/rgba_image.hpp"
#include "scene/framing.hpp"
#include "render/gl/gl_capabilities.hpp"
#include "render/platform/gl_context.hpp"
#include "render/scene_renderer.hpp"
#include "scene/sun_position.hpp"
#include "terrain/height_sampler.hpp"
#include "terrain/source_factory.hpp"
#include "track/diagnostics.hpp"
#include "track/io/load.hpp"
#include "track/io/parse_util.hpp"

namespace trailray::app {
namespace {

constexpr std::uint32_t kMaxImageSide = 16384;
constexpr int kMaxProfiledFrames = 10000;

struct RenderArgs {
  std::vector<std::string> tracks;
  std::string output;
  std::string size = "1920x1080";
  CameraArgs camera;
  EffectArgs effects;
  double timeout_s = 120.0;
  bool verbose = false;
  bool profile = false;
  int frames = 1;
  track::ReadOptions read;
  track::AnalysisOptions analysis;
  TrackStyleArgs style;
  TerrainOptions terrain;
};

void warn(const std::string& message) { fmt::print(stderr, "trailray: warning: {}\n", message); }

int run_render(const RenderArgs& a) {
  const auto size = parse_image_size(a.size);
  if (!size)
    throw CLI::ValidationError(
        "--size", fmt::format("'{}' is not WxH with W and H in 1..{}, e.g. 1920x1080", a.size, kMaxImageSide));
  scene::Lens lens{a.camera.fov_deg, size->width, size->height};
  if (auto problem = scene::lens_problem(lens)) throw CLI::ValidationError("--fov/--size", *problem);
  const CameraRequest camera_request = parse_camera_request(a.camera, !a.tracks.empty());
  if (a.frames < 1 || a.frames > kMaxProfiledFrames)
    throw CLI::ValidationError("--frames",
                               fmt::format("'{}' is not a frame count in 1..{}", a.frames, kMaxProfiledFrames));
  if (a.frames > 1 && !a.profile) throw CLI::ValidationError("--frames", "goes with --profile");
  if (!(a.timeout_s > 0.0) || !std::isfinite(a.timeout_s))
    throw CLI::ValidationError("--timeout", fmt::format("'{}' is not a positive number of seconds", a.timeout_s));

  const TrackStyle style = parse_track_style(a.style);
  const TrackPoints tracks = load_track_points(a.tracks, a.read, warn);
  const double unix_time = sun_time(a.effects.time, tracks);

  const TerrainSources sources = open_terrain_sources(a.terrain, warn);
  terrain::HeightSource* const heights = sources.heights.get();
  // The neutral ground's height: the tracks' lowest point (DESIGN.md), else the lowest terrain in
  // view (NaN asks the renderer for it).
  const double neutral = lowest_height(tracks.points);
  // The tracks: cleaned and coloured (their range sets the legend's labels, hence its size).
  const TrackScene track_scene =
      build_track_scene(tracks.files, style, {heights, std::isnan(neutral) ? 0.0 : neutral, a.analysis}, warn);
  // The camera: framed with the tracks out of the legend's way.
  const scene::KeptClearCorner legend_corner =
      legend_clearance(scene_legend_panel(lens.width_px, lens.height_px, style, track_scene), lens.height_px);
  const std::optional<scene::Camera> camera = initial_camera(camera_request, lens, tracks, heights, legend_corner);

  render::GlContext gl = render::GlContext::create_headless();
  if (a.verbose)
    for (const std::string& line : gl.describe()) fmt::print(stderr, "trailray: {}\n", line);
  render::SceneRenderer renderer({heights, sources.imagery.get()});
  render::SceneRenderOptions options;
  // The tracks on the GPU (their buffers live as long as the renderer's use).
  std::vector<render::TrackBuffer> track_buffers;
  track_buffers.reserve(track_scene.tracks.size());
  for (const SceneTrack& t : track_scene.tracks) track_buffers.emplace_back(t.geometry);
  for (std::size_t i = 0; i < track_buffers.size(); ++i)
    options.tracks.push_back({&track_buffers[i], track_scene.tracks[i].color_srgb, track_scene.range.has_value()});
  options.track_settings = style.settings;
  if (track_scene.range) {
    options.track_settings.value_min = static_cast<float>(track_scene.range->min);
    options.track_settings.value_max = static_cast<float>(track_scene.range->max);
  }
  options.sun_direction_ecef = scene::sun_direction_ecef(unix_time);
  options.neutral_ground_height_m = neutral;
  options.timeout = std::chrono::milliseconds(static_cast<long long>(a.timeout_s * 1000.0));
  options.ssao = !a.effects.no_ssao;
  options.atmosphere = !a.effects.no_atmosphere;
  options.shadows = !a.effects.no_shadows;
  options.snow = {a.effects.snow, a.effects.snowline_m};
  const bool progress = isatty(STDERR_FILENO) != 0;
  if (progress)
    options.on_progress = [](const terrain::LoadProgress& p) {
      fmt::print(stderr, "\rtiles: {}/{} loaded{}\x1b[K", p.loaded + p.no_data, p.wanted,
                 p.failed ? fmt::format(", {} failed", p.failed) : "");
    };
  render::RenderedScene scene = renderer.render(*camera, options);
  if (progress) fmt::print(stderr, "\r\x1b[K");
  if (a.profile) {
    // The first render waited for the tiles; these frames find them loaded and time the passes.
    render::FrameProfiler profiler(render::query_gl_capabilities(), static_cast<std::size_t>(a.frames));
    options.profiler = &profiler;
    for (int frame = 0; frame < a.frames; ++frame) scene = renderer.render(*camera, options);
    profiler.finish();
    fmt::print(stderr, "{}", profiler.table());
  }

  const render::SceneRenderReport& r = scene.report;
  if (r.timed_out)
    warn(fmt::format("tiles still loading after --timeout {} s: drawn with what had arrived", a.timeout_s));
  if (!r.failures.empty())
    warn(fmt::format("{} tile{} failed; first: {}", r.failures.size(), r.failures.size() == 1 ? "" : "s",
                     r.failures.front()));
  if (r.tiles_with_data == 0)
    warn(fmt::format("no terrain source covers the view ({}): drawing a neutral ground at {:.0f} m",
                     heights ? heights->info().name : std::string("--terrain none"), r.neutral_ground_height_m));
  const scene::SolarPosition sun =
      scene::solar_position(unix_time, camera->geodetic().lat_deg, camera->geodetic().lon_deg);
  if (sun.elevation_deg < 0.0)
    warn(fmt::format("the sun is below the horizon ({:.1f} degrees) at that time", sun.elevation_deg));
  if (a.verbose) {
    const auto& g = camera->geodetic();
    fmt::print(
        stderr,
        "trailray: camera {:.6f},{:.6f},{:.0f} m heading {:.1f} pitch {:.1f}, sun azimuth {:.1f} elevation {:.1f}\n",
        g.lat_deg, g.lon_deg, g.height_m, camera->heading_deg(), camera->pitch_deg(), sun.azimuth_deg,
        sun.elevation_deg);
    fmt::print(stderr, "trailray: {} tiles drawn ({} with terrain, {} with imagery), {} selection rounds\n",
               r.tiles_drawn, r.tiles_with_data, r.imagery_tiles_used, r.selection_rounds);
    constexpr double kMiB = 1024.0 * 1024.0;
    fmt::print(stderr, "trailray: GPU memory for terrain: meshes {:.1f} MiB ({} tiles), imagery {:.1f} MiB ({} tiles)\n",
               static_cast<double>(r.gpu_meshes.bytes) / kMiB, r.gpu_meshes.entries,
               static_cast<double>(r.gpu_imagery.bytes) / kMiB, r.gpu_imagery.entries);
  }
  draw_scene_legend(scene.image, style, track_scene);
  scene::write_srgb_png(a.output, scene.image);
  if (a.verbose) fmt::print(stderr, "trailray: wrote {} ({}x{})\n", a.output, scene.image.width, scene.image.height);
  return 0;
}

}  // namespace

std::optional<ImageSize> parse_image_size(std::string_view text) {
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string_view::npos) return std::nullopt;
  const auto number = [](std::string_view s) -> std::optional<std::uint32_t> {
    std::uint32_t v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || end != s.data() + s.size() || v == 0 || v > kMaxImageSide)
      return std::nullopt;
    return v;
  };
  const auto w = number(text.substr(0, x)), h = number(text.substr(x + 1));
  if (!w || !h) return std::nullopt;
  return ImageSize{*w, *h};
}

void add_render_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "A picture of tracks on the terrain, or of the terrain from a camera, as a PNG");
  cmd->footer(
      "Without tracks a camera is needed (--camera or --look-at). Heading 0 looks north, pitch 0 is\n"
      "horizontal, negative looks down. The sun stands where it was at --time (default: local solar noon\n"
      "on the track's first day, today's for tracks without times, now without tracks). Where no source\n"
      "covers the view a neutral ground"
      " is drawn at the tracks' lowest point.\n"
      "Exit status: 0 written, 1 a file, source or GL failed, 2 a usage error.");
  cmd->add_option("TRACK", args->tracks, "GPX, IGC or TCX files to draw (the view frames them)")->type_name("FILE");
  cmd->add_option("-o,--output", args->output, "The PNG to write (atomically)")->required()->type_name("OUT.png");
  cmd->add_option("--size", args->size, "Image size in pixels (default 1920x1080)")->type_name("WxH");
  add_camera_options(*cmd, args->camera);
  cmd->add_option("--timeout", args->timeout_s, "Seconds to wait for terrain tiles (default 120)")->type_name("S");
  cmd->add_flag("--verbose", args->verbose, "Log the GL context, camera, sun and tiles");
  add_effect_options(*cmd, args->effects);
  cmd->add_flag("--profile", args->profile,
                "After the tiles are loaded, render --frames times and print CPU and GPU time per pass to "
                "standard error");
  cmd->add_option("--frames", args->frames, "With --profile: frames to render and average (default 1)")->type_name("N");
  add_terrain_options(*cmd, args->terrain);
  add_imagery_option(*cmd, args->terrain);
  add_track_style_options(*cmd, args->style);
  add_read_options(*cmd, args->read);
  add_cleaning_options(*cmd, args->analysis);
  cmd->callback([args, &exit_code] { exit_code = run_render(*args); });
}

}  // namespace trailray::app
