#version 300 es
// One camera-facing quad per segment, from gl_VertexID alone (no vertex buffer; a shared index
// buffer only repeats 0 1 2 2 1 3): each instance is a piece of the frame's table (track_pieces.hpp,
// u_piece_base + gl_InstanceID), and its vertices 4k..4k+3 belong to its capsule k, from list
// position start + k to the next (a point index at full detail, else through the level's list).
// The quad is the tight bounding quad of thesis §3.2.2 (Groß and Gumhold), built per end in the
// plane facing the eye, with three corrections: it is widened to the capsule's true silhouette
// when the eye is near (a sphere of radius r seen from distance D spans r D / sqrt(D^2 - r^2) in
// the plane through its centre), both ends get the larger of the two ends' angular size (so a
// segment seen end-on, a disc, stays covered), and it has a margin for the anti-aliased fringe.
// u_orthographic: the shadow pass, where every ray runs along -u_towards_light.
precision highp float;
precision highp int;

#include "track_common.glsl"

uniform mat4 u_view_projection;  // camera-relative ECEF -> clip
uniform bool u_orthographic;
uniform vec3 u_towards_light;    // unit, ECEF (orthographic only)
uniform float u_margin_px;       // the quad's margin for the fringe, in pixels
uniform float u_texel_m;         // orthographic: the size of a shadow map texel
// The overlay's two draws (TrackPass::draw_overlay): 0 every capsule (the other passes), 1 only
// those the terrain may hide, 2 only the others.
uniform int u_overlay_split;
uniform float u_camera_height_m;  // above the ellipsoid
uniform float u_terrain_top_m;    // the highest terrain drawn, above the ellipsoid
uniform float u_depth_step_k;     // depth-buffer resolution at distance d: d * d * k metres
// The frame's pieces (track_pieces.hpp CapsulePieces::texels, three texels each) and the styles
// of the buffer's tracks (per track: linear colour, w 1 when coloured by value).
uniform highp isampler2D u_pieces;
uniform highp sampler2D u_track_styles;
uniform int u_piece_base;  // this draw's first piece (a size class)
// Level of detail (track_lod.hpp): a piece lies in a run of list positions run_first..run_last of
// one level, whose points come from the level's index list at list_base (-1: full detail, a
// position is a point index). The neighbours across the run's ends (x0 of its first capsule, x3
// of its last) are the points the adjacent runs join with (-1: the segment ends there), so a
// joint between two levels gets the same plane from both sides.
uniform highp isampler2D u_lod_indices;
int g_list_base;
int g_run_first;
int g_run_last;
int g_before;
int g_after;

ivec4 fetch_int_texel(highp isampler2D texture_2d, int index) {
  int width = textureSize(texture_2d, 0).x;
  return texelFetch(texture_2d, ivec2(index % width, index / width), 0);
}

int list_point(int position) {
  if (g_list_base < 0) return position;
  return fetch_int_texel(u_lod_indices, g_list_base + position).r;
}

flat out vec3 v_x0;  // the previous point (== v_x1 at a segment start)
flat out vec3 v_x1;
flat out vec3 v_x2;
flat out vec3 v_x3;  // the next point after v_x2 (== v_x2 at a segment end)
flat out vec3 v_radii;   // previous capsule's, this one's, next one's
flat out vec2 v_values;  // at v_x1 and v_x2
flat out int v_neighbours;  // bit 0: there is a previous capsule, bit 1: a next one
flat out vec3 v_start_plane;  // the joint planes' normals at v_x1 and v_x2 (joint_normal)
flat out vec3 v_end_plane;
flat out vec4 v_style;   // the track's linear colour, w 1: by value (track_trace.glsl track_albedo)
out vec3 v_position;     // the quad's point, camera-relative ECEF

// Heights from camera-relative positions: along the camera's vertical plus the Earth's curve over
// the distance across it. The largest radius of curvature of the ellipsoid (heights included)
// makes that curve the least, so a height is never overestimated; the smallest makes the sag of
// a straight line below the Earth's curve the most.
const float kEarthRadiusMaxM = 6.42e6;
const float kEarthRadiusMinM = 6.3e6;

float height_above_camera(vec3 p) {
  float up = dot(p, u_up);
  vec3 across = p - u_up * up;
  return up + dot(across, across) / (2.0 * kEarthRadiusMaxM);
}

// Whether no terrain can hide any part of the capsule x1-x2 or lie within the overlay's margin
// behind it (track_overlay.glsl, visibility_alpha): the camera and the whole capsule stand above
// the highest terrain drawn by more than a straight line between them sags below the Earth's
// curve, so every ray from the camera to the capsule passes above the terrain, and beyond it a
// ray needs as many metres as it has height to spare to come down to the terrain. A few metres
// and 1e-4 of the distance spare for the model (the ellipsoid's curvature, float rounding).
bool above_all_terrain(vec3 x1, vec3 x2, float radius) {
  float far_m = max(length(x1), length(x2)) + radius;
  float sag = far_m * far_m / (8.0 * kEarthRadiusMinM);
  vec3 axis = x2 - x1;
  float lowest = min(height_above_camera(x1), height_above_camera(x2)) - radius -
                 dot(axis, axis) / (8.0 * kEarthRadiusMinM);
  float top = u_terrain_top_m - u_camera_height_m + 2.0 + 1.0e-4 * far_m;
  float margin = 0.1 + 1.01 * far_m * far_m * u_depth_step_k;  // visibility_alpha's 0.07 + t * t * k
  return -sag > top && lowest - sag > top + margin;
}

