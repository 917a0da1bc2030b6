#version 300 es
// The track overlay's draw of the capsules no terrain can hide (TrackPass::draw_overlay; the
// vertex shader keeps only those, u_overlay_split 2): their ghosts cannot exist and their hits'
// depth is in the overlay's depth buffer already (overlay_prefill.frag), so only the fringe is
// left, the same as track_overlay.frag draws it. No gl_FragDepth: the quad stands a radius behind
// the tube (track.vert), near the fringe's own depth, and the depth test runs before this shader,
// so a fragment behind a visible tube costs no ray test.
precision highp float;
precision highp int;

#include "gbuffer.glsl"
#include "srgb.glsl"
#include "track_common.glsl"
#include "track_trace.glsl"
#include "track_overlay.glsl"

out vec4 overlay;

void main() {
  vec3 direction = normalize(v_position);
  // Where the ray enters the capsule, track_overlay.frag draws a hit or nothing (the same entry
  // as trace_capsule's, from the same point): the hit's depth is the prefilled one.
  float shift = dot(0.5 * (v_x1 + v_x2), direction);
  float entry;
  vec3 on_axis;
  if (capsule_entry(direction * shift, direction, v_x1, v_x2, v_radii.y, entry, on_axis) && shift + entry > 0.0)
    discard;
  float terrain = read_distance(u_terrain_distance, ivec2(gl_FragCoord.xy), u_packed_distance);
  vec4 colour;
  vec3 edge;
  if (!fringe(direction, terrain, colour, edge)) discard;
  overlay = colour;
}
