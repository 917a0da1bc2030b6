#version 300 es
// A photo's thumbnail in place of a label's text (label_pass.hpp): the atlas holds it framed, at
// the picture's pixel size, already sRGB (as the frame it is blended over), so each fragment
// reads exactly one texel; premultiplied by the label's opacity (the distance fade and the
// terrain's ghosting), blended ONE, ONE_MINUS_SRC_ALPHA like the text.
precision highp float;

uniform mediump sampler2D u_atlas;  // RGBA8: the framed thumbnails

in vec2 v_atlas_px;
in float v_alpha;
in vec3 v_color;
out vec4 frag_color;

void main() {
  vec4 texel = texelFetch(u_atlas, ivec2(floor(v_atlas_px)), 0);
  frag_color = vec4(texel.rgb * texel.a, texel.a) * v_alpha;
}
