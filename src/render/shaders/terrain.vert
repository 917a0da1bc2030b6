#version 300 es
// Terrain tiles: vertices are float offsets from the tile's origin (terrain_mesh.hpp), and
// u_view_projection already holds the translation "origin - camera" taken in double on the CPU,
// so no large coordinate ever reaches the GPU (DESIGN.md precision rule). The same small
// "origin - camera" offset gives each fragment its distance from the camera.

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_height;
layout(location = 3) in vec2 a_uv;
layout(location = 4) in float a_covered;

uniform mat4 u_view_projection;
uniform mat3 u_view_rotation;        // ECEF directions -> view space
uniform vec3 u_origin_minus_camera;  // ECEF, metres
// Where this tile's (0..1) square lies in its imagery tile's (an ancestor's, while the tile's own
// is missing): uv * scale + offset.
uniform vec4 u_imagery_transform;

out vec3 v_view_normal;
out vec3 v_from_camera;
out float v_height;
out vec2 v_imagery_uv;
out float v_covered;

void main() {
  v_view_normal = u_view_rotation * a_normal;
  v_from_camera = a_position + u_origin_minus_camera;
  v_height = a_height;
  v_imagery_uv = a_uv * u_imagery_transform.xy + u_imagery_transform.zw;
  v_covered = a_covered;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
