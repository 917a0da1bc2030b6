#version 300 es
// Averages the raw occlusion over the 4x4 block of its rotation pattern (ssao.frag), but only
// over pixels at a similar distance, so a ridge's occlusion does not bleed onto the valley far
// behind it (a depth-aware blur). At the occlusion's resolution: u_step as in ssao.frag.
precision highp float;

#include "gbuffer.glsl"

uniform sampler2D u_ao;
uniform sampler2D u_distance;
uniform bool u_packed_distance;
uniform int u_step;  // G-buffer pixels per occlusion pixel, each way

in vec2 v_uv;
out vec4 frag_ao;

void main() {
  ivec2 size = textureSize(u_ao, 0);
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float distance_m = read_distance(u_distance, pixel * u_step, u_packed_distance);
  if (distance_m <= 0.0) {
    frag_ao = vec4(1.0);
    return;
  }
  float sum = 0.0, weights = 0.0;
  for (int y = -2; y < 2; ++y)
    for (int x = -2; x < 2; ++x) {
      ivec2 p = clamp(pixel + ivec2(x, y), ivec2(0), size - 1);
      float d = read_distance(u_distance, p * u_step, u_packed_distance);
      float w = max(0.0, 1.0 - abs(d - distance_m) / (0.05 * distance_m));
      sum += texelFetch(u_ao, p, 0).r * w;
      weights += w;
    }
  frag_ao = vec4(vec3(weights > 0.0 ? sum / weights : 1.0), 1.0);
}
