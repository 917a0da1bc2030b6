#version 300 es
// The G-buffer fill of the bench's reference tracks (render/reference/): a solid albedo, the
// interpolated view-space normal and the distance from the camera, like the terrain and the
// capsules' visible pass, so the three techniques cost the same per fragment outside geometry.
precision highp float;

#include "gbuffer.glsl"
#include "srgb.glsl"

uniform vec3 u_color_srgb;
uniform bool u_packed_distance;

in vec3 v_view_normal;
in vec3 v_from_camera;

layout(location = 0) out vec4 g_albedo;
layout(location = 1) out vec4 g_normal;
layout(location = 2) out vec4 g_distance;

void main() {
  g_albedo = vec4(srgb_to_linear(u_color_srgb), 1.0);
  g_normal = encode_normal(normalize(v_view_normal));
  float distance_m = length(v_from_camera);
  g_distance = u_packed_distance ? pack_distance(distance_m) : vec4(distance_m, 0.0, 0.0, 1.0);
}
