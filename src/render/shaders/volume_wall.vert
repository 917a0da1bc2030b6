#version 300 es
// A volume's wall (volume_pass.hpp): positions are float offsets from the set's origin, and
// u_view_projection holds "origin - camera" taken in double on the CPU (DESIGN.md precision).

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_color;  // sRGB, opacity
layout(location = 2) in vec2 a_wall;   // 0 at the floor .. 1 at the ceiling; 1: the top fades out

uniform mat4 u_view_projection;
uniform vec3 u_origin_minus_camera;

out vec3 v_from_camera;
out vec4 v_color;
out vec2 v_wall;

void main() {
  v_from_camera = a_position + u_origin_minus_camera;
  v_color = a_color;
  v_wall = a_wall;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
