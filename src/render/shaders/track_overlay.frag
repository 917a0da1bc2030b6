#version 300 es
// The track overlay (track_pass.hpp): what the G-buffer cannot hold, drawn into its own
// premultiplied target with its own depth and no blending, so each pixel keeps only the nearest
// track surface and is blended over the frame exactly once:
//   - hits the terrain hides: a translucent "ghost", constant alpha down to u_fade.x metres
//     behind the terrain, fading to 0 at u_fade.y (thesis §3.2.4); not where the terrain passes
//     through the tube (terrain_inside_tube): track_visible.frag draws those hits opaque;
//   - visible hits: transparent, but with their depth, so nothing behind them shows through;
//   - the anti-aliased fringe just outside a tube's silhouette (pushed back by the radius, so a
//     neighbouring tube's surface always wins over it).
// Ghosts and fringes are lit here by the sun and the sky (no shadows: they are not surfaces of
// the scene), and written sRGB-encoded like the composed frame.
precision highp float;
precision highp int;

#include "gbuffer.glsl"
#include "srgb.glsl"
#include "track_common.glsl"
#include "track_trace.glsl"

uniform highp sampler2D u_terrain_distance;  // the G-buffer's distance before the tracks
uniform highp sampler2D u_terrain_normal;    // and its normal
uniform mat3 u_view_rotation;                // ECEF directions -> view space
uniform bool u_packed_distance;
uniform bool u_show_occluded;
uniform float u_occluded_alpha;
uniform vec2 u_fade;           // metres behind the terrain: constant alpha until x, 0 at y
uniform vec3 u_sun;            // unit, towards the sun, ECEF
uniform vec3 u_sun_radiance;
uniform vec3 u_sky_radiance;

out vec4 overlay;

vec3 lit(vec3 albedo, vec3 normal) {
  float sun = max(dot(normal, u_sun), 0.0);
  float sky = 0.5 + 0.5 * dot(normal, u_up);
  return linear_to_srgb(albedo * (u_sun_radiance * sun + u_sky_radiance * sky));
}

// The alpha of a track point `t` metres along the ray where the terrain is `terrain` metres
// away (0: sky); 1 where nothing hides it.
float visibility_alpha(float t, float terrain) {
  // Lean towards "hidden": where the two passes' depth tests disagree by a depth step, a faint
  // ghost over the opaque tube shows nothing, a hole would.
  if (terrain <= 0.0 || t < terrain - (0.07 + t * t * u_depth_step_k)) return 1.0;
  if (!u_show_occluded) return 0.0;
  float behind = max(t - terrain, 0.0);
  float fade = u_fade.y > u_fade.x ? clamp((behind - u_fade.x) / (u_fade.y - u_fade.x), 0.0, 1.0)
                                   : (behind > u_fade.x ? 1.0 : 0.0);
  return u_occluded_alpha * (1.0 - fade);
}

// Whether the terrain passes through the tube where the ray passes nearest `on_axis`, at `t`:
// the same test with the same inputs as track_visible.frag's, which draws the tube there (each
// pixel once).
bool inside_tube(vec3 on_axis, vec3 direction, float terrain, float t) {
  if (!terrain_near_tube(terrain, t)) return false;
  vec4 normal_texel = texelFetch(u_terrain_normal, ivec2(gl_FragCoord.xy), 0);
  return terrain_inside_tube(on_axis, direction, terrain, terrain_normal_ecef(u_view_rotation, normal_texel));
}

void main() {
  vec3 direction = normalize(v_position);
  CapsuleHit hit = trace_capsule(vec3(0.0), direction, true);
  if (hit.clipped) discard;
  float terrain = read_distance(u_terrain_distance, ivec2(gl_FragCoord.xy), u_packed_distance);
  // Where the ray passes nearest the axis: the fringe's geometry, and where the terrain is asked
  // whether it runs through the tube, once for a hit or a fringe (llvmpipe runs both branches).
  vec3 on_axis = axis_nearest_ray(direction);
  float shift = dot(0.5 * (v_x1 + v_x2), direction);
  vec3 o = direction * shift;  // the ray's point nearest the segment's middle
  float t_local = dot(on_axis - o, direction);
  float t = hit.hit ? hit.t : shift + t_local;
  float visibility = visibility_alpha(t, terrain);
  bool inside = visibility < 1.0 && inside_tube(hit.hit ? hit.on_axis : on_axis, direction, terrain, t);
  if (inside) visibility = 1.0;
  if (hit.hit) {
    float depth = window_depth(hit.position);
    // Drawn by track_visible.frag in front of the terrain: the same depth here, so that no other
    // track's ghost behind the terrain shows over it.
    if (inside) depth = min(depth, window_depth(direction * (terrain - terrain_margin(terrain))));
    gl_FragDepth = depth;
    if (visibility >= 1.0) {
      overlay = vec4(0.0);  // in the G-buffer already: only its depth matters here
      return;
    }
    if (visibility <= 0.0) discard;
    overlay = vec4(lit(track_albedo(hit.position), hit.normal) * visibility, visibility);
    return;
  }
  // The fringe: how far the ray passes outside the tube, in pixels at that distance.
  vec3 on_ray = o + direction * t_local;
  if (t <= 0.0) discard;
  vec3 outward = on_ray - on_axis;
  float miss = length(outward);
  float radius = v_radii.y;
  float pixel_m = pixel_size_at(on_ray);
  float coverage = clamp(0.5 - (miss - radius) / pixel_m, 0.0, 0.5);
  if (coverage <= 0.0 || miss <= 0.0) discard;
  vec3 normal = outward / miss;
  vec3 edge = on_axis + normal * radius;
  if (clipped_by_joints(edge) || in_dash_gap(edge)) discard;
  float alpha = coverage * visibility;
  if (alpha <= 0.0) discard;
  gl_FragDepth = window_depth(edge + direction * radius);
  overlay = vec4(lit(track_albedo(edge), normal) * alpha, alpha);
}
