#version 300 es
// A floor or ceiling outline (volume_pass.hpp): each segment a quad u_width_px wide in screen
// space (GL lines are one pixel wide on many drivers), its ends clipped to the near plane first
// so a segment passing beside the camera keeps its direction.

layout(location = 0) in vec3 a_from;
layout(location = 1) in vec3 a_to;
layout(location = 2) in vec4 a_color;
layout(location = 3) in vec2 a_corner;  // x: 0 at a_from, 1 at a_to; y: -1 or 1 across

uniform mat4 u_view_projection;
uniform vec3 u_origin_minus_camera;
uniform vec2 u_viewport_px;
uniform float u_width_px;

out vec3 v_from_camera;
out vec4 v_color;
out vec2 v_wall;

void main() {
  vec4 p = u_view_projection * vec4(a_from, 1.0);
  vec4 q = u_view_projection * vec4(a_to, 1.0);
  float dp = p.z + p.w, dq = q.z + q.w;  // >= 0 in front of the near plane
  vec3 from = a_from, to = a_to;
  if (dp < 0.0 && dq < 0.0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // wholly behind: outside the clip volume
    v_from_camera = vec3(0.0);
    v_color = vec4(0.0);
    v_wall = vec2(0.0);
    return;
  }
  if (dp < 0.0) {
    float t = dp / (dp - dq);
    p = mix(p, q, t);
    from = mix(a_from, a_to, t);
  } else if (dq < 0.0) {
    float t = dq / (dq - dp);
    q = mix(q, p, t);
    to = mix(a_to, a_from, t);
  }
  p.w = max(p.w, 1e-6);
  q.w = max(q.w, 1e-6);
  vec2 sp = p.xy / p.w * u_viewport_px * 0.5;
  vec2 sq = q.xy / q.w * u_viewport_px * 0.5;
  vec2 along = sq - sp;
  along = dot(along, along) > 1e-8 ? normalize(along) : vec2(1.0, 0.0);
  vec2 across = vec2(-along.y, along.x);
  vec4 here = a_corner.x < 0.5 ? p : q;
  here.xy += across * a_corner.y * (0.5 * u_width_px) / (u_viewport_px * 0.5) * here.w;
  v_from_camera = (a_corner.x < 0.5 ? from : to) + u_origin_minus_camera;
  v_color = a_color;
  v_wall = vec2(0.0);
  gl_Position = here;
}
