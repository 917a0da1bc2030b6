// Shared by the track pass's shaders (track_pass.hpp): fetching points from the track textures
// (track_buffer.hpp), the tube's radius, and the capsule geometry. Positions are camera-relative
// ECEF metres: the camera (the eye of the perspective passes) is at the origin.

uniform highp sampler2D u_points;  // xyz: offset from the block origin, w: value
uniform highp sampler2D u_blocks;  // xyz: block origin minus the camera
// The segment being drawn: its first and last point index, its first block and log2 of its points
// per block (TrackBuffer::Range). Set by the vertex shader's main (track.vert from its piece's
// texels, track_curtain.vert from uniforms) before any point is fetched.
int g_first;
int g_last;
int g_first_block;
int g_block_shift;
uniform float u_width_value;     // the tube's diameter: metres, or pixels when u_width_in_pixels
uniform bool u_width_in_pixels;
uniform float u_min_width_px;    // a tube is never thinner on screen than this
uniform float u_pixel_angle;     // the camera's pixel size per metre of view depth
uniform vec3 u_camera_forward;   // unit, ECEF: the camera's view axis

const float kMissingValueBelow = -1.0e38;  // track_buffer.cpp stores -3e38 for "no value"
// A category (track::kCategoryValue, -1e30: gliding) is drawn in u_category_color, not on the scale.
const float kCategoryValueBelow = -1.0e29;

vec4 fetch_texel(highp sampler2D texture_2d, int index) {
  int width = textureSize(texture_2d, 0).x;
  return texelFetch(texture_2d, ivec2(index % width, index / width), 0);
}

float track_value(int index) { return fetch_texel(u_points, index).w; }

// The point of segment a-b closest to p.
vec3 closest_on_segment(vec3 p, vec3 a, vec3 b) {
  vec3 ab = b - a;
  float length2 = dot(ab, ab);
  float s = length2 > 0.0 ? clamp(dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return a + ab * s;
}

// The size of a pixel (metres) at camera-relative point p: from its depth along the view axis,
// not its distance, so a tube off the image centre is as many pixels wide as one in the middle
// (the projection divides by depth).
float pixel_size_at(vec3 p) { return u_pixel_angle * max(dot(p, u_camera_forward), 1.0e-3 * length(p)); }

uniform vec3 u_up;    // unit, ECEF: the local vertical at the camera
uniform vec2 u_lift;  // the capsules' last points raised by max(x pixels, y metres) (pins)
// How the segment's points make capsules (CapsuleShape::Capsules): 0 a polyline (a capsule per
// consecutive pair, joined at the joints), 1 pairs (points 2k and 2k+1, each on its own: pins'
// stems), 2 singles (each point a ball on its own: pins' balls).
uniform int u_capsule_mode;

// Whether a point is the last of its capsule, which u_lift raises.
bool lifted(int index) {
  if (u_capsule_mode == 1) return ((index - g_first) & 1) == 1;
  return u_capsule_mode == 2 || index == g_last;
}

vec3 track_point(int index) {
  vec3 p = fetch_texel(u_points, index).xyz + fetch_texel(u_blocks, g_first_block + ((index - g_first) >> g_block_shift)).xyz;
  if ((u_lift.x > 0.0 || u_lift.y > 0.0) && lifted(index)) p += u_up * max(u_lift.x * pixel_size_at(p), u_lift.y);
  return p;
}

// The radius of the capsule a-b: from the width, never under the minimum on-screen width at the
// segment's depth (so a distant track never breaks into dots).
float tube_radius(vec3 a, vec3 b) {
  float pixel_m = pixel_size_at(closest_on_segment(vec3(0.0), a, b));
  float diameter = u_width_in_pixels ? u_width_value * pixel_m : u_width_value;
  return 0.5 * max(diameter, u_min_width_px * pixel_m);
}

// The plane through a joint that splits the overlap of the capsules before and after it (thesis
// eq. 3.7: normal along the chord from the next point to the previous one). An exact reversal
// (before == after) has no chord: any plane through the joint containing the segment will do,
// as the two capsules coincide. Both segments at a joint call this with the same three points.
vec3 joint_normal(vec3 before, vec3 joint, vec3 after) {
  vec3 chord = before - after;
  float chord_length = length(chord);
  float scale = length(before - joint) + length(after - joint);
  if (chord_length > 1.0e-5 * scale && chord_length > 0.0) return chord / chord_length;
  vec3 axis = joint - before;
  if (dot(axis, axis) == 0.0) axis = vec3(1.0, 0.0, 0.0);
  vec3 helper = abs(normalize(axis).x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  return normalize(cross(axis, helper));
}
