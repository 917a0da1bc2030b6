#version 300 es
// The curtain's colour: the track's colour at that point, translucent, a little stronger near
// the track so the wall reads as hanging from it; hidden where the terrain is in front.
precision highp float;
precision highp int;

#include "gbuffer.glsl"
#include "srgb.glsl"

uniform float u_depth_step_k;  // depth-buffer resolution at distance d: d * d * k metres
#include "behind_visible_track.glsl"

uniform highp sampler2D u_terrain_distance;
uniform bool u_packed_distance;
uniform bool u_by_value;
uniform vec3 u_color;          // linear
uniform vec3 u_missing_color;  // linear
uniform vec3 u_category_color;  // linear: track::kCategoryValue (-1e30), e.g. gliding
uniform highp sampler2D u_colormap;
uniform vec2 u_value_range;
uniform float u_curtain_alpha;
uniform vec3 u_sky_radiance;
uniform vec3 u_sun_radiance;

in vec3 v_position;
in float v_value;
in float v_height_fraction;

out vec4 overlay;


void main() {
  float terrain = read_distance(u_terrain_distance, ivec2(gl_FragCoord.xy), u_packed_distance);
  if (terrain > 0.0 && length(v_position) > terrain + 0.5) discard;
  if (behind_visible_track(length(v_position), visible_track_distance(terrain, u_packed_distance))) discard;
  vec3 albedo = u_color;
  if (u_by_value) {
    // v_value interpolates across the segment; a missing end drags it far below any real value,
    // a category end (-1e30) below any measurement.
    if (v_value < -1.0e30) {
      albedo = u_missing_color;
    } else if (v_value < -1.0e29) {
      albedo = u_category_color;
    } else {
      float span = u_value_range.y - u_value_range.x;
      float position = span > 0.0 ? clamp((v_value - u_value_range.x) / span, 0.0, 1.0) : 0.5;
      albedo = texture(u_colormap, vec2((position * 255.0 + 0.5) / 256.0, 0.5)).rgb;
    }
  }
  float alpha = u_curtain_alpha * mix(0.6, 1.0, v_height_fraction);
  vec3 color = linear_to_srgb(albedo * (0.35 * u_sun_radiance + u_sky_radiance));
  overlay = vec4(color * alpha, alpha);
}
