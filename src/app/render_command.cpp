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

#include "app/terrain_options.hpp"
#include "app/track_options.hpp"
#include "app/track_legend.hpp"
#include "app/track_scene.hpp"
#include "app/track_style_options.hpp"
#include "render/camera.hpp"
#include "render/frame_profiler.hpp"
#include "render/framebuffer_readback.hpp"
#include "render/framing.hpp"
#include "render/gl_capabilities.hpp"
#include "render/gl_context.hpp"
#include "render/scene_renderer.hpp"
#include "render/sun_position.hpp"
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
  std::string camera, look_at;
  std::optional<double> distance_m, heading_deg, pitch_deg;
  double fov_deg = render::kDefaultVerticalFovDeg;
  std::string time;
  double timeout_s = 120.0;
  bool verbose = false;
  bool no_ssao = false, no_atmosphere = false, no_shadows = false, snow = false;
  double snowline_m = 2500.0;
  bool profile = false;
  int frames = 1;
  track::ReadOptions read;
  track::AnalysisOptions analysis;
  TrackStyleArgs style;
  TerrainOptions terrain;
};

void warn(const std::string& message) { fmt::print(stderr, "trailray: warning: {}\n", message); }

// Every recorded point of the tracks (track and route points), and the first timestamp.
struct TrackPoints {
  std::vector<LoadedTrackFile> files;
  std::vector<render::GeoPosition> points;
  std::optional<double> first_time_s;
  double first_lon_deg = 0.0;              // of the first timed point
  std::optional<double> any_lon_deg;       // of the first point at all
};

TrackPoints load_tracks(const RenderArgs& a) {
  TrackPoints out;
  for (const std::string& path : a.tracks) {
    track::ReadResult read = track::load_track_file(path, a.read);
    for (const auto& w : read.warnings) warn(w.to_string());
    if (read.error) throw std::runtime_error(read.error->to_string());
    const auto add = [&](const track::TrackPoint& p) {
      out.points.push_back({p.lat, p.lon, p.has_ele() ? p.ele : std::numeric_limits<double>::quiet_NaN()});
      if (!out.any_lon_deg) out.any_lon_deg = p.lon;
      if (!out.first_time_s && !std::isnan(p.time)) {
        out.first_time_s = p.time;
        out.first_lon_deg = p.lon;
      }
    };
    for (const auto& t : read.file.tracks)
      for (const auto& s : t.segments)
        for (const auto& p : s.points) add(p);
    for (const auto& r : read.file.routes)
      for (const auto& p : r.points) add(p);
    std::size_t points = 0;
    for (const auto& t : read.file.tracks) points += t.point_count();
    for (const auto& r : read.file.routes) points += r.points.size();
    if (points == 0) throw std::runtime_error(path + ": has no track or route points to draw");
    out.files.push_back({path, std::move(read.file)});
  }
  return out;
}

// The terrain height at a place, from the source (NaN where it has none, or without a source).
double ground_height_at(terrain::HeightSource* source, double lat, double lon) {
  if (source == nullptr) return std::numeric_limits<double>::quiet_NaN();
  terrain::HeightSampler sampler(*source);
  return sampler.sample(lat, lon);
}

double lowest_height(const std::vector<render::GeoPosition>& points) {
  double lowest = std::numeric_limits<double>::quiet_NaN();
  for (const auto& p : points)
    if (!std::isnan(p.height_m) && !(p.height_m >= lowest)) lowest = p.height_m;
  return lowest;
}

double sun_time(const RenderArgs& a, const TrackPoints& tracks) {
  if (!a.time.empty()) {
    const auto t = track::parse_iso8601(a.time);
    if (!t)
      throw CLI::ValidationError("--time",
                                 "'" + a.time + "' is not an ISO 8601 date and time, e.g. 2024-06-18T12:00:00Z");
    return *t;
  }
  if (tracks.first_time_s) return render::solar_noon_utc(*tracks.first_time_s, tracks.first_lon_deg);
  const double now = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  // Tracks without times (planned routes): today's noon there, not the dark of "now" at night.
  if (tracks.any_lon_deg) return render::solar_noon_utc(now, *tracks.any_lon_deg);
  return now;
}

