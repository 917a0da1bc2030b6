#version 300 es
// A label's pixels (label_pass.hpp): the atlas holds the text's coverage (red) and its halo's
// (green), rasterized at the picture's pixel size, so each fragment reads exactly one texel:
// crisp at any pixel ratio. The text's colour over a dark halo, premultiplied, blended over the
// frame's sRGB values (ONE, ONE_MINUS_SRC_ALPHA) as the legend is painted.
// Atlas coordinates reach 2048: highp, since a 16-bit float cannot address single texels there.
precision highp float;

uniform mediump sampler2D u_atlas;  // coverage bytes: mediump is plenty

in vec2 v_atlas_px;
in float v_alpha;
in vec3 v_color;
out vec4 frag_color;

const vec3 kHaloColor = vec3(0.06, 0.07, 0.08);
const float kHaloOpacity = 0.85;

void main() {
  vec2 coverage = texelFetch(u_atlas, ivec2(floor(v_atlas_px)), 0).rg;
  float text = coverage.r, halo = coverage.g * kHaloOpacity;
  float alpha = text + halo * (1.0 - text);
  vec3 color = v_color * text + kHaloColor * halo * (1.0 - text);
  frag_color = vec4(color, alpha) * v_alpha;
}
