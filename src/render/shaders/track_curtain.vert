#version 300 es
// The curtain (`--curtain`): per segment a vertical wall from the track down to the ground, as
// Google Earth's "extrude" draws it: two triangles between the segment's points and the points
// below them. The drop (height above the ground) comes from the track's drop texture; "down" is
// the ellipsoid's normal at each point.
precision highp float;
precision highp int;

#include "track_common.glsl"

uniform highp sampler2D u_drops;  // R32F: metres from each point down to the ground
uniform mat4 u_view_projection;
uniform vec3 u_eye_ecef;          // the camera's position (only for the direction of "down")
// The segment (TrackBuffer::Range) and the point of this draw's first wall (draws go in chunks).
uniform int u_first;
uniform int u_last;
uniform int u_first_block;
uniform int u_block_shift;
uniform int u_chunk_first;

out vec3 v_position;
out float v_value;
out float v_height_fraction;  // 1 at the track, 0 at the ground

const vec3 kInverseAxes2 = vec3(1.0 / (6378137.0 * 6378137.0), 1.0 / (6378137.0 * 6378137.0),
                                1.0 / (6356752.314245 * 6356752.314245));

void main() {
  g_first = u_first;
  g_last = u_last;
  g_first_block = u_first_block;
  g_block_shift = u_block_shift;
  // Four vertices per segment (corner = end * 2 + top), indexed as triangles (0 1 2) (2 1 3).
  int segment = gl_VertexID >> 2;
  int corner = gl_VertexID & 3;
  int index = min(u_chunk_first + segment + (corner >> 1), g_last);
  bool top = (corner & 1) == 1;
  vec3 point = track_point(index);
  float drop = fetch_texel(u_drops, index).r;
  vec3 down = -normalize((u_eye_ecef + point) * kInverseAxes2);
  vec3 position = top ? point : point + down * drop;
  v_position = position;
  v_value = track_value(index);
  v_height_fraction = top ? 1.0 : 0.0;
  gl_Position = u_view_projection * vec4(position, 1.0);
}
