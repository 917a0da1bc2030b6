// The fragment half of the capsule technique (track_pass.hpp): the ray-capsule intersection
// with the exact normal, the joint clipping, the colour of a hit. Needs track_common.glsl.

flat in vec3 v_x0;
flat in vec3 v_x1;
flat in vec3 v_x2;
flat in vec3 v_x3;
flat in vec3 v_radii;
flat in vec2 v_values;
flat in int v_neighbours;
flat in vec3 v_start_plane;
flat in vec3 v_end_plane;
flat in vec4 v_style;  // the track's linear colour, w 1: coloured by value
in vec3 v_position;

uniform mat4 u_view_projection;

// The nearest entry of the line o + t d (d unit, t of either sign) into the capsule a-b of
// radius r: the cylinder body, else the nearer of the end spheres (which lie inside the infinite
// cylinder, so a ray missing it misses them too). Each part is solved from the ray's point of
// closest approach to it (the axis line, a sphere's centre), where the quadratic has no large
// terms: a textbook form such as |oa|^2 |ba|^2 - (oa.ba)^2 - r^2 |ba|^2 subtracts numbers of
// 1e15 to find one of 1e9 for a kilometre-long segment, and float arithmetic loses the radius
// (ragged edges). The caller puts o near the capsule. `on_axis`: the point of the axis segment
// the line passes nearest (of the entered end sphere's centre when the line runs along the axis).
bool capsule_entry(vec3 o, vec3 d, vec3 a, vec3 b, float r, out float t, out vec3 on_axis) {
  t = 0.0;
  on_axis = a;
  bool across = false;
  vec3 ba = b - a;
  float len = length(ba);
  if (len > 0.0) {
    vec3 u = ba / len;
    vec3 oa = o - a;
    vec3 d_across = d - u * dot(d, u);
    float dd = dot(d_across, d_across);
    if (dd > 1.0e-10) {
      across = true;
      vec3 oa_across = oa - u * dot(oa, u);
      float closest = -dot(oa_across, d_across) / dd;  // the ray's point nearest the axis line
      on_axis = a + u * clamp(dot(oa + d * closest, u), 0.0, len);
      vec3 miss = oa_across + d_across * closest;
      float miss2 = dot(miss, miss);
      if (miss2 > r * r) return false;
      float entry = closest - sqrt((r * r - miss2) / dd);
      float y = dot(oa + d * entry, u);
      if (y > 0.0 && y < len) {
        t = entry;
        return true;
      }
    }
  }
  bool hit = false;
  float best = 0.0;
  for (int end = 0; end < 2; ++end) {
    vec3 centre = end == 0 ? a : b;
    float closest = dot(centre - o, d);
    vec3 miss = o + d * closest - centre;
    float miss2 = dot(miss, miss);
    if (miss2 > r * r) continue;
    float entry = closest - sqrt(r * r - miss2);
    if (!hit || entry < best) {
      best = entry;
      if (!across) on_axis = centre;
    }
    hit = true;
  }
  t = best;
  return hit;
}

// Whether p (on this capsule's surface) lies inside the capsule a-b, by a hair more than
// rounding: where two surfaces nearly coincide (points much closer together than the radius),
// neither capsule drops its hit, and the depth test keeps the nearer; a looser test let both
// drop theirs and left pinholes.
bool inside_capsule(vec3 p, vec3 a, vec3 b, float r) {
  return length(p - closest_on_segment(p, a, b)) < r * (1.0 - 1.0e-3);
}

// The joints (thesis §3.2.3): a hit beyond the plane through a joint is dropped when the
// neighbouring capsule holds it; that capsule draws the surface there. Clipping only what the
// neighbour covers leaves no hole at any turn: the first entry of a ray into the union of the
// two capsules is never inside either, so it is always drawn. Both passes depth-test without
// blending between track fragments, so a pixel both capsules draw still shows one surface once.
bool clipped_by_joints(vec3 p) {
  if ((v_neighbours & 1) != 0 && dot(p - v_x1, v_start_plane) >= 0.0 &&
      inside_capsule(p, v_x0, v_x1, v_radii.x))
    return true;
  if ((v_neighbours & 2) != 0 && dot(p - v_x2, v_end_plane) < 0.0 && inside_capsule(p, v_x2, v_x3, v_radii.z))
    return true;
  return false;
}

