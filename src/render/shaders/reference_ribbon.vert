#version 300 es
// The reference ribbon (render/reference/ribbon_pass.hpp): the usual polyline, a flat strip of
// constant width in pixels. Each track point comes twice (a_side -1 and +1); both copies are
// pushed apart on screen, across the track's screen direction at the point, by half the width.
// No joint handling beyond the averaged direction each point carries (a rough miter).

layout(location = 0) in vec3 a_position;   // ECEF offset from the track's origin, metres
layout(location = 1) in vec3 a_direction;  // unit ECEF direction of the track at the point
layout(location = 2) in float a_side;      // -1 or +1: which edge of the strip

uniform mat4 u_view_projection;      // relative to the origin (Camera::view_projection_relative_to)
uniform vec3 u_origin_minus_camera;  // ECEF, metres
uniform vec2 u_viewport_px;
uniform float u_half_width_px;

out vec3 v_view_normal;
out vec3 v_from_camera;

void main() {
  vec4 clip = u_view_projection * vec4(a_position, 1.0);
  // The derivative of the projected point along the track, in pixels (up to a positive factor
  // w^2): d(xy / w) = (dxy * w - xy * dw) / w^2.
  vec4 clip_direction = u_view_projection * vec4(a_direction, 0.0);
  vec2 along_px = (clip_direction.xy * clip.w - clip.xy * clip_direction.w) * u_viewport_px;
  float along_length = length(along_px);
  // Seen end-on the track has no screen direction: any side will do.
  vec2 across_px = along_length > 1e-20 ? vec2(-along_px.y, along_px.x) / along_length : vec2(0.0, 1.0);
  // Pixels to normalised device coordinates (2 / viewport), then to clip space (* w).
  clip.xy += across_px * (a_side * u_half_width_px) * 2.0 / u_viewport_px * clip.w;
  gl_Position = clip;
  // A flat strip facing the camera: its normal is the view axis.
  v_view_normal = vec3(0.0, 0.0, 1.0);
  v_from_camera = a_position + u_origin_minus_camera;
}
