#include "app/pictures/render_report.hpp"

#include <fmt/format.h>

#include "render/gl/frame_profiler.hpp"
#include "render/gl/gl_capabilities.hpp"
#include "scene/camera/sun_position.hpp"

namespace trailray::app {

std::string tiles_status(const terrain::LoadProgress& p) {
  return fmt::format("tiles: {}/{} loaded{}", p.loaded + p.no_data, p.wanted,
                     p.failed ? fmt::format(", {} failed", p.failed) : "");
}

void report_render(const render::FrameReport& r, const scene::Camera& camera, const scene::Scene& scene,
                   terrain::HeightSource* heights, const RenderArgs& a, scene::Diagnostics& diagnostics) {
  if (r.terrain.timed_out)
    diagnostics.warning(
        fmt::format("tiles still loading after --timeout {} s: drawn with what had arrived", a.timeout_s));
  if (!r.terrain.failures.empty())
    diagnostics.warning(fmt::format("{} tile{} failed; first: {}", r.terrain.failures.size(),
                                    r.terrain.failures.size() == 1 ? "" : "s", r.terrain.failures.front()));
  if (r.tiles_with_data == 0)
    diagnostics.warning(fmt::format("no terrain source covers the view ({}): drawing a neutral ground at {:.0f} m",
                                    heights ? heights->info().name : std::string("--terrain none"),
                                    r.terrain.neutral_ground_m));
  const auto& g = camera.geodetic();
  const scene::SolarPosition sun = scene::solar_position(scene.sun_time_unix_s, g.lat_deg, g.lon_deg);
  if (sun.elevation_deg < 0.0)
    diagnostics.warning(fmt::format("the sun is below the horizon ({:.1f} degrees) at that time", sun.elevation_deg));
  diagnostics.note(fmt::format(
      "camera {:.6f},{:.6f},{:.0f} m heading {:.1f} pitch {:.1f}, sun azimuth {:.1f} elevation {:.1f}", g.lat_deg,
      g.lon_deg, g.height_m, camera.heading_deg(), camera.pitch_deg(), sun.azimuth_deg, sun.elevation_deg));
  diagnostics.note(fmt::format("{} tiles drawn ({} with terrain, {} with imagery), {} selection rounds", r.tiles_drawn,
                               r.tiles_with_data, r.imagery_tiles_used, r.terrain.selection_rounds));
  constexpr double kMiB = 1024.0 * 1024.0;
  diagnostics.note(fmt::format("GPU memory for terrain: meshes {:.1f} MiB ({} tiles), imagery {:.1f} MiB ({} tiles)",
                               static_cast<double>(r.gpu_meshes.bytes) / kMiB, r.gpu_meshes.entries,
                               static_cast<double>(r.gpu_imagery.bytes) / kMiB, r.gpu_imagery.entries));
}

void profile_frames(render::Renderer& renderer, const scene::Scene& scene, const scene::Camera& camera, int frames,
                    render::ImageTarget& picture) {
  render::FrameProfiler profiler(render::query_gl_capabilities(), static_cast<std::size_t>(frames));
  picture.profiler = &profiler;
  // Each frame as drawn the first time: the shadow maps too, which a repeated frame would reuse.
  render::FrameOptions whole;
  whole.render_shadow_maps = true;
  for (int frame = 0; frame < frames; ++frame) renderer.draw(scene, camera, picture, whole);
  picture.profiler = nullptr;
  profiler.finish();
  fmt::print(stderr, "{}", profiler.table());
}

}  // namespace trailray::app
