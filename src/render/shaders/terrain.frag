#version 300 es
// The G-buffer fill (DESIGN.md "The frame", step 3): albedo (imagery, else a hypsometric tint by
// height; the neutral ground where the source has no data), the view-space normal and the
// distance from the camera. Lighting happens later, in the compose pass.
precision highp float;

#include "gbuffer.glsl"
#include "srgb.glsl"

uniform vec3 u_neutral_albedo;  // linear
uniform bool u_has_imagery;
uniform sampler2D u_imagery;  // sRGB texture: sampled as linear
uniform bool u_packed_distance;
// Snow cover (`--snow`): from about u_snowline_m up, on slopes gentle enough to hold it;
// u_view_up is the local vertical at the tile's origin, in view space.
uniform bool u_snow;
uniform float u_snowline_m;
uniform vec3 u_view_up;

in vec3 v_view_normal;
in vec3 v_from_camera;
in float v_height;
in vec2 v_imagery_uv;
in float v_covered;

layout(location = 0) out vec4 g_albedo;  // sRGB8_ALPHA8 target: written linear, stored encoded
layout(location = 1) out vec4 g_normal;
layout(location = 2) out vec4 g_distance;

// Colours of the tint (sRGB, as a map would print them) at increasing heights in metres: green
// lowlands, brown foothills, grey rock, white above about 3000 m.
const int kStops = 6;
const float kStopHeights[kStops] = float[](0.0, 700.0, 1500.0, 2200.0, 2700.0, 3200.0);
const vec3 kStopColors[kStops] = vec3[](vec3(0.47, 0.62, 0.38), vec3(0.58, 0.67, 0.42), vec3(0.68, 0.63, 0.45),
                                        vec3(0.62, 0.54, 0.45), vec3(0.60, 0.59, 0.57), vec3(0.95, 0.95, 0.97));

vec3 hypsometric_tint(float height_m) {
  vec3 color = kStopColors[0];
  for (int i = 1; i < kStops; ++i) {
    float t = clamp((height_m - kStopHeights[i - 1]) / (kStopHeights[i] - kStopHeights[i - 1]), 0.0, 1.0);
    color = mix(color, kStopColors[i], t);
  }
  return srgb_to_linear(color);
}

void main() {
  // Imagery where it is opaque; the tint by height through its transparent parts (an overlay
  // without base imagery, a raster's edge).
  vec3 albedo = hypsometric_tint(v_height);
  if (u_has_imagery) {
    vec4 image = texture(u_imagery, v_imagery_uv);
    albedo = mix(albedo, image.rgb, image.a);
  }
  if (u_snow) {
    // Snow thins out over the last few hundred metres below the line, and slides off slopes
    // steeper than about 45 degrees (rock faces stay dark, as seen in the Alps in spring).
    float by_height = smoothstep(u_snowline_m - 300.0, u_snowline_m + 150.0, v_height);
    float cos_slope = dot(normalize(v_view_normal), u_view_up);
    float by_slope = smoothstep(0.64, 0.80, cos_slope);  // cos 50 deg .. cos 37 deg
    albedo = mix(albedo, srgb_to_linear(vec3(0.93, 0.95, 0.98)), by_height * by_slope);
  }
  if (v_covered < 0.5) albedo = u_neutral_albedo;
  g_albedo = vec4(albedo, 1.0);
  g_normal = encode_normal(normalize(v_view_normal));
  float distance_m = length(v_from_camera);
  g_distance = u_packed_distance ? pack_distance(distance_m) : vec4(distance_m, 0.0, 0.0, 1.0);
}
