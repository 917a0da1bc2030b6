// Cascaded shadow lookup for a lighting pass (compose): whether the sun reaches a point.
// The CPU side is render/shadow_cascades.hpp; ShadowMaps::bind_for_lookup sets these uniforms.
// Positions are camera-relative (what the G-buffer gives back), in metres.
//
// Bias, why three kinds: a depth map texel covers a patch of ground that is tilted against the
// light, so a receiver compared with its own texel's depth self-shadows ("acne"). Moving the
// receiver along its normal (normal offset) and lowering its depth by a constant plus a
// slope-scaled amount, all in proportion to the cascade's texel size, removes the acne without
// detaching shadows from their casters (peter-panning) at mountain scale.

uniform highp sampler2DArrayShadow u_shadow_maps;  // one layer per cascade, compare mode on
uniform mat4 u_shadow_matrices[4];                  // camera-relative light view-projection
uniform vec4 u_shadow_split_far_m;                  // far view depth of each cascade
uniform vec4 u_shadow_depth_extent_m;               // light depth range of each cascade
uniform vec4 u_shadow_constant_bias_m;
uniform vec4 u_shadow_slope_bias_m;
uniform vec4 u_shadow_normal_offset_m;
uniform float u_shadow_texel_uv;  // 1 / map size

// The first cascade whose far split lies beyond `view_depth_m`; 4 beyond the last (no shadow).
int shadow_cascade_for(float view_depth_m) {
  for (int i = 0; i < 4; ++i) {
    if (view_depth_m <= u_shadow_split_far_m[i]) return i;
  }
  return 4;
}

// Visibility of the sun in one cascade, 0 (shadow) .. 1 (lit), 3x3 PCF with the compare sampler.
float shadow_visibility_in(int cascade, vec3 position, vec3 normal, vec3 sun_direction) {
  float cos_theta = clamp(dot(normal, sun_direction), 0.0, 1.0);
  float sin_theta = sqrt(1.0 - cos_theta * cos_theta);
  vec3 offset_position = position + normal * (u_shadow_normal_offset_m[cascade] * sin_theta);
  float tan_theta = min(sin_theta / max(cos_theta, 1e-3), 10.0);
  float bias_m = u_shadow_constant_bias_m[cascade] + u_shadow_slope_bias_m[cascade] * tan_theta;

  vec4 clip = u_shadow_matrices[cascade] * vec4(offset_position, 1.0);  // orthographic: w = 1
  vec2 uv = clip.xy * 0.5 + 0.5;
  float depth = clip.z * 0.5 + 0.5 - bias_m / u_shadow_depth_extent_m[cascade];
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || depth > 1.0) return 1.0;

  float lit = 0.0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      vec2 tap = uv + vec2(float(dx), float(dy)) * u_shadow_texel_uv;
      lit += texture(u_shadow_maps, vec4(tap, float(cascade), depth));
    }
  }
  return lit / 9.0;
}

// Visibility of the sun at a camera-relative `position` whose view depth (metres along the view
// axis) is `view_depth_m`, with unit `normal` and unit `sun_direction` in the same frame. Faces
// turned away from the sun are in their own shadow (0). The last tenth of each cascade blends
// into the next, so the change of resolution leaves no seam.
float shadow_visibility(vec3 position, float view_depth_m, vec3 normal, vec3 sun_direction) {
  if (dot(normal, sun_direction) <= 0.0) return 0.0;
  int cascade = shadow_cascade_for(view_depth_m);
  if (cascade >= 4) return 1.0;
  float visibility = shadow_visibility_in(cascade, position, normal, sun_direction);
  float cascade_near = cascade == 0 ? 0.0 : u_shadow_split_far_m[cascade - 1];
  float blend_start = mix(cascade_near, u_shadow_split_far_m[cascade], 0.9);
  if (view_depth_m > blend_start) {
    float next = cascade == 3 ? 1.0 : shadow_visibility_in(cascade + 1, position, normal, sun_direction);
    float t = (view_depth_m - blend_start) / (u_shadow_split_far_m[cascade] - blend_start);
    visibility = mix(visibility, next, t);
  }
  return visibility;
}
