#pragma once
// The shadow pass (DESIGN.md "The frame", step 2): the sun's cascaded shadow maps with the
// terrain tiles and the tracks as casters (tracks cast shadows: that is how a flight's height
// above the ground shows).

#include <glm/glm.hpp>

#include <span>

#include "render/passes/shadow_cascades.hpp"
#include "render/passes/shadow_maps.hpp"
#include "render/passes/terrain_pass.hpp"
#include "render/passes/track_pass.hpp"
#include "scene/camera/camera.hpp"

namespace trailray::render {

struct ShadowCasters {
  std::span<const TerrainDrawItem> tiles;
  std::span<const TrackDraw> tracks;
  const TrackSceneSettings* track_settings = nullptr;  // tracks cast when its cast_shadows is set
};

// How far above the lowest ground drawn the casters reach: the tiles' highest terrain and the
// tracks' bounding spheres (when they cast shadows). `lowest_m`/`highest_m`: the terrain's span.
double caster_height_span_m(double lowest_m, double highest_m, const ShadowCasters& casters);

// Renders every cascade of `maps` with the casters, each tile with its own origin (the cascade's
// matrix relative to it, taken in double), and the tracks that reach into the cascade.
void draw_shadow_pass(const ShadowMaps& maps, const ShadowCascades& cascades, const ShadowCasters& casters,
                      const TrackPass& track_pass, const scene::Camera& camera);

}  // namespace trailray::render
