#version 300 es
// A linear colour written sRGB-encoded: checks that the shared transfer function (srgb.glsl)
// agrees with the CPU's linear_to_srgb8.
precision highp float;

#include "srgb.glsl"

uniform vec4 u_linear_color;

out vec4 frag_color;

void main() { frag_color = vec4(linear_to_srgb(u_linear_color.rgb), u_linear_color.a); }
