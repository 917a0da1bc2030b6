#version 300 es
// A label's quad (label_pass.hpp), in picture pixels with y down, and whether the terrain hides
// its anchor: the G-buffer's distance at five texels around the anchor's pixel (a plus sign two
// pixels wide, so a thin track tube in front of the point does not hide it alone) is compared
// with the anchor's own distance. The fraction of texels that see the anchor mixes the label's
// opacity between u_hidden_alpha (all hidden) and 1, so a label slides into ghosting smoothly as
// a ridge comes over its point.
precision highp float;
precision highp int;
precision highp sampler2D;

#include "gbuffer.glsl"

layout(location = 0) in vec2 a_position_px;  // this corner, picture pixels (y down)
layout(location = 1) in vec2 a_atlas_px;     // the same corner in the atlas, texels
layout(location = 2) in vec2 a_anchor_px;    // the labelled point's pixel (y down)
layout(location = 3) in float a_distance_m;  // and its distance from the camera
layout(location = 4) in float a_alpha;       // from the distance fade
layout(location = 5) in vec3 a_color;        // the text's colour, sRGB
layout(location = 6) in float a_pin_reach_m; // how far its own pin rises above the anchor

uniform vec2 u_viewport_px;
uniform sampler2D u_distance;  // the G-buffer's
uniform bool u_packed_distance;
uniform float u_hidden_alpha;  // the opacity of a label whose point is hidden (0: not drawn)

out vec2 v_atlas_px;
out float v_alpha;
out vec3 v_color;

// Whether the scene at a pixel (GL's, y up) lies behind the anchor or is sky: the anchor is seen
// there. A surface counts as in front when it is nearer by more than 20 m plus 2 % of the
// distance: the terrain model and the recorded heights disagree by that much, and a pin's
// marker or the track's own tube at the anchor must not hide its label; nor may the label's own
// pin, which rises a_pin_reach_m above the anchor (seen from above it covers the anchor).
float sees_anchor(ivec2 pixel) {
  ivec2 size = textureSize(u_distance, 0);
  if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, size))) return 1.0;
  float scene_m = read_distance(u_distance, pixel, u_packed_distance);
  if (scene_m <= 0.0) return 1.0;  // the sky
  return scene_m + 20.0 + 0.02 * a_distance_m + a_pin_reach_m >= a_distance_m ? 1.0 : 0.0;
}

void main() {
  ivec2 anchor = ivec2(floor(vec2(a_anchor_px.x, u_viewport_px.y - a_anchor_px.y)));
  float seen = (sees_anchor(anchor) + sees_anchor(anchor + ivec2(2, 0)) + sees_anchor(anchor - ivec2(2, 0)) +
                sees_anchor(anchor + ivec2(0, 2)) + sees_anchor(anchor - ivec2(0, 2))) / 5.0;
  v_alpha = a_alpha * mix(u_hidden_alpha, 1.0, seen);
  v_atlas_px = a_atlas_px;
  v_color = a_color;
  vec2 ndc = vec2(a_position_px.x / u_viewport_px.x * 2.0 - 1.0, 1.0 - a_position_px.y / u_viewport_px.y * 2.0);
  // A label that ends up fully transparent is moved outside the clip volume: no fragments at all.
  gl_Position = v_alpha > 0.0 ? vec4(ndc, 0.0, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
}
