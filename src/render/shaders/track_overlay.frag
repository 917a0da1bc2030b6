#version 300 es
// The track overlay (track_pass.hpp): what the G-buffer cannot hold, drawn into its own
// premultiplied target with its own depth and no blending, so each pixel keeps only the nearest
// track surface and is blended over the frame exactly once. This shader draws every fragment of
// the capsules the terrain may hide (track_fringe.frag the fringe of the others):
//   - hits the terrain hides: a translucent "ghost", constant alpha down to u_fade.x metres
//     behind the terrain, fading to 0 at u_fade.y (thesis §3.2.4); not where the terrain passes
//     through the tube (terrain_inside_tube): track_visible.frag draws those hits opaque;
//   - visible hits: transparent, but with their depth, so nothing behind them shows through;
//   - the anti-aliased fringe just outside a tube's silhouette (pushed back by the radius, so a
//     neighbouring tube's surface always wins over it).
// Ghosts and fringes are lit here by the sun and the sky (no shadows: they are not surfaces of
// the scene), and written sRGB-encoded like the composed frame.
precision highp float;
precision highp int;

#include "gbuffer.glsl"
#include "srgb.glsl"
#include "track_common.glsl"
#include "track_trace.glsl"
#include "track_overlay.glsl"
#include "behind_visible_track.glsl"

out vec4 overlay;

void main() {
  vec3 direction = normalize(v_position);
  float terrain = read_distance(u_terrain_distance, ivec2(gl_FragCoord.xy), u_packed_distance);
  // All of the capsule behind a visible track: nothing to draw, nothing to trace.
  float visible = visible_track_distance(terrain, u_packed_distance);
  if (behind_visible_track(length(closest_on_segment(vec3(0.0), v_x1, v_x2)) - v_radii.y, visible)) discard;
  CapsuleHit hit = trace_capsule(vec3(0.0), direction, true);
  if (hit.clipped) discard;
  if (!hit.hit) {
    vec4 colour;
    vec3 edge;
    if (!fringe(direction, terrain, colour, edge)) discard;
    if (behind_visible_track(dot(edge, direction) + v_radii.y, visible)) discard;
    // Pushed back by the radius, so a neighbouring tube's surface always wins over it.
    gl_FragDepth = window_depth(edge + direction * v_radii.y);
    overlay = colour;
    return;
  }
  if (behind_visible_track(hit.t, visible)) discard;
  float visibility = visibility_alpha(hit.t, terrain);
  bool inside = visibility < 1.0 && inside_tube(hit.on_axis, direction, terrain, hit.t);
  if (inside) visibility = 1.0;
  float depth = window_depth(hit.position);
  // Drawn by track_visible.frag in front of the terrain: the same depth here, so that no other
  // track's ghost behind the terrain shows over it.
  if (inside) depth = min(depth, window_depth(direction * (terrain - terrain_margin(terrain))));
  gl_FragDepth = depth;
  if (visibility >= 1.0) {
    overlay = vec4(0.0);  // in the G-buffer already: only its depth matters here
    return;
  }
  if (visibility <= 0.0) discard;
  overlay = vec4(lit(track_albedo(hit.position), hit.normal) * visibility, visibility);
}
