#include "render/passes/shadow_pass.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "geo/wgs84.hpp"
#include "render/gl/gl_api.hpp"

namespace trailray::render {
namespace {

void draw_tiles(const ShaderProgram& program, const ShadowCascade& light, std::span<const TerrainDrawItem> tiles) {
  program.use();
  for (const TerrainDrawItem& item : tiles) {
    if (item.mesh == nullptr || item.mesh->index_count == 0) continue;
    // The near cascades cover a few km: most tiles of the view fall outside them.
    if (!light.may_hold(item.mesh->origin, item.mesh->bounding_radius_m)) continue;
    const std::array<float, 16> matrix = light.view_projection_relative_to(item.mesh->origin);
    program.set_mat4("u_light_view_projection", std::span<const float, 16>(matrix));
    glBindVertexArray(item.mesh->vertex_array.id());
    glDrawElements(GL_TRIANGLES, item.mesh->index_count, GL_UNSIGNED_INT, nullptr);
  }
  glBindVertexArray(0);
}

}  // namespace

double caster_height_span_m(double lowest_m, double highest_m, const ShadowCasters& casters) {
  // Tracks (a flight kilometres above the ground) cast shadows too.
  double top = highest_m;
  if (casters.track_settings != nullptr && casters.track_settings->cast_shadows)
    for (const TrackDraw& draw : casters.tracks)
      if (draw.buffer != nullptr && draw.buffer->point_count() > 0) {
        const double centre_height = geo::geodetic_from_ecef(draw.buffer->bounding_centre_ecef()).height_m;
        top = std::max(top, centre_height + draw.buffer->bounding_radius_m());
      }
  return std::max(0.0, top - lowest_m);
}

void draw_shadow_pass(const ShadowMaps& maps, const ShadowCascades& cascades, const ShadowCasters& casters,
                      const TrackPass& track_pass, const scene::Camera& camera) {
  const bool tracks_cast = casters.track_settings != nullptr && casters.track_settings->cast_shadows;
  const int map_size_px = maps.map_size_px();
  std::size_t cascade = 0;
  maps.render(cascades, [&](const std::array<float, 16>&) {
    const ShadowCascade& light = cascades[cascade++];
    draw_tiles(maps.caster_program(), light, casters.tiles);
    if (!tracks_cast) return;
    // Only the tracks that reach into this cascade (a flight far from the camera casts into the
    // far cascades only).
    std::vector<TrackDraw> casting;
    for (const TrackDraw& draw : casters.tracks)
      if (draw.buffer != nullptr &&
          light.may_hold(draw.buffer->bounding_centre_ecef(), draw.buffer->bounding_radius_m()))
        casting.push_back(draw);
    if (casting.empty()) return;
    const std::array<float, 16> relative = light.view_projection_relative_to(camera.position());
    track_pass.draw_shadow_casters(relative, cascades.sun_direction_ecef(), 2.0 * light.radius_m / map_size_px, camera,
                                   casting, *casters.track_settings, [&light](const glm::dvec3& centre, double radius) {
                                     return light.may_hold(centre, radius);
                                   });
  });
}

}  // namespace trailray::render
