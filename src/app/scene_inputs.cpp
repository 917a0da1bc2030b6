#include "app/scene_inputs.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "scene/framing.hpp"
#include "scene/sun_position.hpp"
#include "terrain/height_sampler.hpp"
#include "terrain/source_factory.hpp"
#include "track/io/parse_util.hpp"

namespace trailray::app {

void add_camera_options(CLI::App& cmd, CameraArgs& args) {
  cmd.add_option("--camera", args.camera, "Camera position and orientation (degrees, metres)")
      ->type_name("LAT,LON,ALT,HEADING,PITCH");
  cmd.add_option("--look-at", args.look_at, "Look at this point (degrees, metres)")->type_name("LAT,LON,ALT");
  cmd.add_option("--distance", args.distance_m, "With --look-at: camera distance from the point, metres (default 1000)")
      ->type_name("M");
  cmd.add_option("--heading", args.heading_deg, "With --look-at: degrees clockwise from north (default 0)")
      ->type_name("DEG");
  cmd.add_option("--pitch", args.pitch_deg, "With --look-at: degrees, negative looks down (default -45)")
      ->type_name("DEG");
  cmd.add_option("--fov", args.fov_deg, "Vertical field of view, degrees (default 45)")->type_name("DEG");
}

void add_effect_options(CLI::App& cmd, EffectArgs& args) {
  cmd.add_option("--time", args.time, "Date and time for the sun, ISO 8601 (e.g. 2024-06-18T12:00:00Z)")
      ->type_name("ISO8601");
  cmd.add_flag("--no-ssao", args.no_ssao, "No ambient occlusion (valleys and hollows not darkened)");
  cmd.add_flag("--no-atmosphere", args.no_atmosphere, "No aerial perspective or sky gradient (no haze, a flat sky)");
  cmd.add_flag("--no-shadows", args.no_shadows, "No cast shadows (slopes still shaded by their angle to the sun)");
  cmd.add_flag("--snow", args.snow,
               "Snow cover: white from the snowline up, on slopes under about 40-50 degrees (rock faces stay bare)");
  cmd.add_option("--snowline", args.snowline_m, "Altitude of the snowline for --snow, metres (default 2500)")
      ->check(CLI::Range(-500.0, 9000.0))
      ->type_name("M");
}

CameraRequest parse_camera_request(const CameraArgs& a, bool have_tracks) {
  if (!a.camera.empty() && !a.look_at.empty())
    throw CLI::ValidationError("--camera", "and --look-at exclude each other");
  if (a.look_at.empty() && (a.distance_m || a.heading_deg || a.pitch_deg))
    throw CLI::ValidationError("--distance/--heading/--pitch", "go with --look-at LAT,LON,ALT");
  if (!have_tracks && a.camera.empty() && a.look_at.empty())
    throw CLI::ValidationError(
        "camera",
        "without a track, say where to look from: --camera LAT,LON,ALT,HEADING,PITCH or --look-at LAT,LON,ALT "
        "[--distance M --heading DEG --pitch DEG]");
  CameraRequest request;
  if (!a.camera.empty()) {
    auto parsed = scene::parse_camera_option(a.camera);
    if (!parsed.ok()) throw CLI::ValidationError(parsed.error);  // it names the option
    request.placement = *parsed.value;
  } else if (!a.look_at.empty()) {
    auto parsed = scene::parse_look_at_option(a.look_at);
    if (!parsed.ok()) throw CLI::ValidationError(parsed.error);
    request.look_at = scene::LookAt{*parsed.value};
    if (a.distance_m) request.look_at->distance_m = *a.distance_m;
    if (a.heading_deg) request.look_at->heading_deg = *a.heading_deg;
    if (a.pitch_deg) request.look_at->pitch_deg = *a.pitch_deg;
  }
  return request;
}

void add_track_points(TrackPoints& out, LoadedTrackFile file) {
  const auto add = [&](const track::TrackPoint& p) {
    out.points.push_back({p.lat, p.lon, p.has_ele() ? p.ele : std::numeric_limits<double>::quiet_NaN()});
    if (!out.any_lon_deg) out.any_lon_deg = p.lon;
    if (!out.first_time_s && !std::isnan(p.time)) {
      out.first_time_s = p.time;
      out.first_lon_deg = p.lon;
    }
  };
  std::size_t points = 0;
  for (const auto& t : file.file.tracks) points += t.point_count();
  for (const auto& r : file.file.routes) points += r.points.size();
  if (points == 0) throw std::runtime_error(file.path + ": has no track or route points to draw");
  for (const auto& t : file.file.tracks)
    for (const auto& s : t.segments)
      for (const auto& p : s.points) add(p);
  for (const auto& r : file.file.routes)
    for (const auto& p : r.points) add(p);
  out.files.push_back(std::move(file));
}

TrackPoints load_track_points(const std::vector<std::string>& paths, const track::ReadOptions& read,
                              const WarnFunction& warn) {
  TrackPoints out;
  for (const std::string& path : paths) {
    track::ReadResult result = track::load_track_file(path, read);
    for (const auto& w : result.warnings) warn(w.to_string());
    if (result.error) throw std::runtime_error(result.error->to_string());
    add_track_points(out, {path, std::move(result.file)});
  }
  return out;
}

double lowest_height(const std::vector<scene::GeoPosition>& points) {
  double lowest = std::numeric_limits<double>::quiet_NaN();
  for (const auto& p : points)
    if (!std::isnan(p.height_m) && !(p.height_m >= lowest)) lowest = p.height_m;
  return lowest;
}

double sun_time(const std::string& time_text, const TrackPoints& tracks) {
  if (!time_text.empty()) {
    const auto t = track::parse_iso8601(time_text);
    if (!t)
      throw CLI::ValidationError("--time",
                                 "'" + time_text + "' is not an ISO 8601 date and time, e.g. 2024-06-18T12:00:00Z");
    return *t;
  }
  if (tracks.first_time_s) return scene::solar_noon_utc(*tracks.first_time_s, tracks.first_lon_deg);
  const double now = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  // Tracks without times (planned routes): today's noon there, not the dark of "now" at night.
  if (tracks.any_lon_deg) return scene::solar_noon_utc(now, *tracks.any_lon_deg);
  return now;
}

TerrainSources open_terrain_sources(const TerrainOptions& options, const WarnFunction& warn) {
  const terrain::TerrainConfig config = resolve_terrain_config(options);
  terrain::SourceContext context{config.network, config.cache, [warn](std::string w) { warn("terrain: " + w); }};
  terrain::SourceSettings height_settings = config.terrain;
  if (options.terrain_zoom) height_settings.max_zoom = *options.terrain_zoom;
  TerrainSources sources;
  sources.heights = terrain::open_height_source(height_settings, context);
  // Imagery from --imagery, else the config file's, else the built-in default (README); `none`
  // gives the hypsometric tint, which shows the relief best. Tiles it cannot deliver (offline,
  // unreachable) are tinted too, after one warning.
  sources.imagery = terrain::open_imagery_source(config.imagery, context);
  return sources;
}

double ground_height_at(terrain::HeightSource* source, double lat, double lon) {
  if (source == nullptr) return std::numeric_limits<double>::quiet_NaN();
  terrain::HeightSampler sampler(*source);
  return sampler.sample(lat, lon);
}

scene::Camera initial_camera(const CameraRequest& request, const scene::Lens& lens, const TrackPoints& tracks,
                              terrain::HeightSource* heights, const scene::KeptClearCorner& keep_clear,
                              const std::optional<scene::ImageArea>& area) {
  // The neutral ground's height: the tracks' lowest point (DESIGN.md), else sea level.
  const double neutral = lowest_height(tracks.points);
  if (request.placement || request.look_at) {
    const scene::GeoPosition& where = request.placement ? request.placement->position : request.look_at->target;
    double ground = ground_height_at(heights, where.lat_deg, where.lon_deg);
    if (std::isnan(ground)) ground = std::isnan(neutral) ? 0.0 : neutral;
    auto made = request.placement ? scene::camera_at(*request.placement, lens, ground)
                                  : scene::camera_looking_at(*request.look_at, lens, ground);
    if (!made.ok()) throw CLI::ValidationError(request.placement ? "--camera" : "--look-at", made.error);
    return std::move(*made.value);
  }
  scene::FramingOptions framing;
  framing.lens = lens;
  framing.keep_clear = keep_clear;
  framing.area = area;
  auto framed = scene::frame_points(tracks.points, framing);
  if (!framed.ok()) throw std::runtime_error("cannot frame the tracks: " + framed.error);
  return framed.value->camera;
}

}  // namespace trailray::app
