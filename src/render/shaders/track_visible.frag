#version 300 es
// The track pass into the G-buffer: visible hits become G-buffer texels like terrain (albedo,
// view-space normal, distance from the camera), with gl_FragDepth from the hit, so terrain and
// tracks hide each other per pixel and the compose pass lights them with the sun, the shadows
// and SSAO.
// Where the terrain passes through the tube (terrain_inside_tube: a track lying on the ground),
// a hit below the surface is drawn too: its depth is pulled just in front of the terrain's so
// the depth test keeps it, and its distance is the terrain's, so the lighting (shadows, SSAO,
// haze) sees the surface the tube lies in rather than a point under the ground, which the
// terrain itself would shadow.
precision highp float;
precision highp int;

#include "gbuffer.glsl"
#include "track_common.glsl"
#include "track_trace.glsl"

uniform mat3 u_view_rotation;  // ECEF directions -> view space
uniform bool u_packed_distance;
// The terrain's distance and normal: copies of the G-buffer's (TrackPass::draw_visible makes
// them), as this pass writes the G-buffer itself.
uniform highp sampler2D u_terrain_distance;
uniform highp sampler2D u_terrain_normal;

layout(location = 0) out vec4 g_albedo;
layout(location = 1) out vec4 g_normal;
layout(location = 2) out vec4 g_distance;

void main() {
  vec3 direction = normalize(v_position);
  CapsuleHit hit = trace_capsule(vec3(0.0), direction, true);
  if (!hit.hit) discard;
  float distance_m = hit.t;
  float depth = window_depth(hit.position);
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float terrain = read_distance(u_terrain_distance, pixel, u_packed_distance);
  float margin = terrain_margin(terrain);
  if (hit.t > terrain - margin && terrain_near_tube(terrain, hit.t)) {
    vec3 terrain_normal = terrain_normal_ecef(u_view_rotation, texelFetch(u_terrain_normal, pixel, 0));
    if (terrain_inside_tube(hit.on_axis, direction, terrain, terrain_normal)) {
      distance_m = min(hit.t, terrain);
      depth = min(depth, window_depth(direction * (terrain - margin)));
    }
  }
  g_albedo = vec4(track_albedo(hit.position), 0.0);  // alpha 0: a track (compose.frag: less haze)
  g_normal = encode_normal(normalize(u_view_rotation * hit.normal));
  g_distance = u_packed_distance ? pack_distance(distance_m) : vec4(distance_m, 0.0, 0.0, 1.0);
  gl_FragDepth = depth;
}
