#include "app/pictures/render_picture.hpp"

#include "app/common/track_reading.hpp"
#include "app/drawing/photo_drawing.hpp"
#include "app/drawing/scene_setup.hpp"
#include "app/options/camera_options.hpp"
#include "app/pictures/render_report.hpp"
#include "render/platform/gl_context.hpp"
#include "render/renderer.hpp"
#include "scene/terrain_view.hpp"
#include "scene/text/legend_content.hpp"

namespace trailray::app {

// parse -> scene -> draw.
scene::RgbaImage render_picture(const RenderArgs& a, scene::Diagnostics& diagnostics,
                                std::vector<scene::LoadedTrackFile> more) {
  const scene::Lens lens = parse_lens(a.size, a.camera.fov_deg);
  const CameraRequest camera_request = parse_camera_request(a.camera, !a.tracks.empty() || !more.empty());
  check_render_args(a);
  const scene::Style style = parse_style(a.style);
  const std::optional<double> time = parse_sun_time(a.style.time);

  const TerrainSources sources = open_terrain_sources(a.terrain, diagnostics);
  scene::TerrainView terrain(sources.drawn(), sources.imagery.get());
  terrain.set_policy(
      {true, timeout_of(a), [&diagnostics](const terrain::LoadProgress& p) { diagnostics.progress(tiles_status(p)); }});
  std::vector<scene::LoadedTrackFile> files = read_track_files_parallel(a.tracks, a.track_options.read, diagnostics);
  for (scene::LoadedTrackFile& f : more) files.push_back(std::move(f));
  scene::TrackBuildOptions build{sources.heights.get(), 0.0, a.track_options.analysis};
  build.surface = sources.surface.get();
  SceneTracks tracks =
      build_scene_tracks(std::move(files), a.tracks, a.track_options.read, style.tracks, build, diagnostics, a.waypoints);
  sources.cut_canopy(tracks.tracks);
  // --photos: pins with thumbnails on the tracks.
  add_scene_photos(a.photos, tracks.tracks, tracks.waypoints,
                   {sources.heights.get(), tracks.recorded.lowest_or_sea_level()}, diagnostics);
  // The task's cylinders (--task) and the airspaces of --airspace, on the terrain.
  scene::VolumeSet volumes = tracks.volumes;
  add_airspace_volumes(volumes, a.airspace.files, airspace_region(tracks.tracks, tracks.waypoints, camera_request),
                       sources.heights.get(), diagnostics);
  scene::Scene scene;
  scene.terrain = &terrain;
  scene.tracks = &tracks.tracks;
  scene.waypoints = &tracks.waypoints;
  if (!volumes.volumes.empty()) scene.volumes = &volumes;
  scene.style = style;
  scene.color_range = scene::color_range(tracks.tracks, style);
  scene.overlay_legend = sources.overlay_legend;
  scene.sun_time_unix_s = sun_time(time, tracks.recorded);
  // Where no source has terrain: the tracks' lowest point (DESIGN.md), else the lowest terrain in view.
  scene.neutral_ground_m = tracks.recorded.lowest_m;
  // The camera: framed with the tracks out of the legend's way.
  const scene::KeptClearCorner legend =
      scene::legend_clearance(scene::scene_legend_panel(lens.width_px, lens.height_px, scene), lens.height_px);
  const scene::Camera camera =
      initial_camera(camera_request, lens, tracks.tracks, tracks.recorded.lowest_or_sea_level(), sources.heights.get(),
                     legend, std::nullopt, &tracks.waypoints, &diagnostics);

  render::GlContext gl = render::GlContext::create_headless();
  for (const std::string& line : gl.describe()) diagnostics.note(line);
  render::Renderer renderer;
  render::ImageTarget picture;
  picture.pixel_ratio = a.pixel_ratio;
  const render::FrameReport report = renderer.draw(scene, camera, picture);
  diagnostics.progress_done();
  if (a.profile) profile_frames(renderer, scene, camera, a.frames, picture);

  report_render(report, camera, scene, sources.heights.get(), a, diagnostics);
  scene::draw_scene_legend(picture.image, scene);
  return std::move(picture.image);
}

}  // namespace trailray::app
