#include "app/drawing/scene_setup.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "app/common/track_reading.hpp"
#include "app/drawing/overlay_source.hpp"
#include "app/options/airspace_options.hpp"
#include "app/options/places_options.hpp"
#include "scene/camera/first_camera.hpp"
#include "scene/pictures/overlaid_imagery.hpp"
#include "scene/pins/place_labels.hpp"
#include "scene/pins/scored_route.hpp"
#include "scene/pins/thermal_markers.hpp"
#include "scene/pins/waypoint_building.hpp"
#include "terrain/height_sampler.hpp"
#include "terrain/sources/source_factory.hpp"
#include "track/scoring/score.hpp"
#include "track/task/task_reader.hpp"

namespace trailray::app {

namespace {

bool is_igc_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".igc";
}

}  // namespace

std::vector<track::places::Place> places_around(const std::string& file, const scene::TrackSet& tracks,
                                                const scene::WaypointSet& waypoints, scene::Diagnostics& diagnostics) {
  // Only the places around what is drawn: a country's extract holds tens of thousands.
  const AirspaceRegion region = airspace_region(tracks, waypoints, CameraRequest{});
  std::vector<track::places::Place> places = read_label_places(file, region.bounds.value_or(geo::LatLonBounds{}));
  diagnostics.note(fmt::format("{} place{} from {}", places.size(), places.size() == 1 ? "" : "s", file));
  return places;
}

std::vector<scene::Waypoint> osm_place_labels(const std::string& file, const scene::TrackSet& tracks,
                                              const scene::WaypointSet& waypoints,
                                              const scene::WaypointBuildOptions& placing,
                                              scene::Diagnostics& diagnostics) {
  return scene::osm_place_waypoints(places_around(file, tracks, waypoints, diagnostics), file, placing);
}

SceneTracks load_scene_tracks(const std::vector<std::string>& paths, const track::ReadOptions& read,
                              const scene::TrackStyle& style, const scene::TrackBuildOptions& options,
                              scene::Diagnostics& diagnostics, const WaypointArgs& waypoints) {
  return build_scene_tracks(read_track_files_parallel(paths, read, diagnostics), paths, read, style, options,
                            diagnostics, waypoints);
}

SceneTracks build_scene_tracks(std::vector<scene::LoadedTrackFile> files, const std::vector<std::string>& paths,
                               const track::ReadOptions& read, const scene::TrackStyle& style,
                               const scene::TrackBuildOptions& options, scene::Diagnostics& diagnostics,
                               const WaypointArgs& waypoints) {
  SceneTracks out;
  out.recorded = scene::recorded_points(files);
  scene::TrackBuildOptions build = options;
  build.neutral_ground_m = out.recorded.lowest_or_sea_level();
  const bool thermals = waypoints.thermals_for(style.color_by);
  build.analyse_flights = build.analyse_flights || thermals;
  for (scene::Track& t : build_tracks_releasing(files, style, build, diagnostics)) out.tracks.add(std::move(t));
  const scene::WaypointBuildOptions placing{options.heights, build.neutral_ground_m};
  out.waypoints.points = scene::file_waypoints(files, placing);
  for (scene::Waypoint& w : scene::read_place_labels(waypoints.label_files, read, placing, diagnostics))
    out.waypoints.points.push_back(std::move(w));
  if (!waypoints.places_file.empty())
    for (scene::Waypoint& w : osm_place_labels(waypoints.places_file, out.tracks, out.waypoints, placing, diagnostics))
      out.waypoints.points.push_back(std::move(w));
  if (waypoints.no_waypoints) scene::set_waypoints_visible(out.waypoints, false);
  // After --no-waypoints: the thermals and the score's turnpoints have options of their own.
  if (thermals) {
    std::size_t marked = 0;
    for (const scene::Track& t : out.tracks.tracks())
      for (scene::Waypoint& w : scene::thermal_markers(t)) {
        out.waypoints.points.push_back(std::move(w));
        ++marked;
      }
    diagnostics.note(fmt::format("{} thermal marker{}", marked, marked == 1 ? "" : "s"));
  }
  if (waypoints.score) {
    scene::ScoredRouteDrawing drawing =
        scored_route_of(paths, waypoints.score_rules, style, build, placing, diagnostics);
    for (scene::Track& t : drawing.tracks) out.tracks.add(std::move(t));
    for (scene::Waypoint& w : drawing.waypoints) out.waypoints.points.push_back(std::move(w));
  }
  if (!waypoints.task_file.empty()) {
    scene::TaskDrawing drawing =
        task_drawing_of(waypoints.task_file, scene::highest_recorded_m(out.tracks), style, build, placing, diagnostics);
    for (scene::Track& t : drawing.tracks) out.tracks.add(std::move(t));
    for (scene::Waypoint& w : drawing.waypoints) out.waypoints.points.push_back(std::move(w));
    out.volumes = std::move(drawing.volumes);
  }
  return out;
}

scene::TaskDrawing task_drawing_of(const std::string& task_file, double highest_m, const scene::TrackStyle& style,
                                   const scene::TrackBuildOptions& build, const scene::WaypointBuildOptions& placing,
                                   scene::Diagnostics& diagnostics) {
  const track::task::TaskReadResult read = track::task::read_task_file(task_file);
  for (const auto& w : read.warnings) diagnostics.warning(w.to_string());
  if (read.error) throw std::runtime_error("--task: " + read.error->to_string());
  const track::task::TaskDistances distances = track::task::measure_task(*read.task);
  // 300 m above the highest point flown: the cylinders stand clear above the flights.
  const double ceiling = std::isnan(highest_m) ? highest_m : highest_m + 300.0;
  return scene::build_task_drawing(*read.task, distances, task_file, ceiling, style, build, placing, diagnostics);
}

