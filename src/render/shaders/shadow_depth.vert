#version 300 es
// Shadow casters into one cascade's depth map: positions are float offsets from the caster's
// origin, and the matrix (ShadowCascade::view_projection_relative_to that origin) takes
// "origin minus light eye" in double, so far-away casters keep their precision.

layout(location = 0) in vec3 a_position;

uniform mat4 u_light_view_projection;

void main() { gl_Position = u_light_view_projection * vec4(a_position, 1.0); }
