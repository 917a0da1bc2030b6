#version 300 es
// A volume's wall or outline over the composed frame (volume_pass.hpp), premultiplied for
// blending ONE, ONE_MINUS_SRC_ALPHA over the frame's sRGB values. Hidden where the G-buffer holds
// something nearer (terrain, a track): a wall ends at the ridge in front of it and at the ground.
precision highp float;
precision highp int;
precision highp sampler2D;

#include "gbuffer.glsl"

uniform sampler2D u_distance;  // the G-buffer's
uniform bool u_packed_distance;
uniform vec3 u_fade;  // distance where walls start to fade, where the fade ends, the opacity left there

in vec3 v_from_camera;
in vec4 v_color;
in vec2 v_wall;
out vec4 frag_color;

void main() {
  float distance_m = length(v_from_camera);
  float scene_m = read_distance(u_distance, ivec2(gl_FragCoord.xy), u_packed_distance);
  // A margin of a metre and 0.1 %: the packed distance's steps and the mesh's facets.
  if (scene_m > 0.0 && distance_m > scene_m * 1.001 + 1.0) discard;
  float height = clamp(v_wall.x, 0.0, 1.0);
  // Stronger at the floor, where a pilot enters from below or beside, lighter towards the ceiling.
  float alpha = v_color.a * mix(1.0, 0.55, height);
  if (v_wall.y > 0.5) alpha *= 1.0 - smoothstep(0.45, 1.0, height);  // no real ceiling: fade out
  alpha *= mix(1.0, u_fade.z, smoothstep(u_fade.x, u_fade.y, distance_m));
  frag_color = vec4(v_color.rgb * alpha, alpha);
}