// Dashes (routes): where a point of this capsule lies along the line (the values are metres along
// it), dashes and gaps of about u_dash_px pixels, as a power of two of metres so that the
// pattern stays put while the camera moves (it doubles where the distance does).
uniform float u_dash_px;  // 0: not dashed

bool in_dash_gap(vec3 p) {
  if (u_dash_px <= 0.0) return false;
  vec3 ab = v_x2 - v_x1;
  float length2 = dot(ab, ab);
  float s = length2 > 0.0 ? clamp(dot(p - v_x1, ab) / length2, 0.0, 1.0) : 0.0;
  float along = mix(v_values.x, v_values.y, s);
  float period = exp2(ceil(log2(2.0 * u_dash_px * pixel_size_at(p))));
  return fract(along / period) >= 0.5;
}

struct CapsuleHit {
  bool hit;
  bool clipped;    // the ray hits this capsule where its neighbour draws the surface
  float t;         // along the ray
  vec3 position;   // camera-relative ECEF
  vec3 normal;     // unit, ECEF
  vec3 on_axis;    // the axis point the ray passes nearest (capsule_entry), camera-relative
};

// The ray from `origin` along unit `direction` against this fragment's capsule, with the joints
// clipped. `in_front_only`: hits behind the origin (t <= 0) do not count.
CapsuleHit trace_capsule(vec3 origin, vec3 direction, bool in_front_only) {
  CapsuleHit result;
  result.hit = false;
  result.clipped = false;
  result.t = 0.0;
  result.position = vec3(0.0);
  result.normal = vec3(0.0, 0.0, 1.0);
  result.on_axis = vec3(0.0);
  float shift = dot(0.5 * (v_x1 + v_x2) - origin, direction);
  vec3 near_origin = origin + direction * shift;
  float t;
  vec3 on_axis;
  if (!capsule_entry(near_origin, direction, v_x1, v_x2, v_radii.y, t, on_axis)) return result;
  if (in_front_only && shift + t <= 0.0) return result;
  vec3 p = near_origin + direction * t;
  if (clipped_by_joints(p)) {
    result.clipped = true;
    return result;
  }
  if (in_dash_gap(p)) return result;
  result.hit = true;
  result.t = shift + t;
  result.position = p;
  result.normal = normalize(p - closest_on_segment(p, v_x1, v_x2));
  result.on_axis = on_axis;
  return result;
}

// The point of this capsule's axis segment nearest the ray from the camera along unit
// `direction`: where the pixel's ray passes closest to the tube's middle (a hit has it as
// CapsuleHit::on_axis).
vec3 axis_nearest_ray(vec3 direction) {
  vec3 axis = v_x2 - v_x1;
  float shift = dot(0.5 * (v_x1 + v_x2), direction);
  vec3 o = direction * shift;  // the ray's point nearest the segment's middle
  // Closest approach of the ray (o + t d) and the segment: minimise over the segment parameter.
  float length2 = dot(axis, axis);
  float s = 0.0;
  if (length2 > 0.0) {
    vec3 axis_across = axis - direction * dot(axis, direction);
    float across2 = dot(axis_across, axis_across);
    s = across2 > 1.0e-12 * length2 ? clamp(dot(o - v_x1, axis_across) / across2, 0.0, 1.0) : 0.0;
  }
  return v_x1 + axis * s;
}

// --- terrain inside the tube ---
// A track lying on the ground (a hike whose heights are the DEM's, a track without heights on
// the neutral ground) has the lower half of its tube below the surface; seen obliquely, the rays
// near its near-side silhouette meet the ground first, in front of the tube, then the tube
// underground. Terrain that passes through the tube is not what the occlusion is about (a ridge
// in front, a forest canopy above a hike: thesis section 3.2.4), so it does not hide the tube.
// The test: the terrain's tangent plane where this pixel sees it (distance and normal from the
// G-buffer) passes within the tube's radius of the axis point the pixel's ray passes nearest
// (CapsuleHit::on_axis for a hit, axis_nearest_ray for the fringe). The surface point itself is
// rarely that close (on flat ground the ray meets it up to r / sin(incidence) from the axis),
// but the plane through it cuts the tube exactly when the ground does. Where a track runs into a
// slope, this shows the tube whole as long as the slope cuts its cross-section, i.e. until it
// is buried. The tangent plane is only a local model of the terrain, so a ray that runs more
// than kMaxUndergroundRadii radii below the surface before it meets the tube keeps it hidden
// (terrain_near_tube; for a tube centred on flat ground that happens only where the view grazes
// the ground at under 3 degrees). Camera-relative positions throughout: the terrain point and
// the axis are both near the tube, and their difference keeps its precision at any distance
// from the ECEF origin.
const float kMaxUndergroundRadii = 20.0;