scene::ScoredRouteDrawing scored_route_of(const std::vector<std::string>& paths, const std::string& rules_name,
                                          const scene::TrackStyle& style, const scene::TrackBuildOptions& build,
                                          const scene::WaypointBuildOptions& placing, scene::Diagnostics& diagnostics) {
  const auto igc = std::find_if(paths.begin(), paths.end(), is_igc_path);
  if (igc == paths.end()) throw std::runtime_error("--score needs an IGC file among the tracks");
  const auto rules = track::scoring::rule_set(rules_name);
  if (!rules) throw std::runtime_error("--score-rules: unknown rule set '" + rules_name + "'");
  const track::scoring::FixList list = track::scoring::read_scoring_fixes(*igc);
  if (list.error) throw std::runtime_error(*list.error);
  const track::scoring::ScoreResult result = track::scoring::score_flight(list.fixes, *rules);
  if (result.best < 0) {
    diagnostics.warning(*igc + ": no route scores under the " + rules_name + " rules: nothing to draw for --score");
    return {};
  }
  return scene::build_scored_route(result, list.fixes, *igc, style, build, placing, diagnostics);
}

double sun_time(const std::optional<double>& given, const scene::RecordedPoints& recorded) {
  return given ? *given : scene::default_sun_time(recorded);
}

TerrainSources open_terrain_sources(const TerrainOptions& options, scene::Diagnostics& diagnostics,
                                    bool imagery_without_terrain) {
  const terrain::TerrainConfig config = resolve_terrain_config(options);
  terrain::SourceContext context{config.network, config.cache,
                                 [&diagnostics](std::string w) { diagnostics.warning("terrain: " + w); }};
  terrain::SourceSettings height_settings = config.terrain;
  if (options.terrain_zoom) height_settings.max_zoom = *options.terrain_zoom;
  TerrainSources sources;
  sources.heights = terrain::open_height_source(height_settings, context);
  if (!options.surface.empty() && options.surface != "none") {
    if (!sources.heights)
      throw std::runtime_error("--surface needs --terrain: the tracks stand on the terrain model, the surface is drawn");
    terrain::SourceSettings surface_settings = height_settings;
    surface_settings.source = options.surface;
    surface_settings.encoding.reset();
    surface_settings.scheme.reset();
    sources.surface = terrain::open_height_source(surface_settings, context);
    if (sources.surface) sources.drawn_surface = std::make_unique<scene::CanopyCutHeights>(*sources.surface, *sources.heights);
  }
  // Without terrain the neutral ground is drawn plain: imagery (and an overlay) would never show,
  // so none is opened, and no server is asked (offline that cost seconds a picture).
  if (!sources.heights && !imagery_without_terrain) {
    if (!options.overlay.empty() || (!options.imagery.empty() && options.imagery != "none"))
      diagnostics.warning("--terrain none: the ground is drawn plain, without --imagery or --overlay");
    return sources;
  }
  // Imagery from --imagery, else the config file's, else the built-in default (README); `none`
  // gives the hypsometric tint, which shows the relief best. Tiles it cannot deliver (offline,
  // unreachable) are tinted too, after one warning that says how to leave it out.
  terrain::SourceContext imagery_context = context;
  imagery_context.warn = [&diagnostics](std::string w) {
    const bool unreachable = w.find("unreachable") != std::string::npos;
    diagnostics.warning("imagery: " + w + (unreachable ? " (--imagery none: the tint by height, nothing fetched)" : ""));
  };
  sources.imagery = terrain::open_imagery_source(config.imagery, imagery_context);
  if (!options.overlay.empty()) {
    OverlaySource overlay = open_overlay_source(options, context);
    sources.overlay_legend = std::move(overlay.legend);
    sources.imagery = std::make_unique<scene::OverlaidImagery>(std::move(sources.imagery), std::move(overlay.imagery),
                                                               options.overlay_opacity);
  }
  return sources;
}

void TerrainSources::cut_canopy(const scene::TrackSet& tracks) const {
  if (drawn_surface) drawn_surface->set_cut_lines(scene::covered_lines(tracks));
}

double ground_height_at(terrain::HeightSource* source, double lat, double lon) {
  if (source == nullptr) return std::numeric_limits<double>::quiet_NaN();
  terrain::HeightSampler sampler(*source);
  return sampler.sample(lat, lon);
}

scene::Camera initial_camera(const CameraRequest& request, const scene::Lens& lens, const scene::TrackSet& tracks,
                             double neutral_ground_m, terrain::HeightSource* heights,
                             const scene::KeptClearCorner& keep_clear, const std::optional<scene::ImageArea>& area,
                             const scene::WaypointSet* waypoints, scene::Diagnostics* diagnostics) {
  const scene::GroundHeight ground = [heights](double lat, double lon) { return ground_height_at(heights, lat, lon); };
  try {
    return scene::first_camera(request, lens, tracks, waypoints, neutral_ground_m, ground, {keep_clear, area},
                               diagnostics);
  } catch (const scene::FirstCameraError& e) {
    if (e.option().empty()) throw std::runtime_error(e.what());
    throw CLI::ValidationError(e.option(), e.why());  // a usage error naming the option
  }
}

}  // namespace trailray::app
