#version 300 es
// The reference tube (render/reference/tube_pass.hpp): an explicit 8-sided mesh, vertices with
// their own normals, drawn like the terrain (float offsets from an origin, the camera-relative
// matrix made in double on the CPU).

layout(location = 0) in vec3 a_position;  // ECEF offset from the track's origin, metres
layout(location = 1) in vec3 a_normal;    // unit, ECEF

uniform mat4 u_view_projection;
uniform mat3 u_view_rotation;        // ECEF directions -> view space
uniform vec3 u_origin_minus_camera;  // ECEF, metres

out vec3 v_view_normal;
out vec3 v_from_camera;

void main() {
  v_view_normal = u_view_rotation * a_normal;
  v_from_camera = a_position + u_origin_minus_camera;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