int run_render(const RenderArgs& a) {
  const auto size = parse_image_size(a.size);
  if (!size)
    throw CLI::ValidationError(
        "--size", fmt::format("'{}' is not WxH with W and H in 1..{}, e.g. 1920x1080", a.size, kMaxImageSide));
  render::Lens lens{a.fov_deg, size->width, size->height};
  if (auto problem = render::lens_problem(lens)) throw CLI::ValidationError("--fov/--size", *problem);
  if (!a.camera.empty() && !a.look_at.empty())
    throw CLI::ValidationError("--camera", "and --look-at exclude each other");
  if (a.look_at.empty() && (a.distance_m || a.heading_deg || a.pitch_deg))
    throw CLI::ValidationError("--distance/--heading/--pitch", "go with --look-at LAT,LON,ALT");
  if (a.tracks.empty() && a.camera.empty() && a.look_at.empty())
    throw CLI::ValidationError(
        "camera",
        "without a track, say where to look from: --camera LAT,LON,ALT,HEADING,PITCH or --look-at LAT,LON,ALT "
        "[--distance M --heading DEG --pitch DEG]");
  if (a.frames < 1 || a.frames > kMaxProfiledFrames)
    throw CLI::ValidationError("--frames",
                               fmt::format("'{}' is not a frame count in 1..{}", a.frames, kMaxProfiledFrames));
  if (a.frames > 1 && !a.profile) throw CLI::ValidationError("--frames", "goes with --profile");
  if (!(a.timeout_s > 0.0) || !std::isfinite(a.timeout_s))
    throw CLI::ValidationError("--timeout", fmt::format("'{}' is not a positive number of seconds", a.timeout_s));
  std::optional<render::CameraPlacement> placement;
  std::optional<render::LookAt> look_at;
  if (!a.camera.empty()) {
    auto parsed = render::parse_camera_option(a.camera);
    if (!parsed.ok()) throw CLI::ValidationError(parsed.error);  // it names the option
    placement = *parsed.value;
  } else if (!a.look_at.empty()) {
    auto parsed = render::parse_look_at_option(a.look_at);
    if (!parsed.ok()) throw CLI::ValidationError(parsed.error);
    look_at = render::LookAt{*parsed.value};
    if (a.distance_m) look_at->distance_m = *a.distance_m;
    if (a.heading_deg) look_at->heading_deg = *a.heading_deg;
    if (a.pitch_deg) look_at->pitch_deg = *a.pitch_deg;
  }

  const TrackStyle style = parse_track_style(a.style);
  const TrackPoints tracks = load_tracks(a);
  const double unix_time = sun_time(a, tracks);

  const terrain::TerrainConfig config = resolve_terrain_config(a.terrain);
  terrain::SourceContext context{config.network, config.cache, [](std::string w) { warn("terrain: " + w); }};
  terrain::SourceSettings height_settings = config.terrain;
  if (a.terrain.terrain_zoom) height_settings.max_zoom = *a.terrain.terrain_zoom;
  std::unique_ptr<terrain::HeightSource> heights = terrain::open_height_source(height_settings, context);
  // Imagery from --imagery, else the config file's, else the built-in default (README); `none`
  // gives the hypsometric tint, which shows the relief best. Tiles it cannot deliver (offline,
  // unreachable) are tinted too, after one warning.
  std::unique_ptr<terrain::ImagerySource> imagery = terrain::open_imagery_source(config.imagery, context);

  // The camera, and the neutral ground's height: the tracks' lowest point (DESIGN.md), else the
  // lowest terrain in view (NaN asks the renderer for it).
  double neutral = lowest_height(tracks.points);
  std::optional<render::Camera> camera;
  if (placement || look_at) {
    const render::GeoPosition& where = placement ? placement->position : look_at->target;
    double ground = ground_height_at(heights.get(), where.lat_deg, where.lon_deg);
    if (std::isnan(ground)) ground = std::isnan(neutral) ? 0.0 : neutral;
    auto made =
        placement ? render::camera_at(*placement, lens, ground) : render::camera_looking_at(*look_at, lens, ground);
    if (!made.ok()) throw CLI::ValidationError(placement ? "--camera" : "--look-at", made.error);
    camera = std::move(*made.value);
  } else {
    render::FramingOptions framing;
    framing.lens = lens;
    auto framed = render::frame_points(tracks.points, framing);
    if (!framed.ok()) throw std::runtime_error("cannot frame the tracks: " + framed.error);
    camera = framed.value->camera;
  }

  render::GlContext gl = render::GlContext::create_headless();
  if (a.verbose)
    for (const std::string& line : gl.describe()) fmt::print(stderr, "trailray: {}\n", line);
  render::SceneRenderer renderer({heights.get(), imagery.get()});
  render::SceneRenderOptions options;
  // The tracks: cleaned, coloured, on the GPU (their buffers live as long as the renderer's use).
  const TrackScene track_scene = build_track_scene(
      tracks.files, style, {heights.get(), std::isnan(neutral) ? 0.0 : neutral, a.analysis}, warn);
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
  options.sun_direction_ecef = render::sun_direction_ecef(unix_time);
  options.neutral_ground_height_m = neutral;
  options.timeout = std::chrono::milliseconds(static_cast<long long>(a.timeout_s * 1000.0));
  options.ssao = !a.no_ssao;
  options.atmosphere = !a.no_atmosphere;
  options.shadows = !a.no_shadows;
  options.snow = {a.snow, a.snowline_m};
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
  const render::SolarPosition sun =
      render::solar_position(unix_time, camera->geodetic().lat_deg, camera->geodetic().lon_deg);
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
  }
  draw_scene_legend(scene.image, style, track_scene);
  render::write_srgb_png(a.output, scene.image);
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
  cmd->add_option("--camera", args->camera, "Camera position and orientation (degrees, metres)")
      ->type_name("LAT,LON,ALT,HEADING,PITCH");
  cmd->add_option("--look-at", args->look_at, "Look at this point (degrees, metres)")->type_name("LAT,LON,ALT");
  cmd->add_option("--distance", args->distance_m,
                  "With --look-at: camera distance from the point, metres (default 1000)")
      ->type_name("M");
  cmd->add_option("--heading", args->heading_deg, "With --look-at: degrees clockwise from north (default 0)")
      ->type_name("DEG");
  cmd->add_option("--pitch", args->pitch_deg, "With --look-at: degrees, negative looks down (default -45)")
      ->type_name("DEG");
  cmd->add_option("--fov", args->fov_deg, "Vertical field of view, degrees (default 45)")->type_name("DEG");
  cmd->add_option("--time", args->time, "Date and time for the sun, ISO 8601 (e.g. 2024-06-18T12:00:00Z)")
      ->type_name("ISO8601");
  cmd->add_option("--timeout", args->timeout_s, "Seconds to wait for terrain tiles (default 120)")->type_name("S");
  cmd->add_flag("--verbose", args->verbose, "Log the GL context, camera, sun and tiles");
  cmd->add_flag("--no-ssao", args->no_ssao, "No ambient occlusion (valleys and hollows not darkened)");
  cmd->add_flag("--no-atmosphere", args->no_atmosphere, "No aerial perspective or sky gradient (no haze, a flat sky)");
  cmd->add_flag("--no-shadows", args->no_shadows, "No cast shadows (slopes still shaded by their angle to the sun)");
  cmd->add_flag("--snow", args->snow,
                "Snow cover: white from the snowline up, on slopes under about 40-50 degrees (rock faces stay bare)");
  cmd->add_option("--snowline", args->snowline_m, "Altitude of the snowline for --snow, metres (default 2500)")
      ->check(CLI::Range(-500.0, 9000.0))
      ->type_name("M");
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