// Whether terrain_inside_tube can hold at all for the tube's point `t` along the ray: terrain
// there, and the tube not too far below it (asked first: a GPU then skips the normal's fetch
// for a track far behind a ridge; llvmpipe runs both sides of a branch anyway).
bool terrain_near_tube(float terrain, float t) {
  return terrain > 0.0 && t - terrain <= kMaxUndergroundRadii * v_radii.y;
}

// The terrain's normal in ECEF from its G-buffer texel (gbuffer.glsl's encoding) and the view
// rotation (ECEF -> view). Not normalised: the 10-bit rounding changes its length, and the
// test's height, by well under a percent.
vec3 terrain_normal_ecef(mat3 view_rotation, vec4 normal_texel) {
  return transpose(view_rotation) * (normal_texel.xyz * 2.0 - 1.0);
}

// `on_axis`: as above; the terrain `terrain` metres along the unit ray `direction`, with
// `terrain_normal` (ECEF, terrain_normal_ecef).
bool terrain_inside_tube(vec3 on_axis, vec3 direction, float terrain, vec3 terrain_normal) {
  return abs(dot(on_axis - direction * terrain, terrain_normal)) <= v_radii.y;
}

uniform float u_depth_step_k;  // depth-buffer resolution at distance d: d * d * k metres

// How far in front of the terrain `terrain` metres away a hit it does not hide is drawn: two
// depth steps and a little more than the packed distance's rounding, so that the depth test
// keeps the hit whatever the rounding of either depth. Wider than visibility_alpha's margin in
// track_overlay.frag, so that wherever the overlay asks whether the terrain is inside the tube,
// track_visible.frag has asked it too.
float terrain_margin(float terrain) { return 0.1 + 2.0 * terrain * terrain * u_depth_step_k; }

// Window depth of a camera-relative point (for gl_FragDepth), clamped to the depth range.
float window_depth(vec3 p) {
  vec4 clip = u_view_projection * vec4(p, 1.0);
  return clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
}

// --- colour ---
uniform vec3 u_missing_color;  // linear: a point without a value
uniform vec3 u_category_color;  // linear: a point of the category (kCategoryValueBelow)
uniform highp sampler2D u_colormap;  // 256x1 sRGB texture: sampled as linear
uniform vec2 u_value_range;    // min, max of the colour scale

// The value at a point of the segment: interpolated between the ends; where an end has no
// value or a category instead, the nearer end decides (a category is never blended into the scale).
vec3 track_albedo(vec3 p) {
  if (v_style.w < 0.5) return v_style.rgb;
  vec3 ab = v_x2 - v_x1;
  float length2 = dot(ab, ab);
  float s = length2 > 0.0 ? clamp(dot(p - v_x1, ab) / length2, 0.0, 1.0) : 0.0;
  bool special_a = v_values.x < kCategoryValueBelow;
  bool special_b = v_values.y < kCategoryValueBelow;
  float value;
  if (!special_a && !special_b) {
    value = mix(v_values.x, v_values.y, s);
  } else {
    float nearer = s < 0.5 ? v_values.x : v_values.y;
    if (nearer < kMissingValueBelow) return u_missing_color;
    if (nearer < kCategoryValueBelow) return u_category_color;
    value = nearer;
  }
  float span = u_value_range.y - u_value_range.x;
  float position = span > 0.0 ? clamp((value - u_value_range.x) / span, 0.0, 1.0) : 0.5;
  return texture(u_colormap, vec2((position * 255.0 + 0.5) / 256.0, 0.5)).rgb;
}
