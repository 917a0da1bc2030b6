#version 300 es
// The track overlay's draw of the capsules no terrain can hide (TrackPass::draw_overlay; the
// vertex shader keeps only those, u_overlay_split 2): their ghosts cannot exist and their hits
// are in the G-buffer, so only the fringe is left, the same as track_overlay.frag draws it. What
// lies behind a visible track is dropped either by the depth test against the overlay's
// prefilled depth, before this shader (overlay_prefill.frag), or here (behind_visible_track). No
// gl_FragDepth: the quad stands a radius behind the tube (track.vert), near the fringe's own depth.
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
  float visible = visible_track_distance(terrain, u_packed_distance);
  if (behind_visible_track(length(closest_on_segment(vec3(0.0), v_x1, v_x2)) - v_radii.y, visible)) discard;
  // Where the ray enters the capsule, track_overlay.frag draws a hit or nothing (the same entry
  // as trace_capsule's, from the same point): the hit is the G-buffer's.
  float shift = dot(0.5 * (v_x1 + v_x2), direction);
  float entry;
  vec3 on_axis;
  if (capsule_entry(direction * shift, direction, v_x1, v_x2, v_radii.y, entry, on_axis) && shift + entry > 0.0)
    discard;
  vec4 colour;
  vec3 edge;
  if (!fringe(direction, terrain, colour, edge)) discard;
  if (behind_visible_track(dot(edge, direction) + v_radii.y, visible)) discard;
  overlay = colour;
}
