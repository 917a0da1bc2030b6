#version 300 es
// Checks shadows.glsl (as encode_srgb.frag checks srgb.glsl): pixel column i of the target
// gets the sun's visibility at probe i in red and its cascade / 4 in green.
precision highp float;

#include "shadows.glsl"

uniform vec3 u_probe_positions[8];  // camera-relative, metres
uniform float u_probe_view_depths_m[8];
uniform vec3 u_probe_normal;
uniform vec3 u_sun_direction;

out vec4 frag_color;

void main() {
  int i = clamp(int(gl_FragCoord.x), 0, 7);
  float visibility = shadow_visibility(u_probe_positions[i], u_probe_view_depths_m[i], u_probe_normal, u_sun_direction);
  frag_color = vec4(visibility, float(shadow_cascade_for(u_probe_view_depths_m[i])) / 4.0, 0.0, 1.0);
}
