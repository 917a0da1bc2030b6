#version 300 es
// The track pass into the G-buffer: visible hits become G-buffer texels like terrain (albedo,
// view-space normal, distance from the camera), with gl_FragDepth from the hit, so terrain and
// tracks hide each other per pixel and the compose pass lights them with the sun, the shadows
// and SSAO.
precision highp float;
precision highp int;

#include "gbuffer.glsl"
#include "track_common.glsl"
#include "track_trace.glsl"

uniform mat3 u_view_rotation;  // ECEF directions -> view space
uniform bool u_packed_distance;

layout(location = 0) out vec4 g_albedo;
layout(location = 1) out vec4 g_normal;
layout(location = 2) out vec4 g_distance;

void main() {
  CapsuleHit hit = trace_capsule(vec3(0.0), normalize(v_position), true);
  if (!hit.hit) discard;
  g_albedo = vec4(track_albedo(hit.position), 0.0);  // alpha 0: a track (compose.frag: less haze)
  g_normal = encode_normal(normalize(u_view_rotation * hit.normal));
  g_distance = u_packed_distance ? pack_distance(hit.t) : vec4(hit.t, 0.0, 0.0, 1.0);
  gl_FragDepth = window_depth(hit.position);
}
