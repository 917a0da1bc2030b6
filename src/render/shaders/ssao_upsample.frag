#version 300 es
// The half-resolution occlusion (ssao.frag and ssao_blur.frag with u_step 2) brought to the
// G-buffer's resolution: each pixel blends the four occlusion texels around it bilinearly, but
// weighs each by how close its distance is to the pixel's (a joint bilateral upsample), so a
// ridge's occlusion does not spill over the valley behind it at the ridge line. A pixel none of
// whose four texels lies at its distance (a thin ridge top, a track) takes the nearest in
// distance.
precision highp float;

#include "gbuffer.glsl"

uniform sampler2D u_ao;  // half resolution: texel q stands for G-buffer pixel 2q
uniform sampler2D u_distance;
uniform bool u_packed_distance;

in vec2 v_uv;
out vec4 frag_ao;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float distance_m = read_distance(u_distance, pixel, u_packed_distance);
  if (distance_m <= 0.0) {
    frag_ao = vec4(1.0);
    return;
  }
  ivec2 ao_size = textureSize(u_ao, 0);
  // Texel q's centre is at G-buffer pixel 2q's centre: the pixel's position in texel units.
  vec2 f = vec2(pixel) * 0.5;
  ivec2 base = ivec2(floor(f));
  vec2 t = f - vec2(base);
  float sum = 0.0, weights = 0.0;
  float nearest_ao = 1.0, nearest_gap = 1e30;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      ivec2 q = clamp(base + ivec2(i, j), ivec2(0), ao_size - 1);
      float d = read_distance(u_distance, q * 2, u_packed_distance);
      float ao = texelFetch(u_ao, q, 0).r;
      float gap = abs(d - distance_m);
      if (gap < nearest_gap) {
        nearest_gap = gap;
        nearest_ao = ao;
      }
      float bilinear = (i == 0 ? 1.0 - t.x : t.x) * (j == 0 ? 1.0 - t.y : t.y);
      float w = bilinear * max(0.0, 1.0 - gap / (0.05 * distance_m));
      sum += ao * w;
      weights += w;
    }
  frag_ao = vec4(vec3(weights > 1e-4 ? sum / weights : nearest_ao), 1.0);
}
