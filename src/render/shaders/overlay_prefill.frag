#version 300 es
// The track overlay's depth before its capsules (TrackPass::draw_overlay): a copy of the
// G-buffer's depth after the visible tracks, kept where the nearest visible track lies in front
// of the terrain by the overlay's margin (track_overlay.glsl, visibility_alpha), put back to far
// elsewhere (the terrain, a track within the margin of it or lying in it: the overlay draws
// those itself). Where it is kept, it is the depth the overlay's own trace of that hit would
// write, so the capsules no terrain can hide need not trace their hits again.
precision highp float;

#include "gbuffer.glsl"

uniform highp sampler2D u_distance;          // the G-buffer's, with the visible tracks
uniform highp sampler2D u_terrain_distance;  // the terrain's alone (TrackPass's copy)
uniform bool u_packed_distance;
uniform float u_depth_step_k;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float d = read_distance(u_distance, pixel, u_packed_distance);
  float terrain = read_distance(u_terrain_distance, pixel, u_packed_distance);
  // Kept: the copy's depth stays. Else the triangle's own depth, far (TrackPass sets the depth
  // range to 1..1): no gl_FragDepth, so the depth write needs no late test.
  if (d > 0.0 && (terrain <= 0.0 || d < terrain - (0.07 + d * d * u_depth_step_k))) discard;
}