void main() {
  // Four vertices per capsule (corner = end * 2 + side), indexed as triangles (0 1 2) (2 1 3):
  // the last vertex of each triangle, the provoking one whose flat outputs the fragments see,
  // is an end-1 corner, so only those fetch the neighbours and the values.
  int segment = gl_VertexID >> 2;
  int corner = gl_VertexID & 3;
  int end = corner >> 1;
  float side = (corner & 1) == 1 ? 1.0 : -1.0;
  int piece = 3 * (u_piece_base + gl_InstanceID);
  ivec4 run = fetch_int_texel(u_pieces, piece);
  ivec4 place = fetch_int_texel(u_pieces, piece + 1);
  if (segment >= place.z) {
    // Past the piece's capsules (an instance has as many quads as the largest piece of its class).
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    v_position = vec3(0.0);
    return;
  }
  ivec4 range = fetch_int_texel(u_pieces, piece + 2);
  g_list_base = run.x;
  g_run_first = run.y;
  g_run_last = run.z;
  g_before = run.w;
  g_after = place.x;
  g_first = range.x;
  g_last = range.y;
  g_first_block = range.z;
  g_block_shift = range.w;
  int start = place.y;
  // Pins' capsules stand alone (u_capsule_mode 1, 2: no neighbours, no joints).
  bool alone = u_capsule_mode != 0;
  int j1 = u_capsule_mode == 1 ? start + 2 * segment : start + segment;
  int j2 = u_capsule_mode == 2 ? j1 : min(j1 + 1, g_run_last);
  int i1 = list_point(j1);
  int i2 = list_point(j2);
  vec3 x1 = track_point(i1);
  vec3 x2 = track_point(i2);
  float radius = tube_radius(x1, x2);
  v_x1 = x1;
  v_x2 = x2;
  if (end == 1) {
    int before = j1 > g_run_first ? list_point(j1 - 1) : g_before;
    int after = j2 < g_run_last ? list_point(j2 + 1) : g_after;
    bool has_previous = !alone && before >= 0;
    bool has_next = !alone && after >= 0;
    vec3 x0 = has_previous ? track_point(before) : x1;
    vec3 x3 = has_next ? track_point(after) : x2;
    v_x0 = x0;
    v_x3 = x3;
    v_radii = vec3(has_previous ? tube_radius(x0, x1) : radius, radius, has_next ? tube_radius(x2, x3) : radius);
    v_values = vec2(track_value(i1), track_value(i2));
    v_neighbours = (has_previous ? 1 : 0) + (has_next ? 2 : 0);
    v_start_plane = has_previous ? joint_normal(x0, x1, x2) : vec3(0.0);
    v_end_plane = has_next ? joint_normal(x1, x2, x3) : vec3(0.0);
    v_style = fetch_texel(u_track_styles, place.w);
  } else {
    v_x0 = x1;
    v_x3 = x2;
    v_radii = vec3(radius);
    v_values = vec2(0.0);
    v_neighbours = 0;
    v_start_plane = vec3(0.0);
    v_end_plane = vec3(0.0);
    v_style = vec4(0.0);
  }

  if (u_overlay_split != 0 && above_all_terrain(x1, x2, radius) != (u_overlay_split == 2)) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // the other draw's capsule
    v_position = x1;
    return;
  }

  vec3 here = end == 0 ? x1 : x2;
  vec3 there = end == 0 ? x2 : x1;
  vec3 to_eye;
  float reach;
  if (u_orthographic) {
    to_eye = u_towards_light;
    reach = radius + u_margin_px * u_texel_m;
  } else {
    float eye_distance = length(closest_on_segment(vec3(0.0), x1, x2));
    if (eye_distance <= radius * 1.0001) {
      // The camera is inside this capsule: it would cover the whole view; leave it out.
      gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
      v_position = here;
      return;
    }
    float silhouette = radius * eye_distance / sqrt(eye_distance * eye_distance - radius * radius);
    float d_here = max(length(here), 1.0e-6);
    float d_there = max(length(there), 1.0e-6);
    to_eye = -here / d_here;
    reach = silhouette * max(1.0, d_here / d_there) + u_margin_px * pixel_size_at(here);
  }
  vec3 axis = x2 - x1;
  vec3 across_view = axis - to_eye * dot(axis, to_eye);
  float across_length = length(across_view);
  vec3 along, sideways;
  if (across_length > 1.0e-4 * length(axis) && across_length > 0.0) {
    along = across_view / across_length;
    sideways = normalize(cross(along, to_eye));
  } else {
    // Seen end-on (or a repeated point): any square around the view line.
    vec3 helper = abs(to_eye.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    sideways = normalize(cross(helper, to_eye));
    along = cross(to_eye, sideways);
  }
  float outward = end == 0 ? -1.0 : 1.0;
  vec3 position = here + along * (outward * reach) + sideways * (side * reach);
  // The overlay's fringe draw writes no depth of its own: its quad stands a radius further away
  // along each corner's ray (the same pixels), about where the fringe lies (track_fringe.frag).
  if (u_overlay_split == 2) position *= 1.0 + radius / max(length(position), 1.0e-6);
  v_position = position;
  gl_Position = u_view_projection * vec4(position, 1.0);
}
