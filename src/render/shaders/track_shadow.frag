#version 300 es
// The tracks as shadow casters: the capsule ray traced along the sun's rays (an orthographic
// view), its entry point's depth written into the cascade's map.
precision highp float;
precision highp int;

#include "track_common.glsl"
#include "track_trace.glsl"

uniform vec3 u_towards_light;  // unit, ECEF

void main() {
  CapsuleHit hit = trace_capsule(v_position, -u_towards_light, false);
  if (!hit.hit) discard;
  gl_FragDepth = window_depth(hit.position);
}
