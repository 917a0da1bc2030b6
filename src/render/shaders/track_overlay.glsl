// What the track overlay's two fragment shaders share (track_overlay.frag: every fragment of a
// capsule that may be hidden; track_fringe.frag: the fringe of a capsule the terrain cannot hide):
// the terrain's distance and normal, how visible a point of a track is, the lighting of ghosts
// and fringes, and the fringe itself. Needs gbuffer.glsl, srgb.glsl, track_common.glsl and
// track_trace.glsl.

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

// The anti-aliased fringe where the ray along unit `direction` misses the capsule (the caller
// knows it misses): how far it passes outside the tube, in pixels at that distance, as coverage,
// times the visibility of that part of the tube. `edge_out`: the silhouette point the fringe
// shows. False: nothing to draw here.
bool fringe(vec3 direction, float terrain, out vec4 colour, out vec3 edge_out) {
  colour = vec4(0.0);
  edge_out = vec3(0.0);
  vec3 on_axis = axis_nearest_ray(direction);
  float shift = dot(0.5 * (v_x1 + v_x2), direction);
  vec3 o = direction * shift;  // the ray's point nearest the segment's middle
  float t_local = dot(on_axis - o, direction);
  float t = shift + t_local;
  float visibility = visibility_alpha(t, terrain);
  if (visibility < 1.0 && inside_tube(on_axis, direction, terrain, t)) visibility = 1.0;
  vec3 on_ray = o + direction * t_local;
  if (t <= 0.0) return false;
  vec3 outward = on_ray - on_axis;
  float miss = length(outward);
  float radius = v_radii.y;
  float pixel_m = pixel_size_at(on_ray);
  float coverage = clamp(0.5 - (miss - radius) / pixel_m, 0.0, 0.5);
  if (coverage <= 0.0 || miss <= 0.0) return false;
  vec3 normal = outward / miss;
  vec3 edge = on_axis + normal * radius;
  if (clipped_by_joints(edge) || in_dash_gap(edge)) return false;
  float alpha = coverage * visibility;
  if (alpha <= 0.0) return false;
  edge_out = edge;
  colour = vec4(lit(track_albedo(edge), normal) * alpha, alpha);
  return true;
}
